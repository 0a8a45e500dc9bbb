package org.jecosys.world;

/**
 * A water or nutrient level at a world position, for {@link TilePlacer}: the game's (or a scene's)
 * soil over an unbounded world, where a {@link org.jecosys.terrain.ResourceMap} covers one finite
 * terrain.
 *
 * <p>Implementations must be pure (the same (x, z) always gives the same level) and safe for
 * concurrent calls from worker threads; they should not allocate.
 */
@FunctionalInterface
public interface ResourceFunction {
    /**
     * The level at world position (x, z). Any thread, concurrently; should not allocate.
     *
     * @param x world X, metres
     * @param z world Z, metres
     * @return the level, in [0, 1] (0 none, 1 saturated)
     */
    double level(double x, double z);
}
