package org.jecosys.field;

/**
 * The wind gradient of one effective node of {@link QuadtreeForceField} (1/s), from its edge
 * neighbours alone (no flow evaluation): least squares through the node's own wind over the
 * neighbours' centres of gravity, weighed by how well it predicts them. Leaving each neighbour out
 * in turn, the gradient fitted to the others predicts that neighbour's wind; with E the summed
 * distance of those predictions to the neighbours' winds and E0 the summed distance of the node's own
 * wind to them, the gradient keeps {@code max(0, 1 - (E / E0)^2)} of itself: all of it for a wind
 * linear in space, none where a straight line predicts the neighbours no better than the node's own
 * value (or with one neighbour). It is also scaled down where it would change the wind inside the
 * node by more than twice the largest difference to a neighbour. One owner thread; no allocation.
 */
final class NodeGradient {
    /** Most neighbours: one per edge. */
    private static final int MAX = 4;
    private final double[] dx = new double[MAX];
    private final double[] dz = new double[MAX];
    private final double[] du = new double[MAX];
    private final double[] dv = new double[MAX];
    private int count;
    private double fitXX;
    private double fitXZ;
    private double fitZX;
    private double fitZZ;
    /** The result of the last {@link #solve}: d(wind X)/dx, d(wind X)/dz, d(wind Z)/dx, d(wind Z)/dz, 1/s. */
    double xx;
    double xz;
    double zx;
    double zz;

    /** Starts a node: no neighbour. */
    void clear() {
        count = 0;
    }

    /**
     * Adds a neighbour: the offset of its centre of gravity from the node's (metres) and the
     * difference of its wind from the node's (m/s).
     */
    void add(double offsetX, double offsetZ, double windX, double windZ) {
        dx[count] = offsetX;
        dz[count] = offsetZ;
        du[count] = windX;
        dv[count] = windZ;
        count++;
    }

    /**
     * Fits, weighs and caps the gradient (see the class comment) into {@link #xx} .. {@link #zz}.
     *
     * @param halfX the farthest a point of the node lies from its centre of gravity along X, metres
     * @param halfZ likewise along Z
     * @return false when there is no neighbour to fit (the result is then not written)
     */
    boolean solve(double halfX, double halfZ) {
        int k = count;
        if (!fit(k, -1)) {
            return false;
        }
        double gxx = fitXX;
        double gxz = fitXZ;
        double gzx = fitZX;
        double gzz = fitZZ;
        double maxDiff2 = 0;
        double with = 0;
        double without = 0;
        for (int i = 0; i < k; i++) {
            double pu = 0;
            double pv = 0;
            if (fit(k, i)) {
                pu = fitXX * dx[i] + fitXZ * dz[i];
                pv = fitZX * dx[i] + fitZZ * dz[i];
            }
            double eu = du[i] - pu;
            double ev = dv[i] - pv;
            with += Math.sqrt(eu * eu + ev * ev);
            without += Math.sqrt(du[i] * du[i] + dv[i] * dv[i]);
            maxDiff2 = Math.max(maxDiff2, du[i] * du[i] + dv[i] * dv[i]);
        }
        double r = without > 0 ? with / without : 1;
        double trust = Math.max(0, 1 - r * r);
        // the largest change inside the node is at a corner; keep it within twice the largest difference
        double cu = Math.abs(gxx) * halfX + Math.abs(gxz) * halfZ;
        double cv = Math.abs(gzx) * halfX + Math.abs(gzz) * halfZ;
        double most = Math.sqrt(cu * cu + cv * cv);
        double cap = 2 * Math.sqrt(maxDiff2);
        double scale = trust * (most > cap ? cap / most : 1);
        xx = gxx * scale;
        xz = gxz * scale;
        zx = gzx * scale;
        zz = gzz * scale;
        return true;
    }

    /**
     * Least squares through the node's own wind: the gradient G minimising {@code |G d_i - (du_i, dv_i)|^2}
     * over neighbours {@code 0 .. k-1} but {@code skip} (-1: none), with a small ridge (1e-3 of the
     * offsets' spread) that keeps it defined when the offsets are collinear, into fitXX .. fitZZ.
     * False when no neighbour is left.
     */
    private boolean fit(int k, int skip) {
        double sxx = 0;
        double sxz = 0;
        double szz = 0;
        double bxx = 0;
        double bxz = 0;
        double bzx = 0;
        double bzz = 0;
        for (int i = 0; i < k; i++) {
            if (i == skip) {
                continue;
            }
            sxx += dx[i] * dx[i];
            sxz += dx[i] * dz[i];
            szz += dz[i] * dz[i];
            bxx += dx[i] * du[i];
            bxz += dz[i] * du[i];
            bzx += dx[i] * dv[i];
            bzz += dz[i] * dv[i];
        }
        double lambda = 1e-3 * (sxx + szz);
        double a = sxx + lambda;
        double d = szz + lambda;
        double det = a * d - sxz * sxz;
        if (!(det > 0)) {
            return false;
        }
        fitXX = (d * bxx - sxz * bxz) / det;
        fitXZ = (a * bxz - sxz * bxx) / det;
        fitZX = (d * bzx - sxz * bzz) / det;
        fitZZ = (a * bzz - sxz * bzx) / det;
        return true;
    }
}
