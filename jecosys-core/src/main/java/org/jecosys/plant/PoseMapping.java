package org.jecosys.plant;

/**
 * Maps a component's deviation (from the animation layer, paper §4.2) to a continuous coordinate in
 * its pose table (§4.1). The bend angle of a deviation {@code |D|} (metres, in the ground plane, of a
 * component of skeleton length {@code L}) is {@code asin(min(1, |D| / L))}: the component keeps its
 * length, so its tip moves by {@code L sin(angle)}; it maps linearly onto
 * [0, maxBend] → [0, K - 1] and saturates at the last pose. The integer part is the pose index
 * {@code k}, the fraction the blend weight toward {@code k + 1}; the renderer rotates the blended
 * pose about Y by the deviation's azimuth.
 *
 * <p>Pure static functions; any thread; no allocation (per-frame safe).
 */
public final class PoseMapping {
    private PoseMapping() {
    }

    /**
     * Bend angle of a deviation, the length kept: {@code asin(min(1, |deviation| / length))}.
     *
     * @param deviation deviation magnitude, metres (its absolute value is used)
     * @param length    component skeleton length, metres, &gt; 0
     * @return radians, in [0, pi/2]; 0 for a NaN deviation
     */
    public static double bendAngle(double deviation, double length) {
        double s = Math.abs(deviation) / length;
        return s > 0 ? Math.asin(Math.min(1, s)) : 0;
    }

    /**
     * Continuous pose coordinate in [0, poses - 1].
     *
     * @param deviation signed or unsigned deviation magnitude, metres (its absolute value is used)
     * @param length    component skeleton length, metres, &gt; 0
     * @param maxBend   bend of the last pose, radians, &gt; 0
     * @param poses     pose count K, &gt;= 2
     * @return {@code min(1, asin(min(1, |D|/L)) / maxBend) (K - 1)}; 0 for a NaN deviation
     */
    public static double poseCoordinate(double deviation, double length, double maxBend, int poses) {
        double t = bendAngle(deviation, length) / maxBend;
        if (!(t > 0)) {
            return 0;
        }
        return Math.min(1.0, t) * (poses - 1);
    }

    /**
     * Lower pose index of a coordinate: {@code floor(c)} clamped to [0, poses - 2].
     *
     * @param poseCoordinate a value of {@link #poseCoordinate}
     * @param poses          pose count K, &gt;= 2
     * @return the pose blended from, in [0, poses - 2]
     */
    public static int poseIndex(double poseCoordinate, int poses) {
        int k = (int) Math.floor(poseCoordinate);
        return Math.max(0, Math.min(poses - 2, k));
    }

    /**
     * Blend weight toward pose {@code poseIndex + 1}.
     *
     * @param poseCoordinate a value of {@link #poseCoordinate}
     * @param poses          pose count K, &gt;= 2
     * @return weight in [0, 1]; 1 at the last pose
     */
    public static double blendWeight(double poseCoordinate, int poses) {
        double w = poseCoordinate - poseIndex(poseCoordinate, poses);
        return Math.max(0, Math.min(1, w));
    }
}
