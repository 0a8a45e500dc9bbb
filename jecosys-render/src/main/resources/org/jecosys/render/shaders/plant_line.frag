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
// 4x4 ordered-dither threshold in (0, 1), arithmetic (bit-reversed interleave of x ^ y and y)
float bayer4(vec2 p) {
    ivec2 q = ivec2(p) & 3;
    int a = q.x ^ q.y;
    int m = ((a & 1) << 3) | ((q.y & 1) << 2) | (a & 2) | ((q.y & 2) >> 1);
    return (float(m) + 0.5) / 16.0;
}
#endif

void main() {
#ifdef DITHER
    float b = bayer4(gl_FragCoord.xy);
    if (b < vKeep.x || b >= vKeep.y) {
        discard;
    }
#endif
    fragColour = vec4(vColour, vCover);
    fragDetail = vec4(1.0);
}
