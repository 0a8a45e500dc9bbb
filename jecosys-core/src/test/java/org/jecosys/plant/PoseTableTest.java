package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.Rng;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

class PoseTableTest {
    /** Float storage of metre-scale coordinates. */
    private static final double LENGTH_TOL = 1e-5;

    private static PoseTable table(ComponentType type, int segs, double length, double base, double tip,
                                   double tilt, double curvature, double twist, double mass, double tipMass,
                                   double gravity, int poses, double maxBend) {
        double[] a = new double[segs];
        GravityBend.solve(type, segs, length, base, tip, tilt, curvature, mass, tipMass, gravity, a);
        return PoseTable.build(a, segs, length, base, tip, twist, poses, maxBend);
    }

    private static double dist(PoseTable t, int pose, int p, int q) {
        Vector3f a = t.position(pose, p, new Vector3f());
        Vector3f b = t.position(pose, q, new Vector3f());
        return a.distance(b);
    }

    /** Checks every documented pose-table property of one table. */
    private static void checkInvariants(PoseTable t, String what) {
        double seg = t.segmentLength();
        double step = t.length() * t.maxBend() / (t.poses() - 1);
        double prevTipX = Double.NEGATIVE_INFINITY;
        Vector3f p = new Vector3f();
        Vector3f q = new Vector3f();
        for (int k = 0; k < t.poses(); k++) {
            t.position(k, 0, p);
            assertEquals(0f, p.length(), 0f, what + ": base at origin");
            for (int i = 0; i < t.points(); i++) {
                t.position(k, i, p);
                assertTrue(p.y >= 0f, what + ": pose " + k + " point " + i + " below ground: " + p.y);
                if (i > 0) {
                    assertEquals(seg, dist(t, k, i - 1, i), LENGTH_TOL * Math.max(1, seg), what + ": segment length");
                }
                if (k > 0) {
                    t.position(k - 1, i, q);
                    assertTrue(p.distance(q) <= step * (1 + 1e-4) + 1e-6, what + ": neighbouring poses close");
                }
            }
            double tipX = t.position(k, t.points() - 1, p).x;
            assertTrue(tipX >= prevTipX - 1e-6, what + ": tip deflection monotonic at pose " + k);
            prevTipX = tipX;
        }
    }

    @Test
    void poseZeroIsTheRestShape() {
        double[] a = new double[6];
        GravityBend.solve(ComponentType.LEAF, 6, 0.4, 0.006, 0.002, 0.3, 0.3, 8e-4, 0, 9.81, a);
        PoseTable t = PoseTable.build(a, 6, 0.4, 0.006, 0.002, 0.2, 16, 1.2);
        double[] xy = new double[14];
        Skeleton.points(a, 6, 0.4 / 6, xy);
        Vector3f p = new Vector3f();
        for (int i = 0; i <= 6; i++) {
            t.position(0, i, p);
            assertEquals(xy[2 * i], p.x, 1e-6);
            assertEquals(xy[2 * i + 1], p.y, 1e-6);
            assertEquals(0, p.z, 0);
        }
    }

    @Test
    void noGravityPoseZeroIsStraight() {
        PoseTable t = table(ComponentType.LEAF, 5, 0.5, 0.01, 0.002, 0, 0, 0.3, 1e-3, 0, 0.0, 16, 1.0);
        Vector3f p = new Vector3f();
        for (int i = 0; i < t.points(); i++) {
            t.position(0, i, p);
            assertEquals(0, p.x, 1e-7);
            assertEquals(0.1 * i, p.y, 1e-6);
        }
    }

    @Test
    void libraryLikeTableKeepsInvariantsAndTipDeflectionGrowsStrictly() {
        PoseTable t = table(ComponentType.LEAF, 5, 0.45, 0.006, 0.0015, 0.35, 0.3, 0.4, 8e-4, 0, 9.81, 16, 1.2);
        checkInvariants(t, "grass");
        Vector3f tip0 = t.position(0, 5, new Vector3f());
        Vector3f tip = new Vector3f();
        double prev = -1;
        for (int k = 1; k < t.poses(); k++) {
            double d = t.position(k, 5, tip).distance(tip0);
            assertTrue(d > prev, "tip displacement strictly grows at pose " + k);
            prev = d;
        }
    }

    @Test
    void sweepOfDocumentedRangesNeverGoesBelowGround() {
        Rng rng = new Rng(42);
        ComponentType[] types = ComponentType.values();
        for (int trial = 0; trial < 400; trial++) {
            int segs = 1 + rng.nextInt(32);
            double length = rng.nextDouble(1e-3, 10);
            double base = rng.nextDouble(1e-6, 1);
            double tip = rng.nextDouble() < 0.3 ? 0 : rng.nextDouble(0, 1);
            double tilt = rng.nextDouble(0, Math.PI / 2);
            double curv = rng.nextDouble(-Math.PI, Math.PI);
            double twist = rng.nextDouble(-2 * Math.PI, 2 * Math.PI);
            double mass = Math.exp(rng.nextDouble(Math.log(1e-9), Math.log(10)));
            double tipMass = rng.nextDouble() < 0.5 ? 0 : rng.nextDouble(0, 10);
            int poses = 2 + rng.nextInt(63);
            double maxBend = rng.nextDouble(1e-3, Math.PI / 2);
            PoseTable t = table(types[rng.nextInt(types.length)], segs, length, base, tip, tilt, curv, twist,
                    mass, tipMass, 9.81, poses, maxBend);
            checkInvariants(t, "trial " + trial);
        }
    }

    @Test
    void sideVectorsHaveHalfWidthAndAreOrthogonalToTheSkeleton() {
        PoseTable t = table(ComponentType.PETAL, 4, 0.04, 0.01, 0.02, 0.5, 0.3, 1.0, 3e-4, 0, 9.81, 8, 1.0);
        Vector3f s = new Vector3f();
        Vector3f n = new Vector3f();
        Vector3f a = new Vector3f();
        Vector3f b = new Vector3f();
        for (int k = 0; k < t.poses(); k++) {
            for (int i = 0; i < t.points(); i++) {
                double half = 0.5 * Skeleton.width(0.01, 0.02, i, 4);
                assertEquals(half, t.side(k, i, s).length(), 1e-6);
                assertEquals(half, t.normal(k, i, n).length(), 1e-6);
                assertEquals(0, s.dot(n), 1e-9);
                if (i < t.points() - 1) {
                    t.position(k, i + 1, b).sub(t.position(k, i, a)).normalize();
                    assertEquals(0, b.dot(s) / half, 0.2, "side roughly across the skeleton");
                }
            }
        }
    }

    @Test
    void blendedPositionInterpolatesBetweenPoses() {
        PoseTable t = table(ComponentType.LEAF, 5, 0.45, 0.006, 0.0015, 0.35, 0.3, 0.4, 8e-4, 0, 9.81, 16, 1.2);
        Vector3f a = t.position(3, 5, new Vector3f());
        Vector3f b = t.position(4, 5, new Vector3f());
        Vector3f m = t.blendedPosition(3.5, 5, new Vector3f());
        assertEquals(0.5 * (a.x + b.x), m.x, 1e-6);
        assertEquals(0.5 * (a.y + b.y), m.y, 1e-6);
        assertEquals(t.position(15, 5, new Vector3f()).x, t.blendedPosition(99, 5, new Vector3f()).x, 0);
        float[] flat = new float[t.floatCount() + 3];
        t.copyTo(flat, 3);
        assertEquals(t.get(t.offset(4, 5)), flat[3 + t.offset(4, 5)], 0);
    }
}
