#version 330 core
// The ground cover's skin (CoverSkin): the cover as the terrain shader lays it (ground_cover.glsl, the
// same colour, grain, sheen, contact darkening, shadows and haze), drawn over a host's own ground with
// premultiplied alpha (blend ONE, ONE_MINUS_SRC_ALPHA): opaque where the cover hides the ground, open in
// its gaps and where it thins out at the cover's extent, and faded out toward the terrain's border so no
// hard edge shows. Where the host's ground shows through, it is darkened under the plants and in their
// sun shadows as the library's own ground would be.
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
uniform vec4 uBounds;                            // the terrain's minX, minZ, maxX, maxZ, metres
uniform float uEdge;                             // width of the fade inside the terrain's border, metres
#include "ground_cover.glsl"
#include "sun_shadow.glsl"
layout(location = 0) out vec4 fragColour;
// the resolve's detail mask (GlFramebuffer): ground, so 0; with alpha 0 the blend keeps what is there
layout(location = 1) out vec4 fragDetail;

void main() {
    vec3 maps = texture(uOcclusion, vUvDry.xy).rgb;
    vec2 map = sunShadowMap(vWorld);
    float shadow = uShadows * mix(maps.b, map.x, map.y);
    float level = uCover.x * maps.g;
    vec4 cover = groundCover(vWorld.xz, vUvDry.z, level);
    float contact = 1.0 - uContactShadow * maps.r;
    vec3 lit = cover.rgb * (vLight + vSunLight * (1.0 - shadow)) * contact;
    if (uSheen > 0.0) {
        lit = coverSheen(lit, vWorld, uEye, level);
    }
    float fog = clamp((distance(uEye, vWorld) - uFogStart) / max(uFogEnd - uFogStart, 1e-3), 0.0, 1.0);
    lit = mix(lit, uFogColour, fog * fog);
    vec2 inside = min(vWorld.xz - uBounds.xy, uBounds.zw - vWorld.xz);
    float edge = smoothstep(0.0, uEdge, min(inside.x, inside.y));
    float a = cover.a * edge;
    // the host's ground left showing: what the contact darkening and the plants' shadows take from it
    // (the sun's share of the light, times the shadow), faded with the haze and at the border
    const vec3 luma = vec3(0.2126, 0.7152, 0.0722);
    float sun = dot(vSunLight, luma) / max(dot(vLight + vSunLight, luma), 1e-6);
    float keep = 1.0 - (1.0 - contact * (1.0 - shadow * sun)) * (1.0 - fog * fog) * edge;
    fragColour = vec4(lit * a, 1.0 - (1.0 - a) * keep);
    fragDetail = vec4(0.0);
}
