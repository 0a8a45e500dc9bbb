#version 330 core
// Benchmark reference: the cheapest instanced draw of the same primitives, each instance at a plant.
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aOffset;            // per instance (divisor 1): a plant's base
uniform mat4 uViewProj;
void main() {
    gl_Position = uViewProj * vec4(aPos + aOffset, 1.0);
}
