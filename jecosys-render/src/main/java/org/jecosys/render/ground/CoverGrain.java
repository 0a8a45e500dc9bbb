package org.jecosys.render.ground;

import java.nio.ByteBuffer;

/**
 * The ground cover's grain: a repeating square tile of speckle, bright and dark flecks about two texels
 * across (blade tips and the gaps between them seen from above), that the terrain shader lays over the
 * cover's colour at two scales. Seeded, so the same on every run. Any thread; {@link #bytes} allocates
 * nothing.
 */
final class CoverGrain {
    /** Texels on a side of the tile (a power of two, for the mipmaps). */
    static final int SIDE = 128;

    private CoverGrain() {
    }

    /** Hash of a texel to [0, 1). */
    private static double hash(int x, int y) {
        int h = (x & (SIDE - 1)) * 0x27d4eb2d ^ (y & (SIDE - 1)) * 0x165667b1 ^ 0x5bd1e995;
        h ^= h >>> 15;
        h *= 0x2c1b3c6d;
        h ^= h >>> 12;
        h *= 0x297a2d39;
        h ^= h >>> 15;
        return (h >>> 8) / 16777216.0;
    }

    /**
     * Writes the tile, rows of {@link #SIDE} bytes, into {@code dest} from its position, and flips it.
     * Each texel is its own noise half and its eight neighbours' mean half (flecks a little larger than a
     * texel), stretched to use the byte's range.
     *
     * @param dest at least {@code SIDE * SIDE} bytes remaining
     * @return {@code dest}, flipped
     */
    static ByteBuffer bytes(ByteBuffer dest) {
        for (int y = 0; y < SIDE; y++) {
            for (int x = 0; x < SIDE; x++) {
                double around = 0;
                for (int dy = -1; dy <= 1; dy++) {
                    for (int dx = -1; dx <= 1; dx++) {
                        if (dx != 0 || dy != 0) {
                            around += hash(x + dx, y + dy);
                        }
                    }
                }
                double v = 0.5 * hash(x, y) + 0.5 * around / 8;
                // the mean of such a mix is 0.5 with a spread of about 0.17: stretch it to +-3 spreads
                double s = 0.5 + (v - 0.5) * 2.8;
                dest.put((byte) Math.round(Math.max(0, Math.min(1, s)) * 255));
            }
        }
        return dest.flip();
    }
}
