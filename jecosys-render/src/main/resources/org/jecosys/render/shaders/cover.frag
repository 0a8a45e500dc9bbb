#version 330 core
// Near ground cover (CoverBlades): the colour lit and hazed per vertex.
in vec3 vColour;
layout(location = 0) out vec4 fragColour;
// the resolve's detail mask (GlFramebuffer): thin blades want the wide filter
layout(location = 1) out vec4 fragDetail;

void main() {
    fragColour = vec4(vColour, 1.0);
    fragDetail = vec4(1.0);
}
