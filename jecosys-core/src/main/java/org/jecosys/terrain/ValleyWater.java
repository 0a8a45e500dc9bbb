package org.jecosys.terrain;

import java.util.Arrays;

/**
 * Water that gathers in low ground and along valleys (the VALLEYS resource source, paper §4.3
 * "irrigation"). On a grid of cell centres sampled from the heightfield:
 * <ol>
 * <li>low ground: {@code 1 - (h - hmin) / (hmax - hmin)};</li>
 * <li>flow accumulation, multiple-flow-direction: every cell starts with one unit of rain and, from
 * the highest cell down, hands its total to its lower 8-neighbours in proportion to the drop per
 * metre; pits keep theirs. The accumulation is taken as {@code ln(acc) / ln(maxAcc)} and blurred
 * once (3 x 3) so streams are a few cells wide;</li>
 * <li>water = {@link #LOW_GROUND_WEIGHT} x low ground + the rest x accumulation, stretched to
 * [0, 1]. A flat terrain is wet everywhere (1).</li>
 * </ol>
 * Deterministic (ties in height are ordered by cell index). Package-private; allocates its scratch.
 */
final class ValleyWater {
    /** Share of the "low ground" term; the flow-accumulation term gets the rest. */
    static final double LOW_GROUND_WEIGHT = 0.5;

    private ValleyWater() {
    }

    /** Fills {@code out} (length res * res, index j * res + i) with levels in [0, 1]. */
    static void compute(Heightfield hf, int res, double[] out) {
        int n = res * res;
        double sx = hf.sizeX();
        double sz = hf.sizeZ();
        double cx = sx / res;
        double cz = sz / res;
        double[] h = new double[n];
        for (int j = 0; j < res; j++) {
            for (int i = 0; i < res; i++) {
                h[j * res + i] = hf.height(-sx / 2 + (i + 0.5) * cx, -sz / 2 + (j + 0.5) * cz);
            }
        }
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (double v : h) {
            lo = Math.min(lo, v);
            hi = Math.max(hi, v);
        }
        if (!(hi - lo > 1e-9)) {
            Arrays.fill(out, 0, n, 1.0);
            return;
        }
        // order cells from highest to lowest; ties by index
        long[] keys = new long[n];
        for (int k = 0; k < n; k++) {
            int bits = Float.floatToIntBits((float) h[k]);
            bits ^= (bits >> 31) & 0x7FFFFFFF;
            keys[k] = ((long) bits << 32) | (0xFFFFFFFFL & (n - 1 - k));
        }
        Arrays.sort(keys);
        double[] acc = new double[n];
        Arrays.fill(acc, 1.0);
        double diag = Math.sqrt(cx * cx + cz * cz);
        double[] w = new double[8];
        for (int s = n - 1; s >= 0; s--) {
            int k = n - 1 - (int) (keys[s] & 0xFFFFFFFFL);
            int i = k % res;
            int j = k / res;
            double total = 0;
            for (int d = 0; d < 8; d++) {
                int di = dx(d);
                int dj = dz(d);
                int ni = i + di;
                int nj = j + dj;
                w[d] = 0;
                if (ni < 0 || nj < 0 || ni >= res || nj >= res) {
                    continue;
                }
                double drop = h[k] - h[nj * res + ni];
                if (drop > 0) {
                    double dist = di != 0 && dj != 0 ? diag : (di != 0 ? cx : cz);
                    w[d] = drop / dist;
                    total += w[d];
                }
            }
            if (total > 0) {
                for (int d = 0; d < 8; d++) {
                    if (w[d] > 0) {
                        acc[(j + dz(d)) * res + i + dx(d)] += acc[k] * w[d] / total;
                    }
                }
            }
        }
        double maxAcc = 1;
        for (double a : acc) {
            maxAcc = Math.max(maxAcc, a);
        }
        double logMax = Math.log(maxAcc);
        double[] flow = new double[n];
        for (int k = 0; k < n; k++) {
            flow[k] = logMax > 0 ? Math.log(acc[k]) / logMax : 0;
        }
        for (int j = 0; j < res; j++) {
            for (int i = 0; i < res; i++) {
                double sum = 0;
                int cnt = 0;
                for (int dj = -1; dj <= 1; dj++) {
                    for (int di = -1; di <= 1; di++) {
                        int ni = i + di;
                        int nj = j + dj;
                        if (ni >= 0 && nj >= 0 && ni < res && nj < res) {
                            sum += flow[nj * res + ni];
                            cnt++;
                        }
                    }
                }
                int k = j * res + i;
                double low = 1 - (h[k] - lo) / (hi - lo);
                out[k] = LOW_GROUND_WEIGHT * low + (1 - LOW_GROUND_WEIGHT) * sum / cnt;
            }
        }
        ResourceMap.stretch(out);
    }

    /** X offset of neighbour d in [0, 8) (the 3 x 3 block without its centre). */
    private static int dx(int d) {
        return (d < 4 ? d : d + 1) % 3 - 1;
    }

    /** Z offset of neighbour d in [0, 8). */
    private static int dz(int d) {
        return (d < 4 ? d : d + 1) / 3 - 1;
    }
}
