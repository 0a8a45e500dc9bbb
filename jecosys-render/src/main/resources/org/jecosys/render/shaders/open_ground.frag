#version 330 core
in vec3 vColour;
layout(location = 0) out vec4 fColour;

void main() {
    fColour = vec4(vColour, 1.0);
}
