#version 330 core
// The second half of a multisampled framebuffer's resolve: the samples of each pixel have been
// averaged (a box filter one pixel wide); this widens the filter where thin geometry was drawn
// (resolve_filter.glsl).
#include "resolve_filter.glsl"
uniform sampler2D uImage;
uniform sampler2D uDetail;
uniform vec2 uTexel;                             // 1 / size
uniform vec3 uWeights;                           // box, tent, wide; sum 1
layout(location = 0) out vec4 fragColour;

void main() {
    fragColour = resolveFiltered(uImage, uDetail, gl_FragCoord.xy * uTexel, uTexel, uWeights);
}
