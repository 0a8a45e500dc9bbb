#version 330 core
// Terrain: gentle lighting (a sky-tinted ambient term and a soft sun term), so the ground stays a
// darker backdrop for the plants.
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColour;
uniform mat4 uViewProj;
uniform vec3 uEye;
uniform vec3 uLightDir;
out vec3 vColour;
out float vDistance;

void main() {
    gl_Position = uViewProj * vec4(aPos, 1.0);
    vec3 n = normalize(aNormal);
    float diffuse = max(dot(n, uLightDir), 0.0);
    float sky = 0.5 + 0.5 * n.y;
    vColour = aColour * (0.45 * sky + 0.55 * diffuse) * vec3(0.97, 1.0, 1.04) + aColour * 0.25 * diffuse;
    vDistance = distance(uEye, aPos);
}
