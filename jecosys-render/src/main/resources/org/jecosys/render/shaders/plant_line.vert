#version 330 core
// Plants drawn as lines (the far level, paper Table 3): the cheaper variant of plant.vert. The line
// vertices are placed as in plant.vert (plant_common.glsl, without widening: a line is a
// pixel wide already, but the two edge lines of a ribbon move apart to span the same least width as
// the triangle levels). Far away a component is a few pixels: the resolve pass has lit it once, at its
// middle, with the same light as plant.vert (plant_light.glsl), into record texel 2; here only the
// shade toward the base is applied, one flat colour per segment from its provoking vertex. The dither
// window is the same as for plant.vert.
//
// Coverage: a line is one pixel wide whatever the leaf's width, so far away, where a leaf is a
// fraction of a pixel wide, lines would cover several times the area the leaf does. A ribbon is
// drawn as its two edges (a = +-half width); each edge line takes as alpha the half width over the
// pixel's footprint at that distance, so once the two edges fall in the same pixels they add up to
// the leaf's share of the pixel, and when they are a pixel or more apart each is about opaque.
// Vertices on a centre line (a = 0) are opaque.
//
// Species with flower parts are drawn by the variant compiled with FLOWERS, which places every vertex
// as plant.vert does. Without it (blades and stems only, most of a meadow) the vertex work is cut to
// what a far component needs: its distance, pixel size and view direction are taken at its base (a
// component is short against 15 m and more), worked out once per component by the resolve pass
// (plant_far.glsl), and a ribbon's edge is moved to the least width along the part of its
// half-width vector that crosses the view.

#include "plant_common.glsl"

flat out vec3 vColour;                           // fogged, one colour per line segment
#ifdef DITHER
flat out vec2 vKeep;                             // keep fragments with lo <= bayer < hi
#endif
out float vCover;                                // alpha: the share of a pixel the ribbon covers

void main() {
    int slot = int(aVertex.x);
    int point = int(aVertex.y);
    int kind = int(aShape.x + 0.5);
    int ci = (uComponentBase + gl_InstanceID * uSlotCount + slot) * 3;
    vec4 c0 = texelFetch(uComponents, ci);       // base xyz, cos(azimuth)
    vec4 c1 = texelFetch(uComponents, ci + 1);   // texel of pose k, w, sin(azimuth), dither window
    vec4 c2 = texelFetch(uComponents, ci + 2);   // lit colour, widening, 1 / distance, pixel (plant_far.glsl)
    int t = int(c1.x + 0.5) + point * 3;
    int u = t + int(aStride + 0.5);
    float w = c1.y;
    vec3 p = mix(texelFetch(uPoses, t).xyz, texelFetch(uPoses, u).xyz, w);
#ifdef FLOWERS
    vec3 side = vec3(0.0);
    vec3 normal = vec3(0.0);
    if (aVertex.z != 0.0) {
        side = mix(texelFetch(uPoses, t + 1).xyz, texelFetch(uPoses, u + 1).xyz, w);
        if (kind < 2) {
            side *= farWiden(c2);
        }
    }
    if (aVertex.w != 0.0 || kind == 3) {
        normal = mix(texelFetch(uPoses, t + 2).xyz, texelFetch(uPoses, u + 2).xyz, w);
    }
    vec3 world;
    float distance;
    if (kind >= 2) {
        // flower parts: turned toward the viewer and kept a few pixels wide, as in plant.vert
        Placed v = place(c0.xyz, c0.w, c1.z, p, side, normal, false);
        world = v.world;
        distance = v.distance;
    } else {
        vec3 centre = c0.xyz + rotY(p, c0.w, c1.z);
        vec3 offset = rotY(aVertex.z * side + aVertex.w * normal, c0.w, c1.z);
        world = centre + offset;
        distance = length(uEye - world);
        if (aVertex.z != 0.0 && uMinPixels > 0.0 && point < int(aStride + 0.5) / 3 - 1) {
            // like the triangle levels' widening: the two edge lines (a pixel wide each) move apart
            // until together they span uMinPixels across the view (not at the tip, as below)
            vec3 v = (uEye - centre) / max(length(uEye - centre), 1e-6);
            vec3 across = offset - dot(offset, v) * v;
            float seen = length(across);
            float pixel = uPixelScale.x + distance * uPixelScale.y;
            float least = 0.5 * (uMinPixels - 1.0) * pixel;
            if (seen > 1e-9 && least > seen) {
                world += (least - seen) * across / seen;
            }
        }
    }
    float halfWidth = abs(aVertex.z) * length(side);
    float pixel = max(uPixelScale.x + distance * uPixelScale.y, 1e-6);
    vCover = aVertex.z == 0.0 ? 1.0 : clamp(halfWidth / pixel, 1.0 / 32.0, 1.0);
#else
    // the component's distance and the pixel's size at its base, from the resolve pass
    vec3 toEye = uEye - c0.xyz;
    float pixel = c2.w;
    vec3 world = c0.xyz + rotY(p, c0.w, c1.z);
    vCover = 1.0;
    if (aVertex.z != 0.0) {
        vec3 side = mix(texelFetch(uPoses, t + 1).xyz, texelFetch(uPoses, u + 1).xyz, w) * farWiden(c2);
        vec3 offset = aVertex.z * rotY(side, c0.w, c1.z);
        // the edge lines (a pixel wide each) move apart until together they span uMinPixels across
        // the view: the part of the offset that crosses the view is lengthened to the least width;
        // not at the tip, which stays as narrow as it is (a pointed blade's tip is one vertex on
        // its centre line anyway): widened, a blunt tip's edge became a line of most of a pixel
        // across a tip a fraction of a pixel wide, nearly transparent and costly to draw
        vec3 v = toEye * c2.z;
        vec3 across = offset - dot(offset, v) * v;
        float seen2 = dot(across, across);
        float least = 0.5 * (uMinPixels - 1.0) * pixel;
        bool tip = point == int(aStride + 0.5) / 3 - 1;
        world += !tip && least > 0.0 && seen2 < least * least && seen2 > 1e-18
                ? across * (least * inversesqrt(seen2)) : offset;
        vCover = clamp(abs(aVertex.z) * length(side) / pixel, 1.0 / 32.0, 1.0);
    }
#endif
    gl_Position = uViewProj * vec4(world, 1.0);
    // the resolve pass lit the component at its middle (record texel 2); the base is darker
    vColour = farColour(c2) * (baseShade(kind, aColour.w, 1.0) / baseShade(kind, 0.5, 1.0));
#ifdef DITHER
    int keep = int(c1.w);
    vKeep = vec2(float(keep >> 8), float(keep & 255)) / 255.0;
#endif
}
