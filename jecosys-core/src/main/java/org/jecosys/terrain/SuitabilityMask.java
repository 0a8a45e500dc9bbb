package org.jecosys.terrain;

/**
 * Where one distribution could grow, on a grid of mask cells over the terrain (paper §4.3, "verifies
 * if the terrain has the proper conditions of development for each plant distribution"), evaluated
 * at each mask cell's centre:
 * <ul>
 * <li><b>possible</b>: slope and altitude hold, and water and nutrients are at least the species'
 * minimum. Resources only fall, so a point that is not possible now never will be: candidates are
 * drawn only from possible cells;</li>
 * <li><b>suitable</b>: possible, and water and nutrients are also at most the maximum. Its area is
 * what a density multiplies, and a distribution with no suitable cell "matches nowhere".</li>
 * </ul>
 * Built once per distribution; immutable afterwards; package-private.
 */
final class SuitabilityMask {
    final int res;
    final double cellX;
    final double cellZ;
    /** Indices (j * res + i) of the possible cells, ascending. */
    final int[] possible;
    /** Number of suitable cells. */
    final int suitable;

    private SuitabilityMask(int res, double cellX, double cellZ, int[] possible, int suitable) {
        this.res = res;
        this.cellX = cellX;
        this.cellZ = cellZ;
        this.possible = possible;
        this.suitable = suitable;
    }

    /** Suitable area, square metres. */
    double suitableArea() {
        return suitable * cellX * cellZ;
    }

    /**
     * Evaluates d over a res x res mask, rows split over {@code workers} (results do not depend on
     * the thread count: each row writes its own flags).
     */
    static SuitabilityMask build(DistributionDef d, Heightfield hf, ResourceMap water, ResourceMap nutrients,
                                 int res, Workers workers) {
        double sx = hf.sizeX();
        double sz = hf.sizeZ();
        double cx = sx / res;
        double cz = sz / res;
        byte[] flags = new byte[res * res];
        workers.run(res, j -> {
            double z = -sz / 2 + (j + 0.5) * cz;
            for (int i = 0; i < res; i++) {
                double x = -sx / 2 + (i + 0.5) * cx;
                double h = hf.height(x, z);
                if (h < d.minAltitude() || h > d.maxAltitude() || hf.slope(x, z) > d.maxSlope()) {
                    continue;
                }
                double w = water.sample(x, z);
                double n = nutrients.sample(x, z);
                if (w < d.minWater() || n < d.minNutrients()) {
                    continue;
                }
                flags[j * res + i] = (byte) (w <= d.maxWater() && n <= d.maxNutrients() ? 2 : 1);
            }
        });
        int count = 0;
        int suitable = 0;
        for (byte f : flags) {
            if (f != 0) {
                count++;
            }
            if (f == 2) {
                suitable++;
            }
        }
        int[] possible = new int[count];
        int k = 0;
        for (int c = 0; c < flags.length; c++) {
            if (flags[c] != 0) {
                possible[k++] = c;
            }
        }
        return new SuitabilityMask(res, cx, cz, possible, suitable);
    }
}
