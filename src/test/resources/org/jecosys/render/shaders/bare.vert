#version 330 core
// Benchmark reference: the cheapest instanced draw of the same triangle count.
layout(location = 0) in vec3 aPos;
uniform mat4 uViewProj;
void main() {
    float i = float(gl_InstanceID);
    vec3 offset = vec3(mod(i, 100.0) * 0.2 - 10.0, 0.0, floor(i / 100.0) * 0.2 - 10.0);
    gl_Position = uViewProj * vec4(aPos + offset, 1.0);
}
