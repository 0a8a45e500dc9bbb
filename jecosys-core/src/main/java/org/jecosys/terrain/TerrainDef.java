package org.jecosys.terrain;

import org.jecosys.math.Require;

/**
 * The terrain: a heightfield centred on the origin covering [-sizeX/2, sizeX/2] by
 * [-sizeZ/2, sizeZ/2] (paper §4.3: "a simple terrain mesh generator"). Immutable; any thread.
 *
 * @param sizeX       extent along X, metres, in (0, 100000]
 * @param sizeZ       extent along Z, metres, in (0, 100000]
 * @param resolution  heightfield vertices per side, in [2, 2049]
 * @param heightScale height of the highest point above the lowest, metres, in [0, 10000]
 * @param roughness   fractal roughness of the generated relief, in [0, 1]
 * @param seed        seed of the generated relief
 * @param heightmap   path of a greyscale PNG heightmap relative to the scene file, or null to generate
 * @param water       the water map
 * @param nutrients   the nutrient map
 */
public record TerrainDef(double sizeX, double sizeZ, int resolution, double heightScale, double roughness,
                         long seed, String heightmap, ResourceMapDef water, ResourceMapDef nutrients) {
    /**
     * Checks the components.
     *
     * @param sizeX       extent along X, metres, in [{@link #MIN_SIZE}, {@link #MAX_SIZE}]
     * @param sizeZ       extent along Z, metres, in [{@link #MIN_SIZE}, {@link #MAX_SIZE}]
     * @param resolution  heightfield vertices per side, in [2, {@link #MAX_RESOLUTION}]
     * @param heightScale relief height, metres, in [0, {@link #MAX_HEIGHT_SCALE}]
     * @param roughness   fractal roughness, in [0, 1]
     * @param seed        seed of the generated relief (any value)
     * @param heightmap   heightmap path relative to the scene file, or null to generate
     * @param water       the water map, not null
     * @param nutrients   the nutrient map, not null
     * @throws IllegalArgumentException when a component is out of range or a map is null
     */
    public TerrainDef {
        Require.range("sizeX", sizeX, MIN_SIZE, MAX_SIZE);
        Require.range("sizeZ", sizeZ, MIN_SIZE, MAX_SIZE);
        Require.range("resolution", resolution, 2, MAX_RESOLUTION);
        Require.range("heightScale", heightScale, 0, MAX_HEIGHT_SCALE);
        Require.range("roughness", roughness, 0, 1);
        Require.nonNull("water", water);
        Require.nonNull("nutrients", nutrients);
    }

    /** Smallest extent along X or Z, metres (the scene schema's range and the API's). */
    public static final double MIN_SIZE = 1e-3;
    /** Largest extent along X or Z, metres. */
    public static final double MAX_SIZE = 100_000;
    /** Most heightfield vertices per side. */
    public static final int MAX_RESOLUTION = 2049;
    /** Highest relief, metres. */
    public static final double MAX_HEIGHT_SCALE = 10_000;

    /**
     * A flat 40 m by 40 m terrain with full resources.
     *
     * @return 65 vertices per side, height 0, water and nutrients 1 everywhere
     */
    public static TerrainDef flat() {
        return new TerrainDef(40, 40, 65, 0, 0.5, 1, null, ResourceMapDef.UNIFORM_FULL, ResourceMapDef.UNIFORM_FULL);
    }
}
