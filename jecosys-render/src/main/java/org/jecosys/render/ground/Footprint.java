package org.jecosys.render.ground;

import java.util.Arrays;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.joml.Vector3f;

/**
 * A plant's footprint: the outline of everything it has, seen from straight above at rest, as the
 * convex hull of its components' rest-pose points projected on the ground, in the plant's frame (rest
 * azimuth 0, base at the origin). Stored as the distance from the base to the hull's edge in
 * {@value #DIRECTIONS} directions evenly spaced in the "diamond angle" (a cheap monotonic stand-in for the
 * angle: no trigonometry per texel), at least {@value #MIN_REACH} m (a stem's own foot). Immutable;
 * any thread.
 *
 * @param reaches  distance to the hull's edge per diamond-angle step, metres
 * @param area     the hull's area, square metres
 * @param radius   the radius of a disc of that area, metres
 * @param maxReach the largest of the reaches, metres
 * @param minReach the least of the reaches, metres: every point nearer the base lies inside
 */
record Footprint(float[] reaches, double area, double radius, double maxReach, double minReach) {
    /** Directions sampled round the base. */
    static final int DIRECTIONS = 64;
    /** Least reach, metres. */
    static final double MIN_REACH = 0.015;

    /**
     * The footprint of a plant of a species and variant. Allocates.
     *
     * @param model   the species
     * @param variant the plant's variant
     * @return the footprint
     */
    static Footprint of(SpeciesModel model, int variant) {
        return of(model, variant, 0, 0);
    }

    /**
     * The outline of a plant's shadow on flat ground: its rest-pose points each moved by its height
     * times {@code (shearX, shearZ)} (in the plant's frame) before the hull is taken, the base kept. With
     * the shear {@code -(sun's horizontal direction) / tan(sun elevation)} that is where the points'
     * shadows fall. Allocates.
     *
     * @param model   the species
     * @param variant the plant's variant
     * @param shearX  ground offset per metre of height, X in the plant's frame
     * @param shearZ  ground offset per metre of height, Z in the plant's frame
     * @return the footprint of the shadow
     */
    static Footprint of(SpeciesModel model, int variant, double shearX, double shearZ) {
        int slots = model.slotCount();
        double[][][] points = new double[slots][][];
        int count = 1;
        for (int s = 0; s < slots; s++) {
            count += model.slotPoseTable(s, variant).points();
        }
        double[] xs = new double[count];
        double[] zs = new double[count];
        int n = 1; // the base itself
        Vector3f q = new Vector3f();
        for (int s = 0; s < slots; s++) {
            PoseTable t = model.slotPoseTable(s, variant);
            int parent = model.slotParent(s);
            // a slot's children stand on its point they attach to; parents come before their children
            double[] b = parent < 0 ? new double[] {model.slotBaseX(s), 0, model.slotBaseZ(s)}
                    : points[parent][model.slotAttachPoint(s)];
            double az = model.slotAzimuth(s);
            double c = Math.cos(az);
            double sn = Math.sin(az);
            points[s] = new double[t.points()][];
            for (int k = 0; k < t.points(); k++) {
                t.position(0, k, q);
                double x = b[0] + q.x * c - q.z * sn;
                double y = b[1] + q.y;
                double z = b[2] + q.x * sn + q.z * c;
                xs[n] = x + y * shearX;
                zs[n] = z + y * shearZ;
                n++;
                points[s][k] = new double[] {x, y, z};
            }
        }
        double[][] hull = hull(xs, zs, n);
        double area = 0;
        for (int i = 0; i < hull.length; i++) {
            double[] a = hull[i];
            double[] b = hull[(i + 1) % hull.length];
            area += a[0] * b[1] - b[0] * a[1];
        }
        area = Math.abs(area) / 2;
        float[] reaches = new float[DIRECTIONS];
        double max = 0;
        double min = Double.MAX_VALUE;
        for (int k = 0; k < DIRECTIONS; k++) {
            double[] d = direction(4.0 * k / DIRECTIONS);
            double r = Math.max(MIN_REACH, rayToHull(hull, d[0], d[1]));
            reaches[k] = (float) r;
            max = Math.max(max, r);
            min = Math.min(min, reaches[k]);
        }
        double radius = Math.max(MIN_REACH, Math.sqrt(area / Math.PI));
        return new Footprint(reaches, area, radius, max, min);
    }

    /**
     * {@return the distance from the base to the footprint's edge toward a point of the plant's frame,
     * metres, linear between the sampled directions} No allocation.
     *
     * @param x X in the plant's frame
     * @param z Z in the plant's frame
     */
    double reach(double x, double z) {
        double p = diamond(x, z) * (DIRECTIONS / 4.0);
        int k = (int) p;
        double f = p - k;
        return reaches[k & (DIRECTIONS - 1)] * (1 - f) + reaches[(k + 1) & (DIRECTIONS - 1)] * f;
    }

    /** The diamond angle of (x, z), in [0, 4): 0 along +X, 1 along +Z, 2 along -X, 3 along -Z. */
    static double diamond(double x, double z) {
        if (x == 0 && z == 0) {
            return 0;
        }
        if (z >= 0) {
            return x >= 0 ? z / (x + z) : 1 - x / (-x + z);
        }
        return x < 0 ? 2 - z / (-x - z) : 3 + x / (x - z);
    }

    /** The unit direction of diamond angle p in [0, 4). */
    static double[] direction(double p) {
        double x;
        double z;
        if (p < 1) {
            x = 1 - p;
            z = p;
        } else if (p < 2) {
            x = 1 - p;
            z = 2 - p;
        } else if (p < 3) {
            x = p - 3;
            z = 2 - p;
        } else {
            x = p - 3;
            z = p - 4;
        }
        double l = Math.hypot(x, z);
        return new double[] {x / l, z / l};
    }

    /** Distance from the origin along (dx, dz) to the convex polygon's edge; 0 when the ray misses it. */
    private static double rayToHull(double[][] hull, double dx, double dz) {
        double best = 0;
        int n = hull.length;
        for (int i = 0; i < n; i++) {
            double[] a = hull[i];
            double[] b = hull[(i + 1) % n];
            double ex = b[0] - a[0];
            double ez = b[1] - a[1];
            double den = dx * ez - dz * ex;
            if (Math.abs(den) < 1e-12) {
                continue;
            }
            // origin + t d = a + s e
            double t = (a[0] * ez - a[1] * ex) / den;
            double s = (a[0] * dz - a[1] * dx) / den;
            if (t >= 0 && s >= -1e-9 && s <= 1 + 1e-9) {
                best = Math.max(best, t);
            }
        }
        return best;
    }

    /** The convex hull of the first n points, anticlockwise (Andrew's monotone chain). */
    private static double[][] hull(double[] xs, double[] zs, int n) {
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        Arrays.sort(order, (a, b) -> xs[a] != xs[b] ? Double.compare(xs[a], xs[b]) : Double.compare(zs[a], zs[b]));
        int[] h = new int[2 * n];
        int k = 0;
        for (int i = 0; i < n; i++) {
            while (k >= 2 && cross(xs, zs, h[k - 2], h[k - 1], order[i]) <= 0) {
                k--;
            }
            h[k++] = order[i];
        }
        for (int i = n - 2, lower = k + 1; i >= 0; i--) {
            while (k >= lower && cross(xs, zs, h[k - 2], h[k - 1], order[i]) <= 0) {
                k--;
            }
            h[k++] = order[i];
        }
        int m = Math.max(1, k - 1);
        double[][] out = new double[m][];
        for (int i = 0; i < m; i++) {
            out[i] = new double[] {xs[h[i]], zs[h[i]]};
        }
        return out;
    }

    private static double cross(double[] xs, double[] zs, int o, int a, int b) {
        return (xs[a] - xs[o]) * (zs[b] - zs[o]) - (zs[a] - zs[o]) * (xs[b] - xs[o]);
    }
}
