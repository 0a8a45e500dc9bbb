package org.jecosys.terrain;

import java.util.Arrays;

/**
 * Ground taken by plants: footprint discs in a uniform bucket grid, so "ground taken by one species
 * is no longer available to another" (paper §4.3) is a cheap neighbourhood query. Two discs clash
 * when their centres are closer than the sum of their radii. One thread; grows as plants are added.
 */
final class OccupancyGrid {
    /** Most buckets per side. */
    static final int MAX_BUCKETS_PER_SIDE = 2048;

    private final double minX;
    private final double minZ;
    private final int nx;
    private final int nz;
    private final double bucketX;
    private final double bucketZ;
    private final double maxRadius;
    private final int[] head;
    private int[] next = new int[64];
    private float[] px = new float[64];
    private float[] pz = new float[64];
    private float[] pr = new float[64];
    private int n;

    OccupancyGrid(double minX, double minZ, double sizeX, double sizeZ, double maxRadius) {
        this.minX = minX;
        this.minZ = minZ;
        this.maxRadius = maxRadius;
        double want = 2 * maxRadius;
        this.nx = (int) Math.max(1, Math.min(MAX_BUCKETS_PER_SIDE, Math.floor(sizeX / want)));
        this.nz = (int) Math.max(1, Math.min(MAX_BUCKETS_PER_SIDE, Math.floor(sizeZ / want)));
        this.bucketX = sizeX / nx;
        this.bucketZ = sizeZ / nz;
        this.head = new int[nx * nz];
        Arrays.fill(head, -1);
    }

    /** Whether a disc of radius r at (x, z) clashes with no disc already added. */
    boolean free(double x, double z, double r) {
        double reach = r + maxRadius;
        int i0 = bucket(x - reach, minX, bucketX, nx);
        int i1 = bucket(x + reach, minX, bucketX, nx);
        int j0 = bucket(z - reach, minZ, bucketZ, nz);
        int j1 = bucket(z + reach, minZ, bucketZ, nz);
        for (int j = j0; j <= j1; j++) {
            for (int i = i0; i <= i1; i++) {
                for (int p = head[j * nx + i]; p >= 0; p = next[p]) {
                    double dx = px[p] - x;
                    double dz = pz[p] - z;
                    double s = pr[p] + r;
                    if (dx * dx + dz * dz < s * s) {
                        return false;
                    }
                }
            }
        }
        return true;
    }

    /** Adds a disc of radius r (at most the maxRadius given at construction) at (x, z). */
    void add(double x, double z, double r) {
        if (n == next.length) {
            int cap = 2 * n;
            next = Arrays.copyOf(next, cap);
            px = Arrays.copyOf(px, cap);
            pz = Arrays.copyOf(pz, cap);
            pr = Arrays.copyOf(pr, cap);
        }
        px[n] = (float) x;
        pz[n] = (float) z;
        pr[n] = (float) r;
        int b = bucket(z, minZ, bucketZ, nz) * nx + bucket(x, minX, bucketX, nx);
        next[n] = head[b];
        head[b] = n;
        n++;
    }

    private static int bucket(double c, double min, double size, int count) {
        int i = (int) Math.floor((c - min) / size);
        return i < 0 ? 0 : (i >= count ? count - 1 : i);
    }
}
