#version 330 core
// Terrain: the lit colour from the vertex shader, darkened under the plants by the contact-occlusion
// map, then hazed toward the horizon colour with distance.
in vec3 vLit;
in vec3 vWorld;
uniform vec3 uEye;
uniform float uFogStart;
uniform float uFogEnd;
in vec2 vUv;
uniform sampler2D uOcclusion;
uniform float uContactShadow;
uniform vec3 uFogColour;
layout(location = 0) out vec4 fragColour;
// the resolve's detail mask (GlFramebuffer): 1 where thin geometry wants the wide filter, 0 elsewhere;
// written only into the library's own framebuffer (a host's other draw buffers are masked off)
layout(location = 1) out vec4 fragDetail;

void main() {
    // beyond the map (the horizon skirt) nothing darkens the ground
    float occlusion = all(greaterThanEqual(vUv, vec2(0.0))) && all(lessThanEqual(vUv, vec2(1.0)))
            ? texture(uOcclusion, vUv).r : 0.0;
    // haze (squared ramp), the plants' formula, so plants and ground fade alike
    float fog = clamp((distance(uEye, vWorld) - uFogStart) / max(uFogEnd - uFogStart, 1e-3), 0.0, 1.0);
    fragColour = vec4(mix(vLit * (1.0 - uContactShadow * occlusion), uFogColour, fog * fog), 1.0);
    fragDetail = vec4(0.0);
}
