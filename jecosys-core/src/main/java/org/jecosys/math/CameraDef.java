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
     * @param x         eye position X, metres (finite)
     * @param y         eye height above the terrain, metres (finite)
     * @param z         eye position Z, metres (finite)
     * @param yaw       heading, radians (finite)
     * @param pitch     radians, in [-pi/2, pi/2]
     * @param fovY      vertical field of view, radians, in [1e-3, pi - 1e-3]
     * @param near      near clip distance, metres, &gt; 0
     * @param far       far clip distance, metres, &gt; near
     * @param path      waypoints, not null (copied)
     * @param pathSpeed walking speed along the path, m/s, &gt; 0
     * @param pathLoop  whether the path starts again at its end
     * @throws IllegalArgumentException when a value is not finite, out of the range given above,
     *                                  {@code far <= near}, {@code pathSpeed <= 0} or {@code path} is null
     */
    public CameraDef {
        Require.finite("x", x);
        Require.finite("y", y);
        Require.finite("z", z);
        Require.finite("yaw", yaw);
        Require.range("pitch", pitch, -Math.PI / 2, Math.PI / 2);
        Require.range("fovY", fovY, 1e-3, Math.PI - 1e-3);
        Require.positive("near", near);
        Require.positive("far", far);
        if (far <= near) {
            throw new IllegalArgumentException("far must be > near, got far=" + far + " near=" + near);
        }
        path = List.copyOf(Require.nonNull("path", path));
        Require.positive("pathSpeed", pathSpeed);
    }

    /**
     * Defaults: 1.7 m above the origin, looking along -Z, 60 degree field of view, 0.1-500 m.
     *
     * @return the default pose and lens, no path (walking speed 1.4 m/s, looping)
     */
    public static CameraDef defaults() {
        return new CameraDef(0, 1.7, 0, 0, 0, Math.toRadians(60), 0.1, 500, List.of(), 1.4, true);
    }
}
