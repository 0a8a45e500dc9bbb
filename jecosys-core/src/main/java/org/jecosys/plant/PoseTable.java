package org.jecosys.plant;

import java.nio.FloatBuffer;
import org.jecosys.math.Require;
import org.joml.Vector3f;

/**
 * The pre-computed poses of one component type and shape variant (paper §4.1: "the resultant
 * models are then precomputed in several different angles"; §4.2: animating is choosing a pose).
 *
 * <h2>Poses</h2>
 * Pose {@code k} of {@code K} bends the gravity rest shape ({@link GravityBend}) further in its
 * bending plane by {@code beta_k = maxBend k / (K - 1)}, spread like a uniform curvature whose tip
 * tangent turns by {@code beta_k}: segment {@code i} turns by {@code beta_k (i + 1) / segments},
 * then every angle is clamped to [-pi/2, pi/2]. Pose 0 is the rest shape. Consequences (tested):
 * segment lengths are those of the rest shape in every pose; every point has {@code y >= 0} in the
 * local frame; the tip's displacement along +X never decreases with {@code k}; no point moves more
 * than {@code length * maxBend / (K - 1)} between neighbouring poses.
 *
 * <h2>Layout</h2>
 * One flat float array, pose-major then point-major, {@link #STRIDE} floats per point:
 * {@code px, py, pz} the skeleton point in the component's local frame (metres; base at the origin,
 * Y up, bending toward +X), {@code sx, sy, sz} the side vector scaled by half the width there,
 * {@code nx, ny, nz} the face normal (tangent x side) scaled by half the width. A ribbon vertex is
 * {@code p + a s + b n} with the coefficients of {@link ComponentMesh}. Row of (pose, point):
 * {@code (pose * points + point) * STRIDE}. Ready for a texture buffer or SSBO upload.
 *
 * <p>Immutable after construction; any thread; accessors do not allocate.
 */
public final class PoseTable {
    /** Floats per point in a pose: position, half-width side vector, half-width normal vector. */
    public static final int STRIDE = 9;

    private final int poses;
    private final int segments;
    private final int points;
    private final double segLength;
    private final double maxBend;
    private final float[] data;

    private PoseTable(int poses, int segments, double segLength, double maxBend, float[] data) {
        this.poses = poses;
        this.segments = segments;
        this.points = segments + 1;
        this.segLength = segLength;
        this.maxBend = maxBend;
        this.data = data;
    }

    /**
     * Builds the table from a gravity-bent rest shape. Build time only; allocates the table.
     *
     * @param restAngles segment angles of the rest shape (from {@link GravityBend#solve}), radians
     * @param segments   segment count, in [1, 32]
     * @param length     total length, metres, &gt; 0
     * @param baseWidth  width at the base, metres, &gt;= 0
     * @param tipWidth   width at the tip, metres, &gt;= 0
     * @param twist      twist of the side vector around the skeleton over the length, radians
     * @param poses      pose count K, in [2, 64]
     * @param maxBend    extra bend of the last pose, radians, in (0, pi/2]
     * @return the table of {@code poses * (segments + 1)} points
     * @throws IllegalArgumentException when an argument is out of range
     */
    public static PoseTable build(double[] restAngles, int segments, double length, double baseWidth,
                                  double tipWidth, double twist, int poses, double maxBend) {
        Require.range("segments", segments, 1, 32);
        Require.nonNull("restAngles", restAngles);
        Require.range("restAngles.length", restAngles.length, segments, Integer.MAX_VALUE);
        Require.positive("length", length);
        Require.nonNegative("baseWidth", baseWidth);
        Require.nonNegative("tipWidth", tipWidth);
        Require.finite("twist", twist);
        Require.range("poses", poses, 2, 64);
        Require.range("maxBend", maxBend, 1e-6, Math.PI / 2);
        int pts = segments + 1;
        double l = length / segments;
        float[] data = new float[poses * pts * STRIDE];
        double[] angles = new double[segments];
        double[] xy = new double[2 * pts];
        for (int k = 0; k < poses; k++) {
            double beta = maxBend * k / (poses - 1);
            for (int i = 0; i < segments; i++) {
                angles[i] = Skeleton.clampAngle(restAngles[i] + beta * (i + 1) / segments);
            }
            Skeleton.points(angles, segments, l, xy);
            for (int p = 0; p < pts; p++) {
                double phi = Skeleton.tangentAngle(angles, segments, p);
                double tx = Math.sin(phi);
                double ty = Math.cos(phi);
                double psi = twist * p / segments;
                double half = 0.5 * Skeleton.width(baseWidth, tipWidth, p, segments);
                // side: +Z turned by the twist toward the in-plane normal (cos phi, -sin phi, 0)
                double sx = Math.sin(psi) * ty;
                double sy = -Math.sin(psi) * tx;
                double sz = Math.cos(psi);
                // normal = tangent x side
                double nx = ty * sz;
                double ny = -tx * sz;
                double nz = tx * sy - ty * sx;
                int o = (k * pts + p) * STRIDE;
                data[o] = (float) xy[2 * p];
                data[o + 1] = (float) Math.max(0.0, xy[2 * p + 1]);
                data[o + 2] = 0f;
                data[o + 3] = (float) (half * sx);
                data[o + 4] = (float) (half * sy);
                data[o + 5] = (float) (half * sz);
                data[o + 6] = (float) (half * nx);
                data[o + 7] = (float) (half * ny);
                data[o + 8] = (float) (half * nz);
            }
        }
        return new PoseTable(poses, segments, l, maxBend, data);
    }

    /** {@return the pose count K, in [2, 64]} */
    public int poses() {
        return poses;
    }

    /** {@return the number of skeleton segments, in [1, 32]} */
    public int segments() {
        return segments;
    }

    /** {@return the skeleton points per pose: {@code segments + 1}} */
    public int points() {
        return points;
    }

    /** {@return the length of every segment, metres} */
    public double segmentLength() {
        return segLength;
    }

    /** {@return the total skeleton length, metres} */
    public double length() {
        return segLength * segments;
    }

    /** {@return the extra bend of the last pose, radians} */
    public double maxBend() {
        return maxBend;
    }

    /** {@return the number of floats in the table: {@code poses * points * STRIDE}} */
    public int floatCount() {
        return data.length;
    }

    /**
     * {@return the index of the first float of (pose, point) in the flat table}
     *
     * @param pose  pose index, in [0, poses)
     * @param point point index, in [0, points)
     */
    public int offset(int pose, int point) {
        return (pose * points + point) * STRIDE;
    }

    /**
     * {@return one float of the flat table} No allocation.
     *
     * @param index in [0, floatCount())
     */
    public float get(int index) {
        return data[index];
    }

    /**
     * Writes the skeleton point (metres, local frame) of (pose, point) into {@code dest}. No allocation.
     *
     * @param pose  pose index, in [0, poses)
     * @param point point index, in [0, points)
     * @param dest  where to write
     * @return {@code dest}
     */
    public Vector3f position(int pose, int point, Vector3f dest) {
        int o = offset(pose, point);
        return dest.set(data[o], data[o + 1], data[o + 2]);
    }

    /**
     * Writes the half-width side vector (metres) of (pose, point) into {@code dest}. No allocation.
     *
     * @param pose  pose index, in [0, poses)
     * @param point point index, in [0, points)
     * @param dest  where to write
     * @return {@code dest}
     */
    public Vector3f side(int pose, int point, Vector3f dest) {
        int o = offset(pose, point) + 3;
        return dest.set(data[o], data[o + 1], data[o + 2]);
    }

    /**
     * Writes the half-width normal vector (metres) of (pose, point) into {@code dest}. No allocation.
     *
     * @param pose  pose index, in [0, poses)
     * @param point point index, in [0, points)
     * @param dest  where to write
     * @return {@code dest}
     */
    public Vector3f normal(int pose, int point, Vector3f dest) {
        int o = offset(pose, point) + 6;
        return dest.set(data[o], data[o + 1], data[o + 2]);
    }

    /**
     * Writes the skeleton point at a continuous pose coordinate (from
     * {@link PoseMapping#poseCoordinate}) blended linearly between poses {@code floor(c)} and the
     * next, into {@code dest}; returns it. Per-frame safe: no allocation.
     *
     * @param poseCoordinate in [0, poses - 1]; clamped
     * @param point          point index, in [0, points)
     * @param dest           where to write
     * @return {@code dest}
     */
    public Vector3f blendedPosition(double poseCoordinate, int point, Vector3f dest) {
        double c = Math.max(0, Math.min(poses - 1, poseCoordinate));
        int k = Math.min((int) c, poses - 2);
        float w = (float) (c - k);
        int a = offset(k, point);
        int b = offset(k + 1, point);
        return dest.set(data[a] + w * (data[b] - data[a]),
                data[a + 1] + w * (data[b + 1] - data[a + 1]),
                data[a + 2] + w * (data[b + 2] - data[a + 2]));
    }

    /**
     * Copies the whole table into {@code dest} from {@code destOffset}. No allocation.
     *
     * @param dest       receives {@link #floatCount()} floats
     * @param destOffset first index written
     */
    public void copyTo(float[] dest, int destOffset) {
        System.arraycopy(data, 0, dest, destOffset, data.length);
    }

    /**
     * Puts the whole table into {@code dest} at its position (relative put). No allocation.
     *
     * @param dest a buffer with at least {@link #floatCount()} floats remaining; its position advances
     */
    public void writeTo(FloatBuffer dest) {
        dest.put(data);
    }
}
