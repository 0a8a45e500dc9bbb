#version 330 core
// Terrain: gentle lighting (a sky-tinted ambient term and a soft sun term), so the ground stays a
// darker backdrop for the plants. Lighting and fog per vertex.
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColour;
uniform mat4 uViewProj;
uniform vec3 uEye;
uniform vec3 uLightDir;
uniform vec3 uFogColour;
uniform float uFogStart;
uniform float uFogEnd;
out vec3 vColour;                                // lit and fogged: the fragment shader only writes it

void main() {
    gl_Position = uViewProj * vec4(aPos, 1.0);
    vec3 n = normalize(aNormal);
    float diffuse = max(dot(n, uLightDir), 0.0);
    float sky = 0.5 + 0.5 * n.y;
    vec3 lit = aColour * (0.45 * sky + 0.55 * diffuse) * vec3(0.97, 1.0, 1.04) + aColour * 0.25 * diffuse;
    // fog per vertex (squared ramp): mesh cells are small against the fog distances, and llvmpipe
    // shades far more fragments than vertices
    float fog = clamp((distance(uEye, aPos) - uFogStart) / max(uFogEnd - uFogStart, 1e-3), 0.0, 1.0);
    vColour = mix(lit, uFogColour, fog * fog);
}
