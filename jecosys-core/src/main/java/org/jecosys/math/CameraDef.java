package org.jecosys.math;

import java.util.List;

/**
 * A camera's start pose and optional path (paper §5.2: the viewer walked through each scene
 * during the tests). Immutable; any thread.
 *
 * @param x          eye position X, metres
 * @param y          eye height above the terrain at (x, z), metres
 * @param z          eye position Z, metres
 * @param yaw        heading in radians; 0 looks along -Z, positive turns toward +X
 * @param pitch      radians, positive looks up, in [-pi/2, pi/2]
 * @param fovY       vertical field of view, radians, in (0, pi)
 * @param near       near clip distance, metres, &gt; 0
 * @param far        far clip distance, metres, &gt; near
 * @param path       waypoints the camera walks through (may be empty)
 * @param pathSpeed  walking speed along the path, m/s
 * @param pathLoop   whether the path starts again at its end
 */
public record CameraDef(double x, double y, double z, double yaw, double pitch, double fovY,
                        double near, double far, List<Waypoint> path, double pathSpeed, boolean pathLoop) {
    /**
     * Checks every component and copies {@code path}.
     *
     * @param x         eye position X, metres, |x| &lt;= {@link Waypoint#MAX_COORDINATE}
     * @param y         eye height above the terrain, metres, |y| &lt;= {@link Waypoint#MAX_HEIGHT}
     * @param z         eye position Z, metres, |z| &lt;= {@link Waypoint#MAX_COORDINATE}
     * @param yaw       heading, radians, within +-{@link #MAX_YAW_DEGREES} degrees
     * @param pitch     radians, within +-{@link #MAX_PITCH_DEGREES} degrees
     * @param fovY      vertical field of view, radians, in [{@link #MIN_FOV_DEGREES}, {@link #MAX_FOV_DEGREES}] degrees
     * @param near      near clip distance, metres, in [{@link #MIN_NEAR}, {@link #MAX_NEAR}]
     * @param far       far clip distance, metres, &gt; near and &lt;= {@link #MAX_FAR}
     * @param path      waypoints, not null (copied)
     * @param pathSpeed walking speed along the path, m/s, in [{@link #MIN_PATH_SPEED}, {@link #MAX_PATH_SPEED}]
     * @param pathLoop  whether the path starts again at its end
     * @throws IllegalArgumentException when a value is not finite, out of the range given above,
     *                                  {@code far <= near}, {@code pathSpeed <= 0} or {@code path} is null
     */
    public CameraDef {
        Require.range("x", x, -Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE);
        Require.range("y", y, -Waypoint.MAX_HEIGHT, Waypoint.MAX_HEIGHT);
        Require.range("z", z, -Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE);
        Require.degrees("yaw", yaw, -MAX_YAW_DEGREES, MAX_YAW_DEGREES);
        Require.degrees("pitch", pitch, -MAX_PITCH_DEGREES, MAX_PITCH_DEGREES);
        Require.degrees("fovY", fovY, MIN_FOV_DEGREES, MAX_FOV_DEGREES);
        Require.range("near", near, MIN_NEAR, MAX_NEAR);
        Require.above("far", far, 0, MAX_FAR);
        if (far <= near) {
            throw new IllegalArgumentException("far must be > near, got far=" + far + " near=" + near);
        }
        path = List.copyOf(Require.nonNull("path", path));
        Require.range("pathSpeed", pathSpeed, MIN_PATH_SPEED, MAX_PATH_SPEED);
    }

    /** Largest |yaw|, degrees (scene schema and API; the API takes radians). */
    public static final double MAX_YAW_DEGREES = 360;
    /** Largest |pitch|, degrees. */
    public static final double MAX_PITCH_DEGREES = 90;
    /** Narrowest vertical field of view, degrees. */
    public static final double MIN_FOV_DEGREES = 1;
    /** Widest vertical field of view, degrees. */
    public static final double MAX_FOV_DEGREES = 179;
    /** Smallest near clip distance, metres (a smaller one leaves no depth precision). */
    public static final double MIN_NEAR = 1e-3;
    /** Largest near clip distance, metres. */
    public static final double MAX_NEAR = 10_000;
    /** Largest far clip distance, metres. */
    public static final double MAX_FAR = 1e7;
    /**
     * Slowest walk along a path, m/s, for cameras and flows alike (slower would make one lap last
     * longer than any simulation).
     */
    public static final double MIN_PATH_SPEED = 1e-3;
    /** Fastest walk along a path, m/s, for cameras and flows alike. */
    public static final double MAX_PATH_SPEED = 10_000;

    /**
     * Defaults: 1.7 m above the origin, looking along -Z, 60 degree field of view, 0.1-500 m.
     *
     * @return the default pose and lens, no path (walking speed 1.4 m/s, looping)
     */
    public static CameraDef defaults() {
        return new CameraDef(0, 1.7, 0, 0, 0, Math.toRadians(60), 0.1, 500, List.of(), 1.4, true);
    }
}
