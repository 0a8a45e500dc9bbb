package org.jecosys.render.plant;

/**
 * The screen-door dither windows of plants in a level-switch or thinning band ({@code plant.frag}), as
 * {@link PlantBatches} reads them when it draws such a plant whole at one level: a plant's own fixed
 * threshold, and whether it falls in a packed window. Pure; no allocation.
 */
final class DitherWindows {
    private DitherWindows() {
    }

    /** {@return the plant's fixed threshold in (0, 1): a hash of its index} */
    static float threshold(int plant) {
        int h = plant * 0x9E3779B9;
        h ^= h >>> 16;
        h *= 0x85EBCA6B;
        h ^= h >>> 13;
        return ((h >>> 8) + 0.5f) * (1f / (1 << 24));
    }

    /** Whether threshold t lies in the packed window (lo &lt;&lt; 8 | hi, in 1/255): lo &lt;= t &lt; hi. */
    static boolean inWindow(int window, float t) {
        return t >= (window >>> 8) * (1f / 255) && t < (window & 255) * (1f / 255);
    }
}
