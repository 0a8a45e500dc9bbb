package org.jecosys.terrain;

import org.jecosys.math.Require;
import org.jecosys.math.Waypoint;

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
     * @param x       X, metres, |x| &lt;= {@link Waypoint#MAX_COORDINATE}
     * @param z       Z, metres, |z| &lt;= {@link Waypoint#MAX_COORDINATE}
     * @param azimuth rest azimuth, radians, within +-{@link #MAX_AZIMUTH_DEGREES} degrees
     * @throws IllegalArgumentException when species is null or a number is out of range
     */
    public PlacementDef {
        Require.nonNull("species", species);
        Require.range("x", x, -Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE);
        Require.range("z", z, -Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE);
        Require.degrees("azimuth", azimuth, -MAX_AZIMUTH_DEGREES, MAX_AZIMUTH_DEGREES);
    }

    /** Largest |rest azimuth|, degrees (the API takes radians). */
    public static final double MAX_AZIMUTH_DEGREES = 360;
}
