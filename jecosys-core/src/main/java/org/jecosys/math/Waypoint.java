package org.jecosys.math;

/**
 * A point of a path over the ground: X and Z in metres, Y in metres above the terrain
 * (used by camera paths; flows ignore y). Immutable; any thread.
 *
 * @param x world X, metres
 * @param y height above the terrain at (x, z), metres
 * @param z world Z, metres
 */
public record Waypoint(double x, double y, double z) {
    /**
     * Checks the coordinates.
     *
     * @param x world X, metres (finite)
     * @param y height above the terrain, metres (finite)
     * @param z world Z, metres (finite)
     * @throws IllegalArgumentException when a coordinate is not finite
     */
    public Waypoint {
        Require.finite("x", x);
        Require.finite("y", y);
        Require.finite("z", z);
    }
}
