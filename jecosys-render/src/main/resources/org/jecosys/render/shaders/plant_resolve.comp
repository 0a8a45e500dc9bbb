#version 430 core
// The per-component pass on OpenGL 4.3 and later (plant_resolve.glsl): one invocation per drawn
// component, its record stored into the component buffer at its list's place. One dispatch covers
// every list of its program variant: a table (uLists) gives each list's first invocation, instance
// records, slots, first record, slot looks, level kind and dry tips, and each invocation finds its
// list by binary search (a dispatch costs far more than the search on a software rasteriser).

#define LIST_TABLE
layout(local_size_x = 64) in;

uniform isamplerBuffer uLists;                   // RGBA32I, 2 texels per list: (first invocation,
                                                 // instance base, slots, first record), (slot base,
                                                 // line level 0/1, dry tips as float bits, 0)
uniform int uListFirst;                          // this dispatch's first list in the table
uniform int uListCount;                          // and how many
uniform int uCount;                              // invocations of this dispatch (components drawn)
uniform int uFirst;                              // the first of them this dispatch resolves

layout(std430, binding = 0) writeonly buffer Records {
    vec4 records[];                              // 3 per drawn component
};

#include "plant_resolve.glsl"

void main() {
    int index = uFirst + int(gl_GlobalInvocationID.x);
    if (index >= uCount) {
        return;
    }
    // the last list whose first invocation is <= index
    int lo = 0;
    int hi = uListCount - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) >> 1;
        if (texelFetch(uLists, 2 * (uListFirst + mid)).x <= index) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    ivec4 a = texelFetch(uLists, 2 * (uListFirst + lo));
    ivec4 b = texelFetch(uLists, 2 * (uListFirst + lo) + 1);
    uInstanceBase = a.y;
    uSlots = a.z;
    uSlotBase = b.x;
    uLines = b.y;
    uDryTips = intBitsToFloat(b.z);
    int local = index - a.x;
    vec4 r0;
    vec4 r1;
    vec4 r2;
    resolveComponent(local, r0, r1, r2);
    int at = 3 * (a.w + local);
    records[at] = r0;
    records[at + 1] = r1;
    records[at + 2] = r2;
}
