#version 330 core
in vec3 vColour;
in float vDistance;
uniform vec3 uFogColour;
uniform float uFogStart;
uniform float uFogEnd;
out vec4 fragColour;

void main() {
    float fog = clamp((vDistance - uFogStart) / max(uFogEnd - uFogStart, 1e-3), 0.0, 1.0);
    fragColour = vec4(mix(vColour, uFogColour, fog * fog), 1.0);
}
