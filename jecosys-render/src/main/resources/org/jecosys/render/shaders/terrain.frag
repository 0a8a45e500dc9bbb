#version 330 core
// Terrain: the soil or, where the plants grow, the ground cover (RenderDef.GroundCover) in its colour
// with a grain of blade tips at two scales (a mipmapped tile, so it fades to its mean with distance
// instead of shimmering), drier in the dry patches; lit by the light from the vertex shader, darkened
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
uniform sampler2D uGrain;                        // the cover's grain tile, repeating
uniform float uContactShadow;
uniform vec3 uFogColour;
uniform vec4 uCover;                             // amount (0: bare soil), 1 / grain tile (1/m), -, -
uniform vec3 uCoverColour;
uniform vec3 uCoverDry;
uniform sampler2D uBend;                         // the plants' mean bend per tile (CoverBlades), signed bytes
uniform vec4 uBendMap;                           // bend map minX, minZ, 1 / (tile width), 1 / (tile height)
uniform float uSheen;                            // the wind's sheen on the cover (plant_light.glsl), 0: off
uniform vec3 uSheenLight;                        // the sky's light a bent blade's pale side catches
uniform vec2 uSunXZ;                             // horizontal direction toward the sun, unit
#include "sun_shadow.glsl"
layout(location = 0) out vec4 fragColour;
// the resolve's detail mask (GlFramebuffer): 1 where thin geometry wants the wide filter, 0 elsewhere;
// written only into the library's own framebuffer (a host's other draw buffers are masked off)
layout(location = 1) out vec4 fragDetail;

void main() {
    vec2 uv = vUvDry.xy;
    // the map is clamped at its edges: beyond the terrain (the horizon skirt) the cover goes on as at
    // the rim, but nothing darkens the ground
    vec3 maps = texture(uOcclusion, uv).rgb;
    bool inside = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
    float occlusion = inside ? maps.r : 0.0;
    // the splatted shadows, or the shadow map where it reaches (with the plants as they sway)
    vec2 map = sunShadowMap(vWorld);
    float shadow = uShadows * mix(inside ? maps.b : 0.0, map.x, map.y);
    vec3 albedo = vSoil;
    if (uCover.x > 0.0) {
        vec2 p = vWorld.xz * uCover.y;
        float fine = texture(uGrain, p).r;
        float coarse = texture(uGrain, mat2(0.8, -0.6, 0.6, 0.8) * p * 0.29 + vec2(0.37, 0.71)).r;
        float grain = 0.6 * fine + 0.4 * coarse;
        // dry patches and a few dry flecks turn the cover toward straw
        float dry = clamp(vUvDry.z * 1.3 + (coarse - 0.5) * 0.35, 0.0, 1.0);
        // blade tips bright, the gaps between them dark (the canopy's own shade)
        vec3 cover = mix(uCoverColour, uCoverDry, dry) * (0.72 + 0.55 * grain);
        // thin cover lets the soil show through its gaps
        float level = uCover.x * maps.g;
        float hides = smoothstep(0.1, 0.75, level + 0.45 * (grain - 0.5));
        albedo = mix(vSoil, cover, hides);
    }
    vec3 lit = albedo * (vLight + vSunLight * (1.0 - shadow)) * (1.0 - uContactShadow * occlusion);
    if (uSheen > 0.0) {
        // the wind's sheen on the cover, as on the plants' blades (plant_light.glsl windSheen), from the
        // plants' bend where the fragment is: gusts roll over the sward as bands of light
        vec2 bend = (texture(uBend, (vWorld.xz - uBendMap.xy) * uBendMap.zw).rg * 255.0 - 128.0) * (1.6 / 127.0);
        float bent = length(bend);
        vec2 dir = bent > 1e-4 ? bend / bent : vec2(0.0);
        vec2 e = normalize(uEye.xz - vWorld.xz + vec2(1e-6));
        float toward = 0.6 + 0.25 * dot(dir, e) + 0.15 * dot(dir, uSunXZ);
        vec3 view = uEye - vWorld;
        float g = 1.0 - abs(view.y) / max(length(view), 1e-6);
        toward *= 0.8 + 0.8 * g * g * g;
        float k = uSheen * clamp(6.0 * bent * (1.0 / 1.2), 0.0, 1.0) * toward * clamp(uCover.x * maps.g * 1.5, 0.0, 1.0);
        lit = mix(lit, lit * 1.25 + uSheenLight, clamp(k, 0.0, 1.0));
    }
    // haze (squared ramp), the plants' formula, so plants and ground fade alike
    float fog = clamp((distance(uEye, vWorld) - uFogStart) / max(uFogEnd - uFogStart, 1e-3), 0.0, 1.0);
    fragColour = vec4(mix(lit, uFogColour, fog * fog), 1.0);
    fragDetail = vec4(0.0);
}
