package org.jecosys.terrain;

import org.jecosys.math.Require;

/**
 * One plant placed by hand at (x, z) on the terrain, outside any distribution (e.g. the single
 * rose of paper Table 1). Immutable; any thread.
 *
 * @param species id of the species
 * @param x       X, metres
 * @param z       Z, metres
 * @param azimuth rest azimuth, radians
 */
public record PlacementDef(String species, double x, double z, double azimuth) {
    /**
     * Checks the components.
     *
     * @param species species id, not null
     * @param x       X, metres (finite)
     * @param z       Z, metres (finite)
     * @param azimuth rest azimuth, radians (finite)
     * @throws IllegalArgumentException when species is null or a number is not finite
     */
    public PlacementDef {
        Require.nonNull("species", species);
        Require.finite("x", x);
        Require.finite("z", z);
        Require.finite("azimuth", azimuth);
    }
}
