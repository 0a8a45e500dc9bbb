#version 430 core
// The per-component pass on OpenGL 4.3 and later (plant_resolve.glsl): one invocation per drawn
// component of a draw list, its record stored into the component buffer at the list's place. A
// software rasteriser runs compute on all its threads, where it runs vertex shaders on one.

layout(local_size_x = 64) in;

uniform int uCount;                              // components drawn by this list
uniform int uFirst;                              // the first of them this dispatch resolves
uniform int uRecordBase;                         // first record of this list

layout(std430, binding = 0) writeonly buffer Records {
    vec4 records[];                              // 3 per drawn component
};

#include "plant_resolve.glsl"

void main() {
    int index = uFirst + int(gl_GlobalInvocationID.x);
    if (index >= uCount) {
        return;
    }
    vec4 r0;
    vec4 r1;
    vec4 r2;
    resolveComponent(index, r0, r1, r2);
    int at = 3 * (uRecordBase + index);
    records[at] = r0;
    records[at + 1] = r1;
    records[at + 2] = r2;
}
