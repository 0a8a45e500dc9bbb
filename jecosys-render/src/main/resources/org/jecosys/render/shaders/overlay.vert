#version 330 core
// Top-down map of the ground plane: world (x, z) to the overlay viewport, north (-Z) up.
layout(location = 0) in vec2 aXZ;
layout(location = 1) in vec4 aColour;
uniform vec4 uRect;   // minX, minZ, sizeX, sizeZ
out vec4 vColour;

void main() {
    vec2 uv = (aXZ - uRect.xy) / uRect.zw;
    gl_Position = vec4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, 0.0, 1.0);
    vColour = aColour;
}
