package org.jecosys.render.ground;

/**
 * The healthy/dry patch noise of the ground and the plants: two octaves of seeded value noise made
 * into patches with a smooth step. {@code patches.glsl} computes the same function bit for bit on the
 * lattice hash; {@code RenderSettings.patchLevel} gives it in metres, and the plants' colour variation
 * ({@code ComponentLooks}) reads it at each plant's root. Any thread; no allocation.
 */
public final class PatchNoise {
    private PatchNoise() {
    }

    /**
     * The patch level at a point given in patch units (metres / patch size), before the patches'
     * strength scales it. Any thread; no allocation.
     *
     * @param px   X in patch units
     * @param pz   Z in patch units
     * @param seed the patches' seed
     * @return the level, 0 healthy to 1 driest
     */
    public static float level(float px, float pz, int seed) {
        float n = 0.65f * valueNoise(px, pz, seed) + 0.35f * valueNoise(2.7f * px, 2.7f * pz, seed + 1013);
        float t = Math.max(0, Math.min(1, (n - 0.35f) / 0.3f));
        return t * t * (3 - 2 * t);
    }

    /** Bilinear value noise with smooth interpolation, in [0, 1]; mirrored in patches.glsl. */
    static float valueNoise(float x, float z, int seed) {
        float fx = (float) Math.floor(x);
        float fz = (float) Math.floor(z);
        int ix = (int) fx;
        int iz = (int) fz;
        float tx = x - fx;
        float tz = z - fz;
        tx = tx * tx * (3 - 2 * tx);
        tz = tz * tz * (3 - 2 * tz);
        float a = hash(ix, iz, seed);
        float b = hash(ix + 1, iz, seed);
        float c = hash(ix, iz + 1, seed);
        float d = hash(ix + 1, iz + 1, seed);
        return a + (b - a) * tx + (c - a) * tz + (a - b - c + d) * tx * tz;
    }

    /** An integer hash of a lattice point to [0, 1]; mirrored in patches.glsl (uint arithmetic). */
    static float hash(int x, int z, int seed) {
        int h = x * 0x27d4eb2d ^ z * 0x165667b1 ^ seed * 0x6c8e9cf5;
        h ^= h >>> 15;
        h *= 0x2c1b3c6d;
        h ^= h >>> 12;
        h *= 0x297a2d39;
        h ^= h >>> 15;
        return (h >>> 8) * (1f / (1 << 24));
    }
}
