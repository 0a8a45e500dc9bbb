#version 330 core
// Gizmos and wind arrows: world-space triangles with a colour each (built on the CPU per frame).
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec4 aColour;
uniform mat4 uViewProj;
uniform float uAlpha;   // 1, or the faint alpha of the pass that draws what the scene hides
out vec4 vColour;

void main() {
    gl_Position = uViewProj * vec4(aPos, 1.0);
    vColour = vec4(aColour.rgb, aColour.a * uAlpha);
}
