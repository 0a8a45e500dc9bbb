package org.jecosys.math;

/**
 * The ground's height (and slope and normal) at a point: the one small interface through which
 * placement (and later the ground cover and the field) reads a game's own terrain. The library's heightfield implements it,
 * and so do the open world's rolling hills; a game implements it over its own terrain.
 *
 * <p>Implementations must be safe for concurrent calls from worker threads (tiles are built on
 * workers), must not allocate per call if they sit on a hot path, and must be pure: the same (x, z)
 * always gives the same height, or tiles would depend on the order they are built in.
 */
@FunctionalInterface
public interface HeightFunction {
    /** Step, metres, of the central differences of the default {@link #slope}. */
    double SLOPE_STEP = 0.05;

    /**
     * The ground height at world position (x, z). Any thread, concurrently; should not allocate.
     *
     * @param x world X, metres
     * @param z world Z, metres
     * @return the ground height (world Y, up), metres, finite
     */
    double height(double x, double z);

    /**
     * The slope of the ground at (x, z), radians in [0, pi/2): by default from central differences
     * of {@link #height} {@link #SLOPE_STEP} metres either side along X and Z (four height calls).
     * An implementation that knows its gradient may do better. Any thread; no allocation.
     *
     * @param x world X, metres
     * @param z world Z, metres
     * @return the angle of the ground from horizontal, radians in [0, pi/2)
     */
    default double slope(double x, double z) {
        double gx = (height(x + SLOPE_STEP, z) - height(x - SLOPE_STEP, z)) / (2 * SLOPE_STEP);
        double gz = (height(x, z + SLOPE_STEP) - height(x, z - SLOPE_STEP)) / (2 * SLOPE_STEP);
        return Math.atan(Math.sqrt(gx * gx + gz * gz));
    }

    /**
     * The ground's unit normal at (x, z), pointing up, written into {@code dest}: by default from the
     * same central differences as {@link #slope} (four height calls). An implementation that knows its
     * normals may do better ({@code terrain.Heightfield} blends its vertex normals). Any thread; no
     * allocation.
     *
     * @param x    world X, metres
     * @param z    world Z, metres
     * @param dest where to write
     * @return {@code dest}
     */
    default org.joml.Vector3f normal(double x, double z, org.joml.Vector3f dest) {
        double gx = (height(x + SLOPE_STEP, z) - height(x - SLOPE_STEP, z)) / (2 * SLOPE_STEP);
        double gz = (height(x, z + SLOPE_STEP) - height(x, z - SLOPE_STEP)) / (2 * SLOPE_STEP);
        double inv = 1 / Math.sqrt(gx * gx + 1 + gz * gz);
        return dest.set((float) (-gx * inv), (float) inv, (float) (-gz * inv));
    }
}
