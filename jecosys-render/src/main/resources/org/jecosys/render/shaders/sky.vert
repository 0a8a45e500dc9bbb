#version 330 core
// Sky: one triangle covering the viewport at depth 1 (z = w), no vertex data.
out vec2 vNdc;

void main() {
    vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    vNdc = p;
    gl_Position = vec4(p, 1.0, 1.0);
}
