// The screen-door dither of a level-of-detail band (#include; plant.frag, plant_line.frag,
// plant_caster.frag): level L keeps the pixels with lo <= bayer < hi, level L + 1 the complementary ones.

// 4x4 ordered-dither threshold in (0, 1), arithmetic (bit-reversed interleave of x ^ y and y)
float bayer4(vec2 p) {
    ivec2 q = ivec2(p) & 3;
    int a = q.x ^ q.y;
    int m = ((a & 1) << 3) | ((q.y & 1) << 2) | (a & 2) | ((q.y & 2) >> 1);
    return (float(m) + 0.5) / 16.0;
}

// whether this fragment is dropped by the band's window keep = (lo, hi)
bool dithered(vec2 keep) {
    float b = bayer4(gl_FragCoord.xy);
    return b < keep.x || b >= keep.y;
}
