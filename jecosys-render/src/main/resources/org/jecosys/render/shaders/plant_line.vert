#version 330 core
// Plants drawn as lines (the far level, paper Table 3): the cheaper variant of plant.vert. The line
// vertices are placed exactly as in plant.vert (same pose blend of position, side and normal: 2 + 6
// texel fetches, the ribbon edges and rims need the side and normal offsets) and lit the same way
// (two-sided, base darkening, sunlit tips, fog), one flat colour per segment from its first vertex,
// so that the far level has the colour of the triangle level it replaces. The component record
// (ComponentStream) and the dither window are the same as for plant.vert.
//
// Coverage: a line is one pixel wide whatever the leaf's width, so far away, where a leaf is a
// fraction of a pixel wide, lines would cover several times the area the leaf does (and the area the
// triangle level just nearer covers, one pixel centre in so many): the far level would look denser
// and brighter than the near one. A ribbon is drawn as its two edges (a = +-half width); each edge
// line takes as alpha the half width over the pixel's footprint at that distance, so once the two
// edges fall in the same pixels they add up to the leaf's share of the pixel, and when they are a
// pixel or more apart each is about opaque. Vertices on a centre line (a = 0) are opaque.

layout(location = 0) in vec4 aVertex;           // slot, point, a, b
layout(location = 1) in vec4 aColour;           // component colour (linear 0..1), fraction along it
layout(location = 2) in float aStride;          // texels between poses k and k + 1 of the slot (3 x points)

uniform mat4 uViewProj;
uniform vec3 uEye;
uniform samplerBuffer uPoses;                    // RGBA32F: 3 texels per point (position, side, normal)
uniform samplerBuffer uComponents;               // RGBA32F: 2 texels per drawn component
uniform int uSlotCount;
uniform int uComponentBase;
uniform vec3 uFogColour;
uniform float uFogStart;
uniform float uFogEnd;
uniform vec3 uLightDir;                          // unit, toward the light
uniform vec2 uPixelScale;                        // a pixel's height, metres: x + distance * y (Camera's
                                                 // viewHeightAtEye and viewHeightPerMetre over the viewport height)

flat out vec3 vColour;                           // fogged, one colour per line segment
flat out vec2 vKeep;                             // keep fragments with lo <= bayer < hi
out float vCover;                                // alpha: the share of a pixel the ribbon covers

void main() {
    int slot = int(aVertex.x);
    int point = int(aVertex.y);
    int ci = (uComponentBase + gl_InstanceID * uSlotCount + slot) * 2;
    vec4 c0 = texelFetch(uComponents, ci);       // base xyz, cos(azimuth)
    vec4 c1 = texelFetch(uComponents, ci + 1);   // texel of pose k, w, sin(azimuth), dither window
    int t = int(c1.x + 0.5) + point * 3;
    int u = t + int(aStride + 0.5);
    float w = c1.y;
    vec3 p = mix(texelFetch(uPoses, t).xyz, texelFetch(uPoses, u).xyz, w);
    vec3 side = mix(texelFetch(uPoses, t + 1).xyz, texelFetch(uPoses, u + 1).xyz, w);
    vec3 normal = mix(texelFetch(uPoses, t + 2).xyz, texelFetch(uPoses, u + 2).xyz, w);
    p += aVertex.z * side + aVertex.w * normal;
    float ca = c0.w;
    float sa = c1.z;
    vec3 world = c0.xyz + vec3(p.x * ca - p.z * sa, p.y, p.x * sa + p.z * ca);
    gl_Position = uViewProj * vec4(world, 1.0);

    float along = aColour.w;
    vec3 colour = aColour.rgb * (0.50 + 0.55 * along);
    colour = mix(colour, colour * vec3(1.10, 1.18, 0.80) + vec3(0.05, 0.06, 0.0), along * along);
    vec3 toEye = uEye - world;
    float distance = length(toEye);
    vec3 n = vec3(normal.x * ca - normal.z * sa, normal.y, normal.x * sa + normal.z * ca);
    float len = length(n);
    float lit = 0.65;                            // plant.vert's value for a normal that says nothing
    if (len > 1e-9) {
        n /= len;
        n = dot(n, toEye) < 0.0 ? -n : n;
        float nl = dot(n, uLightDir);
        lit = max(nl, 0.0) + 0.35 * max(-nl, 0.0);
    }
    float fog = clamp((distance - uFogStart) / max(uFogEnd - uFogStart, 1e-3), 0.0, 1.0);
    float halfWidth = abs(aVertex.z) * length(side);
    vCover = aVertex.z == 0.0 ? 1.0 : clamp(halfWidth / max(uPixelScale.x + distance * uPixelScale.y, 1e-6), 1.0 / 32.0, 1.0);
    vColour = mix(colour * (0.45 + 0.75 * lit), uFogColour, fog * fog);

    int keep = int(c1.w + 0.5);
    vKeep = vec2(float(keep >> 8), float(keep & 255)) / 255.0;
}
