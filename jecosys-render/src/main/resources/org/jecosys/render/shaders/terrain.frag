#version 330 core
// Terrain: the soil or, where the plants grow, the ground cover laid over it (ground_cover.glsl, shared
// with the cover's skin over a host's own ground); lit by the light from the vertex shader, darkened
// under the plants by the contact-occlusion map, the sun's share by the plants' shadows (SunShadow's
// splat, SunShadowMap's map near the eye),
// then hazed toward the horizon colour with distance.
in vec3 vSoil;
in vec3 vLight;
in vec3 vSunLight;
in vec3 vWorld;
in vec3 vUvDry;
uniform vec3 uEye;
uniform float uFogStart;
uniform float uFogEnd;
uniform sampler2D uOcclusion;                    // red: contact occlusion, green: ground cover level, blue: sun shadow
uniform float uShadows;                          // strength of the sun shadows, 0: off
uniform float uContactShadow;
uniform vec3 uFogColour;
#include "ground_cover.glsl"
#include "sun_shadow.glsl"
layout(location = 0) out vec4 fragColour;
// the resolve's detail mask (GlFramebuffer): 1 where thin geometry wants the wide filter, 0 elsewhere;
// written only into the library's own framebuffer (a host's other draw buffers are masked off)
layout(location = 1) out vec4 fragDetail;

void main() {
    vec2 uv = vUvDry.xy;
    // beyond the terrain (the horizon skirt) nothing darkens the ground and the cover goes on at the map's
    // mean level (uCover.w), still in the wind: the clamped rim would smear into streaks that sway
    vec3 maps = texture(uOcclusion, uv).rgb;
    bool inside = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
    float level = inside ? maps.g : uCover.w;
    float occlusion = inside ? maps.r : 0.0;
    // the splatted shadows, or the shadow map where it reaches (with the plants as they sway)
    vec2 map = sunShadowMap(vWorld);
    float shadow = uShadows * mix(inside ? maps.b : 0.0, map.x, map.y);
    vec3 albedo = vSoil;
    if (uCover.x > 0.0) {
        // the cover over the soil; thin cover lets the soil show through its gaps
        vec4 cover = groundCover(vWorld.xz, vUvDry.z, uCover.x * level);
        albedo = mix(vSoil, cover.rgb, cover.a);
    }
    vec3 lit = albedo * (vLight + vSunLight * (1.0 - shadow)) * (1.0 - uContactShadow * occlusion);
    if (uSheen > 0.0 && inside) {
        lit = coverSheen(lit, vWorld, uEye, uCover.x * level);
    }
    // haze (squared ramp), the plants' formula, so plants and ground fade alike
    float fog = clamp((distance(uEye, vWorld) - uFogStart) / max(uFogEnd - uFogStart, 1e-3), 0.0, 1.0);
    fragColour = vec4(mix(lit, uFogColour, fog * fog), 1.0);
    fragDetail = vec4(0.0);
}
