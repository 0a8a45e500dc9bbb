// The healthy/dry patches of the ground (#include): RenderSettings.patchLevel, bit for bit on the
// lattice hash, shared by the terrain and the plants' resolve pass so that dry grass stands on dry soil.
uniform vec3 uPatch;                             // 1 / scale (1/m), strength, enabled (0 or 1)
uniform int uPatchSeed;

// ground.PatchNoise.hash / valueNoise / level, bit for bit on the lattice hash
float hash(int x, int z, int seed) {
    uint h = uint(x) * 0x27d4eb2du ^ uint(z) * 0x165667b1u ^ uint(seed) * 0x6c8e9cf5u;
    h ^= h >> 15u;
    h *= 0x2c1b3c6du;
    h ^= h >> 12u;
    h *= 0x297a2d39u;
    h ^= h >> 15u;
    return float(h >> 8u) * (1.0 / 16777216.0);
}

float valueNoise(vec2 p, int seed) {
    vec2 f = floor(p);
    ivec2 i = ivec2(f);
    vec2 t = p - f;
    t = t * t * (3.0 - 2.0 * t);
    float a = hash(i.x, i.y, seed);
    float b = hash(i.x + 1, i.y, seed);
    float c = hash(i.x, i.y + 1, seed);
    float d = hash(i.x + 1, i.y + 1, seed);
    return a + (b - a) * t.x + (c - a) * t.y + (a - b - c + d) * t.x * t.y;
}

float patchLevel(vec2 xz) {
    vec2 p = xz * uPatch.x;
    float n = 0.65 * valueNoise(p, uPatchSeed) + 0.35 * valueNoise(2.7 * p, uPatchSeed + 1013);
    return smoothstep(0.0, 1.0, clamp((n - 0.35) / 0.3, 0.0, 1.0));
}

