#version 330 core
// Screen-door dither across a level-of-detail band: level L keeps pixels with bayer >= fade, level
// L + 1 keeps bayer < fade, so the two levels of one plant cover complementary pixels.
in vec3 vColour;
in float vDistance;
flat in vec2 vKeep;
uniform vec3 uFogColour;
uniform float uFogStart;
uniform float uFogEnd;
out vec4 fragColour;

float bayer4(vec2 p) {
    ivec2 q = ivec2(mod(p, 4.0));
    int i = q.x + q.y * 4;
    int m[16] = int[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
    return (float(m[i]) + 0.5) / 16.0;
}

void main() {
    float b = bayer4(gl_FragCoord.xy);
    if (b < vKeep.x || b >= vKeep.y) {
        discard;
    }
    float fog = clamp((vDistance - uFogStart) / max(uFogEnd - uFogStart, 1e-3), 0.0, 1.0);
    fragColour = vec4(mix(vColour, uFogColour, fog * fog), 1.0);
}
