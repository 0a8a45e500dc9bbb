#version 330 core
// Near ground cover (CoverBlades): one triangle per blade, made from gl_VertexID and the tile instance
// alone. Blade b of a tile stands at a point of a low-discrepancy sequence offset by the tile's hash
// (evenly spread, never in rows), with its height, lean, facing, width and shade from hashes of the
// tile and b, its form (fine blade, broad low leaf or dry thatch lying down) from another, its stand's
// height from value noise on the metre scale; it stands on the heightfield (bilinear in the heights buffer), grows only where the
// cover map has cover, leans further where the plants of its tile are bent by the wind (the bend map),
// and shrinks away beyond the tile's blade count and toward the cover's reach, where the ground's own
// cover colour takes over. Lit by plant_light.glsl's model (darker at the base, light through the
// blade when back-lit), hazed with distance like everything else.
layout(location = 0) in vec4 aTile;              // tile origin X, Z (m), blades to draw (continuous), -

uniform mat4 uViewProj;
uniform samplerBuffer uHeights;                  // R32F heightfield, rows along X
uniform vec4 uField;                             // heightfield minX, minZ, 1 / cellX, 1 / cellZ
uniform int uFieldRes;
uniform sampler2D uMaps;                         // red: contact occlusion, green: cover level, blue: sun shadow
uniform vec2 uShadows;                           // strength of the sun shadows, the sun's share of the light
uniform vec4 uMap;                               // map minX, minZ, 1 / (texelX width), 1 / (texelZ height)
uniform sampler2D uBend;                         // mean bend of the plants per tile, radians, signed bytes
uniform vec4 uBendMap;                           // bend map minX, minZ, 1 / (tile width), 1 / (tile height)
uniform float uTile;                             // tile side, m
uniform vec4 uBlade;                             // height (m), amount, blades per tile, -
uniform float uReach;                            // m
uniform vec3 uCoverColour;
uniform vec3 uCoverDry;
uniform float uContactShadow;
out vec3 vColour;

#include "patches.glsl"
#include "plant_light.glsl"
#include "sun_shadow.glsl"

float groundHeight(vec2 xz) {
    vec2 g = clamp((xz - uField.xy) * uField.zw, vec2(0.0), vec2(float(uFieldRes) - 1.001));
    ivec2 i = ivec2(g);
    vec2 f = g - vec2(i);
    int k = i.y * uFieldRes + i.x;
    float a = texelFetch(uHeights, k).r;
    float b = texelFetch(uHeights, k + 1).r;
    float c = texelFetch(uHeights, k + uFieldRes).r;
    float d = texelFetch(uHeights, k + uFieldRes + 1).r;
    return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}

const float BROAD_SHARE = 0.16;                  // of the blades, broad low leaves
const float THATCH_SHARE = 0.14;                 // of the blades, dry thatch lying on the ground

void main() {
    int blade = gl_VertexID / 3;
    int corner = gl_VertexID - 3 * blade;
    // fewer blades in far tiles: those past the count are gone, the last quarter shrinks away
    float keep = clamp((aTile.z - float(blade)) / max(0.25 * aTile.z, 1.0), 0.0, 1.0);
    if (keep <= 0.0) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // the whole triangle outside the view: clipped
        vColour = vec3(0.0);
        return;
    }
    ivec2 tile = ivec2(floor(aTile.xy / uTile + 0.5));
    int s = blade * 8;
    vec2 offset = vec2(hash(tile.x, tile.y, 7), hash(tile.x, tile.y, 11));
    vec2 u = fract(offset + float(blade) * vec2(0.7548776662, 0.5698402910));
    vec2 xz = aTile.xy + u * uTile;
    vec3 maps = textureLod(uMaps, (xz - uMap.xy) * uMap.zw, 0.0).rgb;
    float cover = uBlade.y * maps.g;
    vec3 base = vec3(xz.x, groundHeight(xz), xz.y);
    float d = distance(base, uEye);
    // a sward, not a carpet: stands taller and shorter on the metre scale (mean about 1), and three forms,
    // by the blade's hash: most are fine blades; some broad low leaves (as plantain or clover); some dry
    // thatch lying on the ground
    float stand = 0.3 + 1.4 * valueNoise(xz * 0.7, uPatchSeed + 4099);
    float form = hash(tile.x, tile.y, s + 2 + 8 * 4099);
    bool broad = form < BROAD_SHARE;
    bool thatch = !broad && form < BROAD_SHARE + THATCH_SHARE;
    float h = uBlade.x * (0.55 + 0.9 * hash(tile.x, tile.y, s + 1)) * smoothstep(0.05, 0.5, cover) * keep
            * (1.0 - smoothstep(0.7 * uReach, uReach, d)) * stand * (broad ? 0.45 : (thatch ? 1.6 : 1.0));
    if (h <= 1e-4) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        vColour = vec3(0.0);
        return;
    }
    // lean: its own, plus the wind's as the plants of the tile show it
    float restAz = 6.2831853 * hash(tile.x, tile.y, s + 2);
    vec2 lean = (0.15 + 0.5 * hash(tile.x, tile.y, s + 3)) * vec2(cos(restAz), sin(restAz));
    vec2 bend = (textureLod(uBend, (xz - uBendMap.xy) * uBendMap.zw, 0.0).rg * 255.0 - 128.0) * (1.6 / 127.0);
    lean += bend * (0.8 + 0.4 * hash(tile.x, tile.y, s + 4));
    float angle = thatch ? 1.1 + 0.3 * hash(tile.x, tile.y, s + 3) : min(length(lean) * (broad ? 2.2 : 1.0), 1.4);
    vec2 dir = angle > 1e-4 ? lean / length(lean) : vec2(1.0, 0.0);
    vec3 tip = base + h * vec3(sin(angle) * dir.x, cos(angle), sin(angle) * dir.y);
    float face = 6.2831853 * hash(tile.x, tile.y, s + 5);
    vec3 side = vec3(cos(face), 0.0, sin(face));
    // wider far away, where fewer blades are drawn (the count falls as 1 / d^2 beyond a third of the reach)
    float width = (0.004 + 0.006 * hash(tile.x, tile.y, s + 6)) * max(1.0, 3.0 * d / uReach) * (broad ? 4.0 : (thatch ? 1.5 : 1.0));
    vec3 p = corner == 2 ? tip : base + side * (corner == 0 ? -0.5 : 0.5) * width;
    gl_Position = uViewProj * vec4(p, 1.0);
    float dry = clamp(uPatch.y * patchLevel(xz) * 1.3 + (hash(tile.x, tile.y, s + 7) - 0.6) * 0.5, 0.0, 1.0);
    dry = thatch ? 1.0 : dry;
    vec3 albedo = mix(uCoverColour, uCoverDry, dry) * (0.8 + 0.4 * hash(tile.x, tile.y, s + 1 + 8 * 4099));
    albedo *= broad ? vec3(0.6, 0.92, 1.15) : (thatch ? vec3(1.3, 1.2, 1.0) : vec3(1.0));  // broad leaves a deeper,
                                                                             // bluer green, thatch pale straw
    albedo *= 1.0 - uContactShadow * maps.r * (corner == 2 ? 0.3 : 1.0);
    vec3 toEye = uEye - p;
    float along = corner == 2 ? 1.0 : 0.0;
    float bent = length(bend);
    vColour = lit(albedo, 0, along, 0.3 * along, cross(side, tip - base), toEye, length(toEye), false,
            bent * (1.0 / 1.2), bent > 1e-4 ? bend / bent : vec2(0.0));
    // the splatted shadows, or the shadow map where it reaches
    vec2 map = sunShadowMap(p);
    vColour *= 1.0 - uShadows.x * mix(maps.b, map.x, map.y) * uShadows.y;
}
