package org.jecosys.terrain;

/**
 * Bilinear interpolation on a square grid of {@code res x res} samples stored row by row (index
 * {@code j * res + i}, i along X, j along Z), shared by {@link Heightfield#height} (vertices) and
 * {@link ResourceMap#sample} (cell centres). Callers map (x, z) to grid coordinates and clamp them
 * with {@link #clamp}. Any thread; no allocation.
 */
final class Grid {
    private Grid() {
    }

    /** u clamped to [0, max]. */
    static double clamp(double u, double max) {
        return u < 0 ? 0 : (u > max ? max : u);
    }

    /**
     * Bilinear value at grid coordinates (u, v), each in [0, res - 1] (res at least 2): the
     * differences of neighbouring samples are taken in float, as the samples are stored.
     */
    static double bilinear(float[] values, int res, double u, double v) {
        int i = Math.min((int) u, res - 2);
        int j = Math.min((int) v, res - 2);
        double fu = u - i;
        double fv = v - j;
        int k = j * res + i;
        double a = values[k] + (values[k + 1] - values[k]) * fu;
        double b = values[k + res] + (values[k + res + 1] - values[k + res]) * fu;
        return a + (b - a) * fv;
    }

    /** As {@link #bilinear(float[], int, double, double)} for double samples. */
    static double bilinear(double[] values, int res, double u, double v) {
        int i = Math.min((int) u, res - 2);
        int j = Math.min((int) v, res - 2);
        double fu = u - i;
        double fv = v - j;
        int k = j * res + i;
        double a = values[k] + (values[k + 1] - values[k]) * fu;
        double b = values[k + res] + (values[k + res + 1] - values[k + res]) * fu;
        return a + (b - a) * fv;
    }
}
