package org.jecosys.terrain;

import org.jecosys.math.Require;

/**
 * Where and how many plants of one species grow (paper §4.3). Plants are placed concurrently with
 * the other distributions, each consuming resources in its footprint. Immutable; any thread.
 *
 * @param species      id of the species
 * @param count        exact number of plants, in [0, 10,000,000], or -1 to use {@code density}
 * @param density      plants per square metre where conditions hold (used when count is -1), in [0, 10000]
 * @param minWater     lowest water level the species accepts, in [0, 1]
 * @param maxWater     highest water level, in [minWater, 1]
 * @param minNutrients lowest nutrient level, in [0, 1]
 * @param maxNutrients highest nutrient level, in [minNutrients, 1]
 * @param maxSlope     steepest ground, radians, in [0, pi/2]
 * @param minAltitude  lowest terrain height, metres
 * @param maxAltitude  highest terrain height, metres, &gt;= minAltitude
 * @param footprint    radius of ground a plant takes, metres, in (0, 100]
 * @param waterUse     water level a plant consumes in its footprint, in [0, 1]
 * @param nutrientUse  nutrient level a plant consumes in its footprint, in [0, 1]
 */
public record DistributionDef(String species, int count, double density, double minWater, double maxWater,
                              double minNutrients, double maxNutrients, double maxSlope, double minAltitude,
                              double maxAltitude, double footprint, double waterUse, double nutrientUse) {
    /** Largest exact count. */
    public static final int MAX_COUNT = 10_000_000;

    public DistributionDef {
        Require.nonNull("species", species);
        Require.range("count", count, -1, MAX_COUNT);
        Require.range("density", density, 0, 10_000);
        Require.range("minWater", minWater, 0, 1);
        Require.range("maxWater", maxWater, minWater, 1);
        Require.range("minNutrients", minNutrients, 0, 1);
        Require.range("maxNutrients", maxNutrients, minNutrients, 1);
        Require.range("maxSlope", maxSlope, 0, Math.PI / 2);
        Require.finite("minAltitude", minAltitude);
        Require.finite("maxAltitude", maxAltitude);
        if (maxAltitude < minAltitude) {
            throw new IllegalArgumentException("maxAltitude must be >= minAltitude");
        }
        Require.range("footprint", footprint, 1e-6, 100);
        Require.range("waterUse", waterUse, 0, 1);
        Require.range("nutrientUse", nutrientUse, 0, 1);
    }
}
