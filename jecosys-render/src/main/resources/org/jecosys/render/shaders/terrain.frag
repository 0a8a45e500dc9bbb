#version 330 core
// Terrain: the lit colour from the vertex shader, darkened under the plants by the contact-occlusion
// map, then hazed toward the horizon colour.
in vec3 vLit;
in float vFog;
in vec2 vUv;
uniform sampler2D uOcclusion;
uniform float uContactShadow;
uniform vec3 uFogColour;
out vec4 fragColour;

void main() {
    float occlusion = texture(uOcclusion, vUv).r;
    fragColour = vec4(mix(vLit * (1.0 - uContactShadow * occlusion), uFogColour, vFog), 1.0);
}
