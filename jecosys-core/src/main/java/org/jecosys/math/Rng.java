package org.jecosys.math;

/**
 * A small, fast, seeded pseudo-random generator (SplitMix64). The same seed gives the same
 * sequence on every JVM. Not thread-safe: give each thread, or each fixed chunk of work, its own
 * instance (see {@link #forStream(long, long)}) so results do not depend on thread count.
 * No method allocates.
 */
public final class Rng {
    private long state;

    /**
     * A generator starting from {@code seed}.
     *
     * @param seed the initial state; any value
     */
    public Rng(long seed) {
        this.state = seed;
    }

    /**
     * A generator for sub-stream {@code stream} of {@code seed}: independent streams for chunks
     * of work, identical whichever thread runs them.
     *
     * @param seed   the scene's (or the step's) seed
     * @param stream the sub-stream number, e.g. a chunk or cell index
     * @return a new generator (allocates)
     */
    public static Rng forStream(long seed, long stream) {
        return new Rng(mix(seed ^ mix(stream + 0x632BE59BD9B4E019L)));
    }

    /**
     * Re-seeds this generator in place.
     *
     * @param seed the new state; the sequence then equals that of {@code new Rng(seed)}
     */
    public void reseed(long seed) {
        this.state = seed;
    }

    /**
     * The next 64 random bits.
     *
     * @return uniformly distributed over all long values
     */
    public long nextLong() {
        state += 0x9E3779B97F4A7C15L;
        return mix(state);
    }

    /**
     * Uniform in [0, 1).
     *
     * @return a multiple of 2^-53 in [0, 1)
     */
    public double nextDouble() {
        return (nextLong() >>> 11) * 0x1.0p-53;
    }

    /**
     * Uniform in [min, max).
     *
     * @param min lower bound (inclusive)
     * @param max upper bound (exclusive); not checked against {@code min}
     * @return a value in [min, max)
     */
    public double nextDouble(double min, double max) {
        return min + (max - min) * nextDouble();
    }

    /**
     * Uniform in [0, bound), bound &gt; 0.
     *
     * @param bound number of possible values, &gt; 0
     * @return a value in [0, bound)
     * @throws IllegalArgumentException when {@code bound} &le; 0
     */
    public int nextInt(int bound) {
        if (bound <= 0) {
            throw new IllegalArgumentException("bound must be > 0, got " + bound);
        }
        return (int) (((nextLong() >>> 33) * bound) >>> 31);
    }

    /**
     * Standard normal (Box-Muller, one value per call).
     *
     * @return a normally distributed value, mean 0, standard deviation 1
     */
    public double nextGaussian() {
        double u1 = 1.0 - nextDouble();
        double u2 = nextDouble();
        return Math.sqrt(-2.0 * Math.log(u1)) * Math.cos(2 * Math.PI * u2);
    }

    /**
     * The SplitMix64 finaliser: a bijective 64-bit hash.
     *
     * @param z the value to hash
     * @return its hash; distinct inputs give distinct outputs
     */
    public static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
