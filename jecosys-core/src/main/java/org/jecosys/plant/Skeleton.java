package org.jecosys.plant;

import org.jecosys.math.Require;

/**
 * The vector skeleton of one component (paper §4.1): a chain of {@code segments} equal-length
 * segments rooted at the origin of the component's local frame. Y is up; the chain lies in the
 * local <em>bending plane</em> XY and leans (and bends) toward +X; Z is the skeleton's side
 * direction before twist. Segment {@code i} has direction angle {@code theta[i]} measured from
 * vertical (+Y) toward +X, so its direction is {@code (sin theta, cos theta, 0)}.
 *
 * <p>Angles are always clamped to [-pi/2, pi/2]: no segment points downward, so every point of
 * the chain has {@code y >= 0} (the component never goes below its base, hence never below the
 * ground when its base is on or above it). Rest shape before gravity: the base leans by
 * {@code tilt} and the rest {@code curvature} (radians over the whole length) is spread evenly,
 * {@code theta[i] = tilt + curvature (i + 0.5) / segments}.
 *
 * <p>Static, pure functions over flat arrays; any thread; no allocation.
 */
public final class Skeleton {
    /** Smallest and largest segment angle from vertical, radians: the chain never points down. */
    public static final double MAX_ANGLE = Math.PI / 2;

    private Skeleton() {
    }

    /**
     * {@code angle} clamped to [-{@link #MAX_ANGLE}, {@link #MAX_ANGLE}].
     *
     * @param angle a segment angle from vertical, radians
     * @return the clamped angle, radians
     */
    public static double clampAngle(double angle) {
        return Math.max(-MAX_ANGLE, Math.min(MAX_ANGLE, angle));
    }

    /**
     * Writes the rest angles before gravity into {@code dest[0..segments)}.
     *
     * @param segments  segment count, &gt;= 1
     * @param tilt      lean of the base from vertical, radians
     * @param curvature rest curvature over the whole length, radians
     * @param dest      receives one angle per segment, radians, clamped
     */
    public static void restAngles(int segments, double tilt, double curvature, double[] dest) {
        Require.range("segments", segments, 1, dest.length);
        for (int i = 0; i < segments; i++) {
            dest[i] = clampAngle(tilt + curvature * (i + 0.5) / segments);
        }
    }

    /**
     * Writes the chain's points into {@code destXY} as (x, y) pairs, {@code segments + 1} points,
     * point 0 at the origin.
     *
     * @param angles    segment angles, radians
     * @param segments  segment count
     * @param segLength length of each segment, metres
     * @param destXY    receives {@code 2 (segments + 1)} values, metres
     */
    public static void points(double[] angles, int segments, double segLength, double[] destXY) {
        double x = 0;
        double y = 0;
        destXY[0] = 0;
        destXY[1] = 0;
        for (int i = 0; i < segments; i++) {
            x += segLength * Math.sin(angles[i]);
            y += segLength * Math.cos(angles[i]);
            destXY[2 * i + 2] = x;
            destXY[2 * i + 3] = y;
        }
    }

    /**
     * Width of the linear width profile at point {@code point} of {@code segments + 1} points.
     *
     * @param baseWidth width at point 0, metres
     * @param tipWidth  width at the last point, metres
     * @param point     point index, in [0, segments]
     * @param segments  segment count, &gt;= 1
     * @return metres, {@code baseWidth + (tipWidth - baseWidth) point / segments}
     */
    public static double width(double baseWidth, double tipWidth, int point, int segments) {
        return baseWidth + (tipWidth - baseWidth) * point / (double) segments;
    }

    /**
     * Direction angle of the tangent at {@code point}: the first or last segment's angle at the
     * ends, the mean of the two adjacent segments' angles inside.
     *
     * @param angles   segment angles, radians
     * @param segments segment count, &gt;= 1
     * @param point    point index, in [0, segments]
     * @return the tangent's angle from vertical, radians
     */
    public static double tangentAngle(double[] angles, int segments, int point) {
        if (point == 0) {
            return angles[0];
        }
        if (point == segments) {
            return angles[segments - 1];
        }
        return 0.5 * (angles[point - 1] + angles[point]);
    }
}
