// Seeded integer hashes and value noise for the plants' colour variation (#include). uSeed is the
// scene's colour seed.
uniform uint uSeed;

uint hash(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// a spread of standard deviation 1 from 10 bits of h: uniform on [-sqrt 3, sqrt 3]
float spread(uint h, int shift) {
    return (float((h >> uint(shift)) & 1023u) / 1023.0 - 0.5) * 3.4641016;
}

float lattice(ivec2 i) {
    return float(hash(uint(i.x) * 73856093u ^ uint(i.y) * 19349663u ^ uSeed) >> 8) / 16777216.0;
}

// smooth value noise in [0, 1], features about one unit apart
float valueNoise(vec2 p) {
    vec2 i = floor(p);
    vec2 f = p - i;
    f = f * f * (3.0 - 2.0 * f);
    ivec2 q = ivec2(i);
    float a = lattice(q);
    float b = lattice(q + ivec2(1, 0));
    float c = lattice(q + ivec2(0, 1));
    float d = lattice(q + ivec2(1, 1));
    return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}
