#version 330 core
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
    float diffuse = max(dot(normalize(aNormal), uLightDir), 0.0);
    float sky = 0.5 + 0.5 * aNormal.y;
    vColour = aColour * (0.30 * sky + 0.70 * diffuse);
    vDistance = distance(uEye, aPos);
}
