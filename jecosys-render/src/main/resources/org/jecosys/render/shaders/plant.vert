#version 330 core
// Plants (paper sections 4.1, 4.2.2): one instanced draw per species and level of detail. Each vertex
// names a slot (component instance of the plant), a pose-table point and side/normal coefficients.
// Per drawn component, the resolve pass (plant_resolve.vert) has written a record: the world position
// of the component's base (the plant's base plus its ground offset, or the animated tip of its
// parent), its bend azimuth as cosine and sine, the pose-table texel of pose k, the blend weight
// toward k + 1, and a packed word: this level's dither window (16 bits) and an 8-bit hash of the
// plant (colour variation). plant_common.glsl places and shades the vertex; 2 + 6 texel fetches.
// Line levels use plant_line.vert instead.

#include "plant_common.glsl"

out vec3 vColour;                                // lit and fogged per vertex
out float vCover;                                // share of the drawn width the part covers
flat out vec2 vKeep;                             // keep fragments with lo <= bayer < hi

void main() {
    int slot = int(aVertex.x);
    int point = int(aVertex.y);
    int ci = (uComponentBase + gl_InstanceID * uSlotCount + slot) * 2;
    vec4 c0 = texelFetch(uComponents, ci);       // base xyz, cos(azimuth)
    vec4 c1 = texelFetch(uComponents, ci + 1);   // texel of pose k, w, sin(azimuth), packed word
    int t = int(c1.x + 0.5) + point * 3;
    int u = t + int(aStride + 0.5);
    float w = c1.y;
    vec3 p = mix(texelFetch(uPoses, t).xyz, texelFetch(uPoses, u).xyz, w);
    vec3 side = mix(texelFetch(uPoses, t + 1).xyz, texelFetch(uPoses, u + 1).xyz, w);
    vec3 normal = mix(texelFetch(uPoses, t + 2).xyz, texelFetch(uPoses, u + 2).xyz, w);
    Placed v = place(c0.xyz, c0.w, c1.z, p, side, normal, true);
    gl_Position = uViewProj * vec4(v.world, 1.0);
    int word = int(c1.w);                        // exact: an integer below 2^24 (no + 0.5: above 2^23 it rounds)
    vColour = shade(v, uint(word >> 16), slot, c0.xyz);
    vCover = v.cover;
    vKeep = vec2(float((word >> 8) & 255), float(word & 255)) / 255.0;
}
