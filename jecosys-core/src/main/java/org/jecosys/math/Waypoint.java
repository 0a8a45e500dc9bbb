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
     * @param x world X, metres, in [-{@link #MAX_COORDINATE}, {@link #MAX_COORDINATE}]
     * @param y height above the terrain, metres, in [-{@link #MAX_HEIGHT}, {@link #MAX_HEIGHT}]
     * @param z world Z, metres, in [-{@link #MAX_COORDINATE}, {@link #MAX_COORDINATE}]
     * @throws IllegalArgumentException when a coordinate is not finite or out of range
     */
    public Waypoint {
        Require.range("x", x, -MAX_COORDINATE, MAX_COORDINATE);
        Require.range("y", y, -MAX_HEIGHT, MAX_HEIGHT);
        Require.range("z", z, -MAX_COORDINATE, MAX_COORDINATE);
    }

    /**
     * Largest |X| or |Z| of any point of a scene (plants, flow centres, waypoints, the camera),
     * metres: the scene schema's range and the API's.
     */
    public static final double MAX_COORDINATE = 1e6;
    /** Largest |height| above the terrain of a waypoint or the camera, metres (scene schema and API). */
    public static final double MAX_HEIGHT = 1e5;
}
