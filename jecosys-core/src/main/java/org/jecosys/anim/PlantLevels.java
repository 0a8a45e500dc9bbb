package org.jecosys.anim;

import org.jecosys.math.Require;
import org.jecosys.math.ViewLod;

/**
 * Where each plant stands and the level of detail it was last animated at (paper §4.1, Table 3): its
 * species' distance bands ({@link LodBands}) against its distance to the views, measured by projected
 * size ({@link ViewLod}). Sized at construction; the updates allocate nothing. A caller updates only
 * its own plants, so disjoint plant ranges may be updated at once.
 */
final class PlantLevels {
    /** Per species its level bands, with the LOD bias. */
    final LodBands bands;
    private final int[] species;
    private final float[] x;
    private final float[] y;
    private final float[] z;
    private final byte[] level;

    /**
     * Build time; allocates and copies the arrays.
     *
     * @param lodEdges per species, the ascending distances (metres) where its levels end
     * @param species  per plant its species index into lodEdges
     * @param x        per plant X, metres (likewise y: base height, z)
     * @throws IllegalArgumentException when a species index is out of range or the lengths differ
     */
    PlantLevels(double[][] lodEdges, int[] species, float[] x, float[] y, float[] z) {
        int plants = species.length;
        if (x.length != plants || y.length != plants || z.length != plants) {
            throw new IllegalArgumentException("plantX/Y/Z must hold plants = " + plants + " values");
        }
        bands = new LodBands(lodEdges);
        for (int p = 0; p < plants; p++) {
            Require.elementRange("plantSpecies", p, species[p], 0, bands.species() - 1);
        }
        this.species = species.clone();
        this.x = x.clone();
        this.y = y.clone();
        this.z = z.clone();
        level = new byte[plants];
    }

    /**
     * Recomputes plant p's level for one view at the eye (metres), its distance measured by the view's
     * projected size (scale2 and fixed2, {@link ViewLod}); stores and returns it.
     */
    int update(int p, double eyeX, double eyeY, double eyeZ, double scale2, double fixed2) {
        double dx = x[p] - eyeX;
        double dy = y[p] - eyeY;
        double dz = z[p] - eyeZ;
        return store(p, ViewLod.equivalent2(dx * dx + dy * dy + dz * dz, scale2, fixed2));
    }

    /**
     * Whether every plant whose base lies in the box at {@code box[o]} (min X, Y, Z, max X, Y, Z,
     * metres) takes, for its species, one level for the view at the eye: the box's nearest and
     * farthest squared distances, widened by a margin far above their roundings, fall in one band
     * (levels are monotonic in distance). Then writes each species' level into {@code table}. No
     * allocation.
     */
    boolean uniform(float[] box, int o, double eyeX, double eyeY, double eyeZ, double scale2, double fixed2,
                    byte[] table) {
        if (!(box[o] <= box[o + 3])) {
            return false; // no plant
        }
        double near2 = org.jecosys.math.Boxes.near2(box, o, eyeX, eyeY, eyeZ);
        double far2 = org.jecosys.math.Boxes.far2(box, o, eyeX, eyeY, eyeZ);
        double q2near = ViewLod.equivalent2(near2 * (1 - MARGIN), scale2, fixed2);
        double q2far = ViewLod.equivalent2(far2 * (1 + MARGIN), scale2, fixed2);
        for (int s = 0; s < table.length; s++) {
            int l = bands.level(s, q2near);
            if (l != bands.level(s, q2far)) {
                return false;
            }
            table[s] = (byte) l;
        }
        return true;
    }

    /** Relative margin on a box's squared distances ({@link #uniform}). */
    private static final double MARGIN = 1e-9;

    /** The number of species. */
    int species() {
        return bands.species();
    }

    /** Sets plant p's level to its species' entry of {@code table} ({@link #uniform}); returns it. */
    int assign(int p, byte[] table) {
        int l = table[species[p]];
        level[p] = (byte) l;
        return l;
    }

    /** Recomputes plant p's level for the step's views: the finest any view asks; stores and returns it. */
    int update(int p, AnimationStep step) {
        double nearest = Double.POSITIVE_INFINITY;
        for (int v = 0; v < step.views; v++) {
            double dx = x[p] - step.viewX[v];
            double dy = y[p] - step.viewY[v];
            double dz = z[p] - step.viewZ[v];
            nearest = Math.min(nearest, ViewLod.equivalent2(dx * dx + dy * dy + dz * dz, step.viewScale2[v],
                    step.viewFixed2[v]));
        }
        return store(p, nearest);
    }

    private int store(int p, double d2) {
        int l = bands.level(species[p], d2);
        level[p] = (byte) l;
        return l;
    }

    /** The level plant p was last updated to. */
    int level(int p) {
        return level[p];
    }

    /** Copies the levels of plants {@code first .. end-1} into dest (same indices). */
    void copy(int first, int end, byte[] dest) {
        System.arraycopy(level, first, dest, first, end - first);
    }
}
