package org.jecosys.math;

/**
 * A point of a path over the ground: X and Z in metres, Y in metres above the terrain
 * (used by camera paths; flows ignore y). Immutable; any thread.
 */
public record Waypoint(double x, double y, double z) {
    public Waypoint {
        Require.finite("x", x);
        Require.finite("y", y);
        Require.finite("z", z);
    }
}
