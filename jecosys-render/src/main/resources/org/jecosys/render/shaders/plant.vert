#version 330 core
// Plants (paper sections 4.1, 4.2.2): one instanced draw per species and level of detail. Each vertex
// names a slot (component instance of the plant), a pose-table point and side/normal coefficients.
// Per drawn component, the resolve pass (plant_resolve.vert) has written a record: the world position
// of the component's base (the plant's base plus its ground offset, or the animated tip of its
// parent), its bend azimuth as cosine and sine, the pose-table texel of pose k, the blend weight
// toward k + 1, this level's dither window, and its colour variation (hue turn, brightness, patch
// dryness). plant_common.glsl places and shades the vertex; 3 + 6 texel fetches (3 + 8 for a vertex of a
// glTF mesh, placed between two points of the skeleton).
// With TEXTURED the vertex also gives plant.frag its place on the component's image.
// Line levels use plant_line.vert instead. Compiled with SHADOW_CASTER it only places the vertex, for
// the sun's shadow map (uViewProj is then the sun's; plant_caster.frag); with SHADOW_MAP it also passes
// on the world position and the sun's share of the colour, and plant.frag reads the map per fragment.

#include "plant_common.glsl"

#ifndef SHADOW_CASTER
uniform float uCoreCut;                          // > 0: the core's pass (plant.frag); parts without a core left out;
                                                 // < 0: the fringe's pass; parts without a fringe left out
#endif

#ifndef SHADOW_CASTER
out vec4 vShade;                                 // rgb: lit and fogged per vertex; a: the share of the
                                                 // drawn width the part covers (one varying: a software
                                                 // rasteriser sets up each varying of each primitive)
#endif
#ifndef SHADOW_CASTER
noperspective out vec2 vEdge;                    // side (-1 to 1) and drawn half width, pixels (uFeather)
#endif
#ifdef SHADOW_MAP
out vec3 vSun;                                   // what the sun's direct light adds to vShade.rgb
out vec3 vWorld;                                 // the vertex, world: plant.frag reads the shadow map there
#endif
#ifdef DITHER
flat out vec2 vKeep;                             // keep fragments with lo <= bayer < hi
#endif
#ifdef TEXTURED
out vec4 vTex;                                   // u, v on the component's image, its layer (-1: none), and
                                                 // the haze's share of vShade (plant.frag keeps it untextured)
#endif

void main() {
    int slot = int(aVertex.x);
    int point = int(aVertex.y);
    int ci = (uComponentBase + gl_InstanceID * uSlotCount + slot) * 3;
    vec4 c0 = texelFetch(uComponents, ci);       // base xyz, cos(azimuth)
    vec4 c1 = texelFetch(uComponents, ci + 1);   // texel of pose k, w, sin(azimuth), dither window
    vec4 c2 = texelFetch(uComponents, ci + 2);   // cos and sin of the hue turn, brightness, patch dryness
    float w = c1.y;
#ifndef SHADOW_CASTER
    if (uCoreCut > 0.0 && aShape.x < 1.5 && aMesh.w < 0.5 && uMinPixels > 0.0) {
        // the core's pass (CoverageDraws): a blade or stem whose widest half width (aMesh.x), widened as
        // the thinning widens it, is under the least half width wherever it reaches (aShape.y from its
        // base) has no core: every vertex of it goes outside the view, before any pose or light work
        float d = length(uEye - c0.xyz);
        float reach = 1.5 * aShape.y;
        float least = 0.5 * uMinPixels * (uPixelScale.x + max(d - reach, 0.0) * uPixelScale.y);
        if (aMesh.x * thinWiden(d + reach) < uCoreCut * least) {
            gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
            return;
        }
    }
    // the fringe's pass: a flower part and a glTF mesh cover all of their drawn area (no widening, alpha 1
    // everywhere, no image to cut it), so their fragments all lie in the core the pass before wrote
    // and would fail the strict depth test: left out before any pose or light work
    bool whole = aMesh.w > 0.5;
#ifdef FLOWERS
    whole = whole || aShape.x > 1.5;
#endif
#ifdef TEXTURED
    whole = whole && aShape.z < -0.5;
#endif
    if (uCoreCut < 0.0 && whole) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
#endif
    int stride = int(aStride + 0.5);
    Placed v;
    if (aMesh.w > 0.5) {
        // a glTF mesh's vertex: between points i0 and i0 + 1 at its fractional point (8 texel fetches)
        int i0 = min(point, stride / 3 - 2);
        int t = int(c1.x + 0.5) + i0 * 3;
        int u = t + stride;
        vec3 p0 = mix(texelFetch(uPoses, t).xyz, texelFetch(uPoses, u).xyz, w);
        vec3 s0 = mix(texelFetch(uPoses, t + 1).xyz, texelFetch(uPoses, u + 1).xyz, w);
        vec3 p1 = mix(texelFetch(uPoses, t + 3).xyz, texelFetch(uPoses, u + 3).xyz, w);
        vec3 s1 = mix(texelFetch(uPoses, t + 4).xyz, texelFetch(uPoses, u + 4).xyz, w);
        v = placeMesh(c0.xyz, c0.w, c1.z, p0, s0, p1, s1, aVertex.y - float(i0));
    } else {
        int t = int(c1.x + 0.5) + point * 3;
        int u = t + stride;
        vec3 p = mix(texelFetch(uPoses, t).xyz, texelFetch(uPoses, u).xyz, w);
        vec3 side = mix(texelFetch(uPoses, t + 1).xyz, texelFetch(uPoses, u + 1).xyz, w);
        vec3 normal = mix(texelFetch(uPoses, t + 2).xyz, texelFetch(uPoses, u + 2).xyz, w);
        v = place(c0.xyz, c0.w, c1.z, p, side, normal, true);
    }
    gl_Position = uViewProj * vec4(v.world, 1.0);
#ifndef SHADOW_CASTER
    // record texel 1's w: the dither window (whole part) and how far the component is bent (fraction)
    vShade = vec4(shade(v, c2, false, fract(c1.w) * (1.0 / 0.99), vec2(c0.w, c1.z)), v.cover);
    vEdge = v.edge;
#endif
#ifdef SHADOW_MAP
    // lit again without the sun: plant.frag moves toward that where the shadow map says it is shaded
    gSunLit = 0.0;
    vSun = vShade.rgb - shade(v, c2, false, fract(c1.w) * (1.0 / 0.99), vec2(c0.w, c1.z));
    vWorld = v.world;
#endif
#ifdef TEXTURED
#ifdef SHADOW_CASTER
    vTex = vec4(textureCoord(), aShape.z, 0.0);
#else
    float haze = clamp((v.distance - uFogStart) / max(uFogEnd - uFogStart, 1e-3), 0.0, 1.0);
    vTex = vec4(textureCoord(), aShape.z, haze * haze);
#endif
#endif
#ifdef DITHER
    int keep = int(c1.w);
    vKeep = vec2(float(keep >> 8), float(keep & 255)) / 255.0;
#endif
}
