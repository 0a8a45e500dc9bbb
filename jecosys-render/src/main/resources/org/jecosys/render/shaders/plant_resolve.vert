#version 330 core
// The per-component pass on OpenGL 3.3 (plant_resolve.glsl): one point per drawn component of a draw
// list, rasterisation discarded, its record captured by transform feedback at the list's place in
// the component buffer.

out vec4 vRecord0;
out vec4 vRecord1;
out vec4 vRecord2;

#include "plant_resolve.glsl"

void main() {
    resolveComponent(gl_VertexID, vRecord0, vRecord1, vRecord2);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
