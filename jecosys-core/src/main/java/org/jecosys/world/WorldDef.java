package org.jecosys.world;

import java.util.List;
import org.jecosys.math.Require;
import org.jecosys.terrain.DistributionDef;

/**
 * A scene's open world ({@code <world>}): plants grown in square tiles within a radius of the views
 * on unbounded rolling hills ({@link RollingTerrain}), each tile placed by the scene's density-based
 * distributions ({@link TilePlacer}). Immutable; any thread.
 *
 * @param tileSize         a tile's side, metres, in [{@link #MIN_TILE_SIZE}, {@link #MAX_TILE_SIZE}]
 * @param radius           reach of a view, metres: tiles whose square comes this close are live, in
 *                         (0, {@link #MAX_RADIUS}] and at most 64 tile sizes
 * @param reliefHeight     the hills' largest height above or below 0, metres, in [0, {@link #MAX_RELIEF_HEIGHT}]
 * @param reliefWavelength the size of the largest hills, metres, in [1, {@link #MAX_RELIEF_WAVELENGTH}]
 * @param reliefOctaves    noise layers of the hills, in [1, 12]
 * @param reliefSeed       selects the hills
 */
public record WorldDef(double tileSize, double radius, double reliefHeight, double reliefWavelength, int reliefOctaves,
                       long reliefSeed) {
    /** Smallest tile side, metres. */
    public static final double MIN_TILE_SIZE = 4;
    /** Largest tile side, metres. */
    public static final double MAX_TILE_SIZE = 256;
    /** Largest radius, metres. */
    public static final double MAX_RADIUS = 2000;
    /** Highest relief, metres. */
    public static final double MAX_RELIEF_HEIGHT = 1000;
    /** Longest relief wavelength, metres. */
    public static final double MAX_RELIEF_WAVELENGTH = 100_000;
    /** Default tile side, metres. */
    public static final double DEFAULT_TILE_SIZE = 16;
    /** Default radius, metres. */
    public static final double DEFAULT_RADIUS = 64;

    /**
     * Checks the components.
     *
     * @param tileSize         a tile's side, metres
     * @param radius           reach of a view, metres
     * @param reliefHeight     the hills' largest height, metres
     * @param reliefWavelength the size of the largest hills, metres
     * @param reliefOctaves    noise layers of the hills
     * @param reliefSeed       selects the hills
     * @throws IllegalArgumentException when a component is out of range (the message starts with its name)
     */
    public WorldDef {
        Require.range("tileSize", tileSize, MIN_TILE_SIZE, MAX_TILE_SIZE);
        Require.range("radius", radius, 1e-3, MAX_RADIUS);
        if (radius > 64 * tileSize) {
            throw new IllegalArgumentException("radius " + radius + " m is more than 64 tiles of " + tileSize + " m");
        }
        Require.range("reliefHeight", reliefHeight, 0, MAX_RELIEF_HEIGHT);
        Require.range("reliefWavelength", reliefWavelength, 1, MAX_RELIEF_WAVELENGTH);
        Require.range("reliefOctaves", reliefOctaves, 1, 12);
    }

    /** {@return the hills the plants stand on} Allocates. */
    public RollingTerrain relief() {
        return new RollingTerrain(reliefSeed, reliefHeight, reliefWavelength, reliefOctaves);
    }

    /**
     * The tiles' placement for these distributions on {@link #relief()} (water and nutrient limits are
     * not checked: the open world has no resource maps). Allocates; any thread.
     *
     * @param seed          the scene's master seed
     * @param distributions density-based distributions ({@code count == -1})
     * @param speciesOf     species index of each distribution
     * @return the placer
     * @throws IllegalArgumentException when the placer refuses them (see {@link TilePlacer})
     */
    public TilePlacer placer(long seed, List<DistributionDef> distributions, int[] speciesOf) {
        return new TilePlacer(seed, tileSize, distributions, speciesOf, relief());
    }
}
