package org.jecosys.math;

/**
 * Seeded, smooth value noise in 2D and 3D, and fractal sums of it. Values lie in [-1, 1].
 * Pure functions of (seed, coordinates): any thread, no allocation, identical on every JVM.
 */
public final class Noise {
    private Noise() {
    }

    /**
     * Smooth value noise along one axis, period-free, in [-1, 1]: a seeded value at every integer,
     * blended with a quintic fade (continuous value, slope and curvature).
     *
     * @param seed selects the noise pattern
     * @param x    coordinate, in lattice cells (one cell per unit)
     * @return the noise value, in [-1, 1]
     */
    public static double value1(long seed, double x) {
        long xi = (long) Math.floor(x);
        double a = lattice(seed, xi, 0, 0);
        double b = lattice(seed, xi + 1, 0, 0);
        return a + (b - a) * fade(x - xi);
    }

    /**
     * {@link #value1} at one coordinate for many seeds: the part of its lattice hashes that does not
     * depend on the seed and its blend factor, worked out once by {@link #at}, so that
     * {@link #value} costs two hashes instead of eight, with the very bits of {@link #value1}.
     * Mutable: one thread sets it, then any threads read it. No allocation after construction.
     */
    public static final class Slice1 {
        private long key0;
        private long key1;
        private double blend;

        /**
         * Moves the slice to coordinate x.
         *
         * @param x coordinate, in lattice cells
         * @return this slice
         */
        public Slice1 at(double x) {
            long xi = (long) Math.floor(x);
            key0 = latticeKey(xi, 0, 0);
            key1 = latticeKey(xi + 1, 0, 0);
            blend = fade(x - xi);
            return this;
        }

        /**
         * {@return {@code value1(seed, x)} at the slice's coordinate x, bit for bit}
         *
         * @param seed selects the noise pattern
         */
        public double value(long seed) {
            double a = unit(Rng.mix(seed ^ key0));
            double b = unit(Rng.mix(seed ^ key1));
            return a + (b - a) * blend;
        }
    }

    /**
     * Smooth value noise at (x, y), period-free, in [-1, 1].
     *
     * @param seed selects the noise pattern
     * @param x    first coordinate, in lattice cells (one cell per unit)
     * @param y    second coordinate, in lattice cells
     * @return the noise value, in [-1, 1]
     */
    public static double value2(long seed, double x, double y) {
        long xi = (long) Math.floor(x);
        long yi = (long) Math.floor(y);
        double fx = fade(x - xi);
        double fy = fade(y - yi);
        double v00 = lattice(seed, xi, yi, 0);
        double v10 = lattice(seed, xi + 1, yi, 0);
        double v01 = lattice(seed, xi, yi + 1, 0);
        double v11 = lattice(seed, xi + 1, yi + 1, 0);
        double a = v00 + (v10 - v00) * fx;
        double b = v01 + (v11 - v01) * fx;
        return a + (b - a) * fy;
    }

    /**
     * Smooth value noise at (x, y, z), in [-1, 1].
     *
     * @param seed selects the noise pattern
     * @param x    first coordinate, in lattice cells (one cell per unit)
     * @param y    second coordinate, in lattice cells
     * @param z    third coordinate, in lattice cells (often time, to animate a 2D pattern)
     * @return the noise value, in [-1, 1]
     */
    public static double value3(long seed, double x, double y, double z) {
        long xi = (long) Math.floor(x);
        long yi = (long) Math.floor(y);
        long zi = (long) Math.floor(z);
        double fx = fade(x - xi);
        double fy = fade(y - yi);
        double fz = fade(z - zi);
        double c00 = lerp(lattice(seed, xi, yi, zi), lattice(seed, xi + 1, yi, zi), fx);
        double c10 = lerp(lattice(seed, xi, yi + 1, zi), lattice(seed, xi + 1, yi + 1, zi), fx);
        double c01 = lerp(lattice(seed, xi, yi, zi + 1), lattice(seed, xi + 1, yi, zi + 1), fx);
        double c11 = lerp(lattice(seed, xi, yi + 1, zi + 1), lattice(seed, xi + 1, yi + 1, zi + 1), fx);
        return lerp(lerp(c00, c10, fy), lerp(c01, c11, fy), fz);
    }

    /**
     * Fractal sum of {@code octaves} layers of 2D value noise, each at twice the frequency and
     * {@code gain} times the amplitude of the last, normalised to [-1, 1].
     *
     * @param seed    selects the noise pattern (each octave uses a seed derived from it)
     * @param x       first coordinate, in cells of the first octave
     * @param y       second coordinate, in cells of the first octave
     * @param octaves number of layers; 0 or less gives 0
     * @param gain    amplitude ratio between successive octaves, typically in (0, 1)
     * @return the normalised sum, in [-1, 1]
     */
    public static double fractal2(long seed, double x, double y, int octaves, double gain) {
        double sum = 0;
        double amp = 1;
        double norm = 0;
        double f = 1;
        for (int o = 0; o < octaves; o++) {
            sum += amp * value2(seed + o * 0x9E3779B97F4A7C15L, x * f, y * f);
            norm += amp;
            amp *= gain;
            f *= 2;
        }
        return norm == 0 ? 0 : sum / norm;
    }

    /** A hash of the lattice point, uniform in [-1, 1]. */
    private static double lattice(long seed, long x, long y, long z) {
        return unit(Rng.mix(seed ^ latticeKey(x, y, z)));
    }

    /** The seed-free part of the hash of lattice point (x, y, z). */
    private static long latticeKey(long x, long y, long z) {
        return Rng.mix(x * 0x9E3779B97F4A7C15L ^ Rng.mix(y * 0xC2B2AE3D27D4EB4FL ^ Rng.mix(z)));
    }

    /** A 64-bit hash as a value uniform in [-1, 1]. */
    private static double unit(long h) {
        return (h >>> 11) * 0x1.0p-52 - 1.0;
    }

    private static double fade(double t) {
        return t * t * t * (t * (t * 6 - 15) + 10);
    }

    private static double lerp(double a, double b, double t) {
        return a + (b - a) * t;
    }
}
