package org.jecosys.sim;

import java.util.Arrays;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.joml.Vector3f;

/**
 * Measures of how natural a built world's plants are, for tests: the Clark–Evans aggregation ratio of
 * one species in square windows and each plant's height at rest.
 *
 * <h2>Clark–Evans ratio</h2>
 * {@code R = mean nearest-neighbour distance / (0.5 / sqrt(density))}: 1 for a random (Poisson)
 * pattern, below 1 for a clumped one, above 1 for a more even one (Clark and Evans 1954). The terrain
 * is cut into square windows of {@code window} metres; a window's density is its own plant count over
 * its area, so the patchiness of the species' habitat at scales above the window does not count.
 * <b>Edges:</b> a plant's nearest neighbour is searched among <em>all</em> plants of its species,
 * inside the window or outside it (the neighbours beyond a window's edge act as Clark and Evans's
 * guard area, so no edge correction is needed there); only windows at least one window away from the
 * terrain's edge are used, where the terrain's own edge would lengthen the distances. <b>Pooling:</b>
 * over the windows with at least {@link #MIN_PLANTS} plants, R is the sum of the observed distances
 * over the sum of the expected ones ({@code n_w 0.5 / sqrt(n_w / A)} per window), i.e. the windows'
 * ratios weighted by their plant counts: a window with ten plants at the rim of a habitat weighs less
 * than one in its middle, where the pattern is the species' own, and the estimate is not the noisy
 * median of small windows. Pure; allocates.
 *
 * <h2>Height</h2>
 * A plant's height is its highest skeleton point at rest (pose 0 of every slot's pose table, attached
 * components placed on their parent's rest tip in their upright frame, as the renderer draws them),
 * metres above its base: the plant's actual built height, whatever component is tallest.
 */
final class MeadowPattern {
    /** Fewest plants of a window that counts. */
    static final int MIN_PLANTS = 10;

    private MeadowPattern() {
    }

    /** Clark–Evans result: pooled ratio, median of window ratios, windows and plants used. */
    record ClarkEvans(double pooled, double median, int windows, int plants) {
    }

    static ClarkEvans clarkEvans(World w, int species, double window) {
        int n = 0;
        for (int p = 0; p < w.plantCount(); p++) {
            if (w.plantSpecies(p) == species) {
                n++;
            }
        }
        float[] x = new float[n];
        float[] z = new float[n];
        for (int p = 0, i = 0; p < w.plantCount(); p++) {
            if (w.plantSpecies(p) == species) {
                x[i] = w.plantX(p);
                z[i++] = w.plantZ(p);
            }
        }
        return clarkEvans(x, z, w, window);
    }

    /**
     * Tussocks: the plants of the given species joined into one where two stand within {@code join}
     * metres of each other (transitively), each group at the mean of its plants' positions; {x, z}.
     */
    static float[][] tussocks(World w, java.util.Set<Integer> species, double join) {
        int n = w.plantCount();
        float[] x = new float[n];
        float[] z = new float[n];
        int m = 0;
        for (int p = 0; p < n; p++) {
            if (species.contains(w.plantSpecies(p))) {
                x[m] = w.plantX(p);
                z[m++] = w.plantZ(p);
            }
        }
        double[][] g = org.jecosys.terrain.PointGroups.join(x, z, m, join);
        float[][] out = new float[2][g[0].length];
        for (int k = 0; k < g[0].length; k++) {
            out[0][k] = (float) g[0][k];
            out[1][k] = (float) g[1][k];
        }
        return out;
    }

    /** The Clark–Evans ratio of the points (x, z) over w's terrain in square windows (see the class comment). */
    static ClarkEvans clarkEvans(float[] x, float[] z, World w, double window) {
        int n = x.length;
        var hf = w.terrain().heightfield();
        double minX = hf.minX();
        double minZ = hf.minZ();
        // bucket grid for the nearest-neighbour search
        double cell = 0.5;
        int gx = (int) Math.ceil(hf.sizeX() / cell) + 1;
        int gz = (int) Math.ceil(hf.sizeZ() / cell) + 1;
        int[] head = new int[gx * gz];
        int[] next = new int[n];
        Arrays.fill(head, -1);
        for (int i = 0; i < n; i++) {
            int b = bucket(x[i], minX, cell, gx) + gx * bucket(z[i], minZ, cell, gz);
            next[i] = head[b];
            head[b] = i;
        }
        int wx = (int) Math.floor(hf.sizeX() / window);
        int wz = (int) Math.floor(hf.sizeZ() / window);
        double[] sum = new double[wx * wz];
        int[] count = new int[wx * wz];
        for (int i = 0; i < n; i++) {
            int a = (int) Math.floor((x[i] - minX) / window);
            int b = (int) Math.floor((z[i] - minZ) / window);
            if (a < 1 || b < 1 || a >= wx - 1 || b >= wz - 1) {
                continue;
            }
            sum[b * wx + a] += nearest(i, x, z, head, next, minX, minZ, cell, gx, gz);
            count[b * wx + a]++;
        }
        double observed = 0;
        double expected = 0;
        double[] ratios = new double[wx * wz];
        int used = 0;
        int plants = 0;
        double area = window * window;
        for (int k = 0; k < sum.length; k++) {
            if (count[k] >= MIN_PLANTS) {
                double e = count[k] * 0.5 / Math.sqrt(count[k] / area);
                observed += sum[k];
                expected += e;
                ratios[used++] = sum[k] / e;
                plants += count[k];
            }
        }
        double[] r = Arrays.copyOf(ratios, used);
        Arrays.sort(r);
        double median = used == 0 ? Double.NaN : (used % 2 == 1 ? r[used / 2] : 0.5 * (r[used / 2 - 1] + r[used / 2]));
        return new ClarkEvans(used == 0 ? Double.NaN : observed / expected, median, used, plants);
    }

    private static double nearest(int i, float[] x, float[] z, int[] head, int[] next, double minX, double minZ,
                                  double cell, int gx, int gz) {
        int bi = bucket(x[i], minX, cell, gx);
        int bj = bucket(z[i], minZ, cell, gz);
        double best = Double.POSITIVE_INFINITY;
        for (int ring = 0; ; ring++) {
            // every point in ring r lies at least (r - 1) cells away
            if (ring > 0 && best <= (ring - 1) * cell) {
                return best;
            }
            if (ring > Math.max(gx, gz)) {
                return best;
            }
            for (int j = bj - ring; j <= bj + ring; j++) {
                for (int a = bi - ring; a <= bi + ring; a++) {
                    if (j < 0 || a < 0 || j >= gz || a >= gx
                            || (Math.abs(j - bj) != ring && Math.abs(a - bi) != ring)) {
                        continue;
                    }
                    for (int q = head[j * gx + a]; q >= 0; q = next[q]) {
                        if (q != i) {
                            best = Math.min(best, Math.hypot(x[q] - x[i], z[q] - z[i]));
                        }
                    }
                }
            }
        }
    }

    private static int bucket(double c, double min, double cell, int count) {
        int i = (int) Math.floor((c - min) / cell);
        return i < 0 ? 0 : Math.min(count - 1, i);
    }

    /** Per plant of {@code species}, in world order, its height at rest, metres (see the class comment). */
    static double[] heights(World w, int species) {
        SpeciesModel m = w.plants().species().get(species);
        int n = 0;
        for (int p = 0; p < w.plantCount(); p++) {
            if (w.plantSpecies(p) == species) {
                n++;
            }
        }
        double[] out = new double[n];
        Vector3f v = new Vector3f();
        for (int p = 0, i = 0; p < w.plantCount(); p++) {
            if (w.plantSpecies(p) != species) {
                continue;
            }
            double top = 0;
            for (int s = 0; s < m.slotCount(); s++) {
                PoseTable t = m.slotPoseTable(s, w.plantVariant(p));
                double base = m.slotParent(s) < 0 ? 0
                        : pointHeight(m, m.slotParent(s), m.slotAttachPoint(s), w.plantVariant(p), v);
                for (int k = 0; k < t.points(); k++) {
                    top = Math.max(top, base + t.position(0, k, v).y);
                }
            }
            out[i++] = top;
        }
        return out;
    }

    /** Height of a slot's highest rest point above the plant's base, metres (its carriers' points added). */
    static double slotTop(SpeciesModel m, int slot, int variant) {
        Vector3f v = new Vector3f();
        PoseTable t = m.slotPoseTable(slot, variant);
        double base = m.slotParent(slot) < 0 ? 0
                : pointHeight(m, m.slotParent(slot), m.slotAttachPoint(slot), variant, v);
        double top = 0;
        for (int k = 0; k < t.points(); k++) {
            top = Math.max(top, base + t.position(0, k, v).y);
        }
        return top;
    }

    /** Height of a slot's rest point {@code k} above the plant's base, metres: its parents' points below it added. */
    private static double pointHeight(SpeciesModel m, int slot, int k, int variant, Vector3f v) {
        double y = m.slotPoseTable(slot, variant).position(0, k, v).y;
        return m.slotParent(slot) < 0 ? y
                : y + pointHeight(m, m.slotParent(slot), m.slotAttachPoint(slot), variant, v);
    }

    /** {mean, standard deviation} of values. */
    static double[] meanSd(double[] values) {
        double mean = 0;
        for (double h : values) {
            mean += h;
        }
        mean /= values.length;
        double var = 0;
        for (double h : values) {
            var += (h - mean) * (h - mean);
        }
        return new double[] {mean, Math.sqrt(var / values.length)};
    }
}
