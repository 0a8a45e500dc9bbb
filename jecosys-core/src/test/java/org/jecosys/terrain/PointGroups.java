package org.jecosys.terrain;

import java.util.Arrays;

/**
 * Points joined into groups, for tests of layouts: two points closer than a distance belong to the
 * same group, transitively (single linkage). Used for the bunches of a tuft and for the meadow's
 * visible tussocks. Pure; allocates.
 */
public final class PointGroups {
    private PointGroups() {
    }

    /**
     * The groups of the first n points (x, z) where two points closer than {@code join} metres are one
     * group: {x, z, size} per group, at the mean of its points, in the order of each group's first
     * point. A bucket grid of cells {@code join} wide over the points' bounds keeps it near linear.
     *
     * @param x    X of the points, metres
     * @param z    Z of the points, metres
     * @param n    how many of them, at most the arrays' length
     * @param join joining distance, metres, &gt; 0
     * @return three arrays of the group count: mean X, mean Z, points
     */
    public static double[][] join(float[] x, float[] z, int n, double join) {
        double minX = Double.POSITIVE_INFINITY;
        double minZ = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double maxZ = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            minX = Math.min(minX, x[i]);
            maxX = Math.max(maxX, x[i]);
            minZ = Math.min(minZ, z[i]);
            maxZ = Math.max(maxZ, z[i]);
        }
        int gx = n == 0 ? 1 : (int) Math.ceil((maxX - minX) / join) + 1;
        int gz = n == 0 ? 1 : (int) Math.ceil((maxZ - minZ) / join) + 1;
        int[] head = new int[gx * gz];
        int[] next = new int[n];
        int[] id = new int[n];
        Arrays.fill(head, -1);
        for (int i = 0; i < n; i++) {
            id[i] = i;
            int b = cell(x[i], minX, join, gx) + gx * cell(z[i], minZ, join, gz);
            next[i] = head[b];
            head[b] = i;
        }
        for (int i = 0; i < n; i++) {
            int bi = cell(x[i], minX, join, gx);
            int bj = cell(z[i], minZ, join, gz);
            for (int j = Math.max(0, bj - 1); j <= Math.min(gz - 1, bj + 1); j++) {
                for (int a = Math.max(0, bi - 1); a <= Math.min(gx - 1, bi + 1); a++) {
                    for (int q = head[j * gx + a]; q >= 0; q = next[q]) {
                        if (q > i && Math.hypot(x[q] - x[i], z[q] - z[i]) < join) {
                            int ri = root(id, i);
                            int rq = root(id, q);
                            id[Math.max(ri, rq)] = Math.min(ri, rq);
                        }
                    }
                }
            }
        }
        double[] sx = new double[n];
        double[] sz = new double[n];
        int[] c = new int[n];
        int groups = 0;
        for (int i = 0; i < n; i++) {
            int r = root(id, i);
            groups += c[r] == 0 ? 1 : 0;
            sx[r] += x[i];
            sz[r] += z[i];
            c[r]++;
        }
        double[][] out = new double[3][groups];
        for (int i = 0, g = 0; i < n; i++) {
            if (c[i] > 0) {
                out[0][g] = sx[i] / c[i];
                out[1][g] = sz[i] / c[i];
                out[2][g++] = c[i];
            }
        }
        return out;
    }

    private static int root(int[] id, int i) {
        while (id[i] != i) {
            id[i] = id[id[i]];
            i = id[i];
        }
        return i;
    }

    private static int cell(double c, double min, double size, int count) {
        int i = (int) Math.floor((c - min) / size);
        return i < 0 ? 0 : Math.min(count - 1, i);
    }
}
