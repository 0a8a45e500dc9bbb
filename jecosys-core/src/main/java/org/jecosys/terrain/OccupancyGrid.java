package org.jecosys.terrain;

import java.util.Arrays;

/**
 * Ground taken by plants: footprint discs in bucket grids, so "ground taken by one species is no
 * longer available to another" (paper §4.3) is a cheap neighbourhood query. Two discs clash when
 * their centres are closer than the sum of their radii.
 *
 * <h2>Footprint classes</h2>
 * The discs are kept in one uniform bucket grid per <em>footprint class</em>: radii whose float value
 * has the same binary exponent ({@link Math#getExponent(float)}, radii in [2<sup>e</sup>,
 * 2<sup>e+1</sup>)). A class's buckets are twice the largest radius declared for it, so one large
 * footprint never makes the buckets of small plants large: with one grid sized by the largest
 * footprint of any distribution, a 100 m footprint (even with count 0) put every plant in one bucket
 * and placement turned quadratic. A query for a disc of radius r visits, in each class that holds
 * discs, the buckets within r + the class's largest radius. That finds exactly the discs that clash,
 * whatever the classes (a disc's bucket is taken from its stored float centre, and bucket indices are
 * monotone in the coordinate), so the answer of {@link #free} is the one a single grid gives.
 *
 * <h2>Cost</h2>
 * Placed discs do not overlap (hand placements aside), and within a class radii differ by less than a
 * factor of two, so a bucket of side 2m holds at most a constant number of a class's discs and a query
 * of radius r &le; m looks at no more than 3 &times; 3 buckets of each class. A query of a large radius
 * among small discs looks at the buckets its disc spans, at most all of that class's buckets; a class
 * has at most {@link #BUCKETS_PER_DISC} buckets per disc it is declared to hold (and at most
 * {@link #MAX_BUCKETS_PER_SIDE} per side), so that is bounded by the class's disc count.
 * {@link PlacementWork} turns these bounds into the work estimate the scene check budgets. Memory: 16
 * bytes per disc, and per class that holds discs at most 4 bytes x {@link #BUCKETS_PER_DISC} per disc
 * it may hold and at most 16 MiB ({@link #MAX_BUCKETS_PER_SIDE} squared).
 *
 * <p>One thread. Allocates a class's buckets at its first disc, and its disc arrays as they grow
 * (doubling); no allocation in {@link #free}.
 */
final class OccupancyGrid {
    /** Most buckets per side of a class's grid. */
    static final int MAX_BUCKETS_PER_SIDE = 2048;
    /** Most buckets of a class's grid per disc it is declared to hold (at least one bucket). */
    static final int BUCKETS_PER_DISC = 64;

    private final double minX;
    private final double minZ;
    /** Per class (ascending exponent): the exponent, largest and smallest declared radius, metres. */
    private final int[] exponent;
    private final double[] classMax;
    private final int[] nx;
    private final int[] nz;
    private final double[] bucketX;
    private final double[] bucketZ;
    /** Per class: first disc of each bucket, -1 for none; null until the class's first disc. */
    private final int[][] head;
    private int[] next = new int[64];
    private float[] px = new float[64];
    private float[] pz = new float[64];
    private float[] pr = new float[64];
    private int n;
    private long visits;

    /**
     * A grid over the terrain rectangle [minX, minX + sizeX] x [minZ, minZ + sizeZ] for discs of the
     * given radii. Build time; allocates the per-class bookkeeping (buckets come with the first disc).
     *
     * @param minX  terrain's smallest X, metres
     * @param minZ  terrain's smallest Z, metres
     * @param sizeX terrain extent along X, metres, &gt; 0
     * @param sizeZ terrain extent along Z, metres, &gt; 0
     * @param radii every radius {@link #add} will be given, metres, &gt; 0 (repeats allowed)
     * @param discs per radius, the most discs of that radius that will be added (sizes the buckets;
     *              adding more is still correct, only slower)
     */
    OccupancyGrid(double minX, double minZ, double sizeX, double sizeZ, double[] radii, long[] discs) {
        if (radii.length != discs.length || radii.length == 0) {
            throw new IllegalArgumentException("radii and discs must have the same, non-zero length, got "
                    + radii.length + " and " + discs.length);
        }
        this.minX = minX;
        this.minZ = minZ;
        int[] exps = classes(radii);
        int k = exps.length;
        this.exponent = exps;
        this.classMax = new double[k];
        this.nx = new int[k];
        this.nz = new int[k];
        this.bucketX = new double[k];
        this.bucketZ = new double[k];
        this.head = new int[k][];
        long[] expected = new long[k];
        for (int i = 0; i < radii.length; i++) {
            int c = Arrays.binarySearch(exps, Math.getExponent((float) radii[i]));
            classMax[c] = Math.max(classMax[c], (float) radii[i]);
            expected[c] = saturatedAdd(expected[c], Math.max(0, discs[i]));
        }
        for (int c = 0; c < k; c++) {
            int[] b = buckets(sizeX, sizeZ, classMax[c], expected[c]);
            nx[c] = b[0];
            nz[c] = b[1];
            bucketX[c] = sizeX / nx[c];
            bucketZ[c] = sizeZ / nz[c];
        }
    }

    /** {@return the distinct footprint classes (binary exponents of the float radii) of radii, ascending} */
    static int[] classes(double[] radii) {
        int[] e = new int[radii.length];
        for (int i = 0; i < radii.length; i++) {
            if (!(radii[i] > 0) || !Double.isFinite(radii[i])) {
                throw new IllegalArgumentException("radii[" + i + "] must be a finite radius > 0 metres, got "
                        + radii[i]);
            }
            e[i] = Math.getExponent((float) radii[i]);
        }
        return Arrays.stream(e).sorted().distinct().toArray();
    }

    /**
     * Buckets per side of a class's grid: side about twice the class's largest radius, at most
     * {@link #MAX_BUCKETS_PER_SIDE} per side and {@link #BUCKETS_PER_DISC} per expected disc in all.
     *
     * @return {buckets along X, buckets along Z}, each at least 1
     */
    static int[] buckets(double sizeX, double sizeZ, double classMax, long expected) {
        double want = 2 * classMax;
        double bx = Math.max(1, Math.min(MAX_BUCKETS_PER_SIDE, Math.floor(sizeX / want)));
        double bz = Math.max(1, Math.min(MAX_BUCKETS_PER_SIDE, Math.floor(sizeZ / want)));
        double most = Math.max(1, (double) BUCKETS_PER_DISC * expected);
        if (bx * bz > most) {
            double f = Math.sqrt(most / (bx * bz));
            bx = Math.max(1, Math.floor(bx * f));
            bz = Math.max(1, Math.floor(bz * f));
        }
        return new int[] {(int) bx, (int) bz};
    }

    /**
     * Whether a disc of radius r at (x, z) clashes with no disc already added. Counts the buckets and
     * discs it looks at into {@link #visits()}. No allocation.
     */
    boolean free(double x, double z, double r) {
        long v = 0;
        for (int c = 0; c < head.length; c++) {
            int[] h = head[c];
            if (h == null) {
                continue;
            }
            double reach = r + classMax[c];
            int w = nx[c];
            int i0 = bucket(x - reach, minX, bucketX[c], w);
            int i1 = bucket(x + reach, minX, bucketX[c], w);
            int j0 = bucket(z - reach, minZ, bucketZ[c], nz[c]);
            int j1 = bucket(z + reach, minZ, bucketZ[c], nz[c]);
            for (int j = j0; j <= j1; j++) {
                for (int i = i0; i <= i1; i++) {
                    v++;
                    for (int p = h[j * w + i]; p >= 0; p = next[p]) {
                        v++;
                        double dx = px[p] - x;
                        double dz = pz[p] - z;
                        double s = pr[p] + r;
                        if (dx * dx + dz * dz < s * s) {
                            visits += v;
                            return false;
                        }
                    }
                }
            }
        }
        visits += v;
        return true;
    }

    /**
     * Adds a disc of radius r at (x, z); r must be one of the radii given at construction (or at most
     * the largest of its class). Allocates only when a class gets its first disc or the arrays grow.
     *
     * @throws IllegalArgumentException when r belongs to no declared class or exceeds its largest radius
     */
    void add(double x, double z, double r) {
        float fr = (float) r;
        int c = Arrays.binarySearch(exponent, Math.getExponent(fr));
        if (c < 0 || fr > classMax[c]) {
            throw new IllegalArgumentException("radius " + r + " m was not declared to this occupancy grid");
        }
        if (n == next.length) {
            int cap = 2 * n;
            next = Arrays.copyOf(next, cap);
            px = Arrays.copyOf(px, cap);
            pz = Arrays.copyOf(pz, cap);
            pr = Arrays.copyOf(pr, cap);
        }
        if (head[c] == null) {
            head[c] = new int[nx[c] * nz[c]];
            Arrays.fill(head[c], -1);
        }
        float fx = (float) x;
        float fz = (float) z;
        px[n] = fx;
        pz[n] = fz;
        pr[n] = fr;
        // the bucket of the stored centre: what free() compares is what decides the bucket
        int b = bucket(fz, minZ, bucketZ[c], nz[c]) * nx[c] + bucket(fx, minX, bucketX[c], nx[c]);
        next[n] = head[c][b];
        head[c][b] = n;
        n++;
    }

    /** {@return the buckets and discs {@link #free} has looked at so far (the search's work)} */
    long visits() {
        return visits;
    }

    /** {@return the number of footprint classes} */
    int classCount() {
        return exponent.length;
    }

    /** {@return the buckets of class c's grid, allocated or not} */
    int bucketCount(int c) {
        return nx[c] * nz[c];
    }

    private static int bucket(double c, double min, double size, int count) {
        int i = (int) Math.floor((c - min) / size);
        return i < 0 ? 0 : (i >= count ? count - 1 : i);
    }

    private static long saturatedAdd(long a, long b) {
        long s = a + b;
        return s < 0 ? Long.MAX_VALUE : s;
    }
}
