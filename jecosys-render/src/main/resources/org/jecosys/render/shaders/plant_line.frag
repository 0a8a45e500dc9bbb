#version 330 core
// Screen-door dither across a level-of-detail band: level L keeps pixels with lo <= bayer < hi, level
// L + 1 the complementary ones, so the switch is gradual. Only plants in a band are drawn with the
// test (compiled with DITHER); the others are drawn by the variant without it, which never
// discards, so the rasteriser can test depth before shading.
// Line variant of plant.frag: one flat, fogged colour per segment from plant_line.vert, with the
// share of a pixel the leaf covers there as alpha (the line level is blended over the opaque scene).
flat in vec3 vColour;
#ifdef DITHER
flat in vec2 vKeep;
#endif
in float vCover;
layout(location = 0) out vec4 fragColour;
// the resolve's detail mask (GlFramebuffer): 1 where thin geometry wants the wide filter, 0 elsewhere;
// written only into the library's own framebuffer (a host's other draw buffers are masked off)
layout(location = 1) out vec4 fragDetail;

#ifdef DITHER
#include "dither.glsl"
#endif

void main() {
#ifdef DITHER
    if (dithered(vKeep)) {
        discard;
    }
#endif
    fragColour = vec4(vColour, vCover);
    fragDetail = vec4(1.0);
}
