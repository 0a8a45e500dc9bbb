#version 330 core
// Sky: one triangle covering the viewport at depth 1 (z = w), no vertex data. The points of the
// view ray on the near plane and at mid depth are linear in screen position, so they are computed
// here and interpolated (the triangle has w = 1: plain linear interpolation).
uniform mat4 uInvViewProj;
out vec4 vNear;
out vec4 vMid;

void main() {
    vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    vNear = uInvViewProj * vec4(p, -1.0, 1.0);
    vMid = uInvViewProj * vec4(p, 0.0, 1.0);     // mid depth: better conditioned than the far plane
    gl_Position = vec4(p, 1.0, 1.0);
}
