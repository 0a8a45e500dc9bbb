package org.jecosys.world;

import java.util.Arrays;
import org.jecosys.math.Rng;

/**
 * The candidates one {@link TilePlacer#place} call gathers from a tile and its halo, and their
 * competition: sorted by rank, accepted when their footprint disc overlaps no accepted one (a spatial
 * hash grid over the gathered region). One thread at a time; grows its arrays as needed and keeps
 * them for the next tile ({@link #clear}), so a placer reusing it allocates nothing here once its
 * arrays fit the largest region; package-private.
 */
final class Candidates {
    /** Salt of a candidate's rank hash, so that the rank is not the variant seed itself. */
    private static final long RANK_SALT = 0x5DEECE66DL * 0x9E3779B97F4A7C15L;

    int n;
    double[] x = new double[1024];
    double[] z = new double[1024];
    float[] azimuth = new float[1024];
    long[] seed = new long[1024];
    int[] dist = new int[1024];
    /** The candidate's global identity after its rank: generating tile and index in its stream. */
    int[] tileI = new int[1024];
    int[] tileJ = new int[1024];
    int[] index = new int[1024];
    /** The competition's scratch, grown as needed: sort keys, order, grid heads and links, accepted. */
    private long[] key = new long[0];
    private int[] order = new int[0];
    private int[] head = new int[0];
    private int[] next = new int[0];
    /** The accepted candidates of the last {@link #compete}, in order of acceptance. */
    int[] accepted = new int[0];

    /** Forgets the candidates, keeping the arrays. */
    void clear() {
        n = 0;
    }

    void add(double px, double pz, float az, long s, int d, int ti, int tj, int k) {
        if (n == x.length) {
            int c = n * 2;
            x = Arrays.copyOf(x, c);
            z = Arrays.copyOf(z, c);
            azimuth = Arrays.copyOf(azimuth, c);
            seed = Arrays.copyOf(seed, c);
            dist = Arrays.copyOf(dist, c);
            tileI = Arrays.copyOf(tileI, c);
            tileJ = Arrays.copyOf(tileJ, c);
            index = Arrays.copyOf(index, c);
        }
        x[n] = px;
        z[n] = pz;
        azimuth[n] = az;
        seed[n] = s;
        dist[n] = d;
        tileI[n] = ti;
        tileJ[n] = tj;
        index[n] = k;
        n++;
    }

    /**
     * A candidate's rank: a hash of its variant seed, the same in every tile that gathers it. Lower
     * ranks compete first.
     */
    static long rank(long variantSeed) {
        return Rng.mix(variantSeed ^ RANK_SALT);
    }

    /**
     * The candidates' indices in competition order: by rank (unsigned), ties (all but impossible) by
     * generating tile, distribution and index in the stream, so the order of any two candidates is the
     * same whatever the tile being placed. The first n entries of the returned array (the scratch,
     * grown when needed).
     */
    private int[] order() {
        int bits = Math.max(1, 32 - Integer.numberOfLeadingZeros(Math.max(1, n - 1)));
        if (key.length < n) {
            key = new long[n];
            order = new int[n];
        }
        for (int c = 0; c < n; c++) {
            key[c] = ((rank(seed[c]) >>> (bits + 1)) << bits) | c;
        }
        Arrays.sort(key, 0, n);
        long mask = (1L << bits) - 1;
        for (int c = 0; c < n; c++) {
            order[c] = (int) (key[c] & mask);
        }
        // runs equal in the truncated rank: order them by the full rank and the global identity
        int from = 0;
        for (int c = 1; c <= n; c++) {
            if (c == n || (key[c] >>> bits) != (key[from] >>> bits)) {
                if (c - from > 1) {
                    insertionSort(order, from, c);
                }
                from = c;
            }
        }
        return order;
    }

    private void insertionSort(int[] order, int from, int to) {
        for (int a = from + 1; a < to; a++) {
            int v = order[a];
            int b = a - 1;
            while (b >= from && before(v, order[b])) {
                order[b + 1] = order[b];
                b--;
            }
            order[b + 1] = v;
        }
    }

    private boolean before(int a, int b) {
        int c = Long.compareUnsigned(rank(seed[a]), rank(seed[b]));
        if (c == 0) {
            c = Integer.compare(tileI[a], tileI[b]);
        }
        if (c == 0) {
            c = Integer.compare(tileJ[a], tileJ[b]);
        }
        if (c == 0) {
            c = Integer.compare(dist[a], dist[b]);
        }
        if (c == 0) {
            c = Integer.compare(index[a], index[b]);
        }
        return c < 0;
    }

    /**
     * The competition (paper §4.3, without resources): in {@link #order}, a candidate is accepted
     * when its footprint disc overlaps no accepted plant's (centres closer than the sum of the radii).
     * The grid's cells are at least {@code 2 maxRadius} wide, so only the 3 x 3 cells around a
     * candidate can hold a disc it overlaps. Grows its scratch when needed.
     *
     * @param radius    footprint radius per distribution, metres
     * @param maxRadius the largest of them, metres
     * @param minX      the region's lowest X, metres (every candidate lies in the region)
     * @param minZ      the region's lowest Z, metres
     * @param sizeX     the region's extent along X, metres
     * @param sizeZ     the region's extent along Z, metres
     * @return how many were accepted: their indices are the first entries of {@link #accepted}, in order
     *         of acceptance
     */
    int compete(double[] radius, double maxRadius, double minX, double minZ, double sizeX, double sizeZ) {
        int[] order = order();
        double cell = Math.max(2 * maxRadius, Math.sqrt(sizeX * sizeZ / Math.max(1, n)));
        int gx = Math.max(1, (int) Math.ceil(sizeX / cell));
        int gz = Math.max(1, (int) Math.ceil(sizeZ / cell));
        if (head.length < gx * gz) {
            head = new int[gx * gz];
        }
        Arrays.fill(head, 0, gx * gz, -1);
        if (next.length < n) {
            next = new int[n];
            accepted = new int[n];
        }
        int na = 0;
        for (int o = 0; o < n; o++) {
            int c = order[o];
            double cx = x[c];
            double cz = z[c];
            double r = radius[dist[c]];
            int ci = Math.min(gx - 1, Math.max(0, (int) ((cx - minX) / cell)));
            int cj = Math.min(gz - 1, Math.max(0, (int) ((cz - minZ) / cell)));
            boolean free = true;
            for (int j = Math.max(0, cj - 1); free && j <= Math.min(gz - 1, cj + 1); j++) {
                for (int i = Math.max(0, ci - 1); free && i <= Math.min(gx - 1, ci + 1); i++) {
                    for (int a = head[j * gx + i]; a >= 0; a = next[a]) {
                        double dx = x[a] - cx;
                        double dz = z[a] - cz;
                        double rr = r + radius[dist[a]];
                        if (dx * dx + dz * dz < rr * rr) {
                            free = false;
                            break;
                        }
                    }
                }
            }
            if (free) {
                int h = cj * gx + ci;
                next[c] = head[h];
                head[h] = c;
                accepted[na++] = c;
            }
        }
        return na;
    }
}
