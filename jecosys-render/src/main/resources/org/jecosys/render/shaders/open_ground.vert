#version 330 core
// An open world's ground: one tile's heightfield (world positions and normals), lit once per vertex by
// the sun and the sky, hazed toward the horizon colour with distance as the plants are.
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
uniform mat4 uViewProj;
uniform vec3 uEye;
uniform vec3 uSunDir;
uniform vec3 uSunColour;
uniform vec3 uAmbient;
uniform vec3 uColour;
uniform vec3 uHaze;
uniform vec2 uFog;
out vec3 vColour;

void main() {
    float sun = max(dot(normalize(aNormal), uSunDir), 0.0);
    vec3 lit = uColour * (uAmbient + uSunColour * sun);
    float d = distance(aPos, uEye);
    float haze = uFog.y > uFog.x ? clamp((d - uFog.x) / (uFog.y - uFog.x), 0.0, 1.0) : 0.0;
    vColour = mix(lit, uHaze, haze);
    gl_Position = uViewProj * vec4(aPos, 1.0);
}
