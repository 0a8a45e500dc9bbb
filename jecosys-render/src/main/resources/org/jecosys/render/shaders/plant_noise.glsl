// Seeded integer hashes for the plants' colour variation (#include). uSeed is the scene's colour seed.
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
