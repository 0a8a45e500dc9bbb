package org.jecosys.render;

/** Which resource map tints the terrain (paper §4.3: why plants grow where they do). */
public enum TerrainTint {
    /** Plain soil and grass colour. */
    NONE,
    /** Dry sand to blue by the water level. */
    WATER,
    /** Pale to dark green by the nutrient level. */
    NUTRIENTS
}
