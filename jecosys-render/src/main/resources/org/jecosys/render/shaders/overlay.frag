#version 330 core
in vec4 vColour;
layout(location = 0) out vec4 fragColour;
// the resolve's detail mask (GlFramebuffer): 1 where thin geometry wants the wide filter, 0 elsewhere;
// written only into the library's own framebuffer (a host's other draw buffers are masked off)
layout(location = 1) out vec4 fragDetail;

void main() {
    fragColour = vColour;
    fragDetail = vec4(0.0);
}
