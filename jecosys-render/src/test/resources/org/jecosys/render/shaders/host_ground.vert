#version 330 core
// CoverSkinTest: a game's own ground, one flat colour at the positions given.
layout(location = 0) in vec3 aPos;
uniform mat4 uViewProj;
uniform float uRaise;                            // metres added to every height
void main() {
    gl_Position = uViewProj * vec4(aPos + vec3(0.0, uRaise, 0.0), 1.0);
}
