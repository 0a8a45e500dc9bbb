package org.jecosys.terrain;

import java.util.List;
import org.jecosys.math.Require;

/**
 * An upper bound of the work {@link CompetitiveDistributor} does to place a scene's plants, from the
 * scene's definitions alone (nothing is built), so that a scene check can refuse what would take too
 * long. Work is counted in <em>units</em> of about one bucket or disc looked at by the footprint
 * search (a few nanoseconds); the other steps are weighed in the same units:
 * <ul>
 * <li>per distribution, its suitability mask: {@link #MASK_CELL_UNITS} per mask cell;</li>
 * <li>its candidates, at most {@link CompetitiveDistributor#ATTEMPTS_BASE} +
 * {@link CompetitiveDistributor#ATTEMPTS_PER_PLANT} x its {@link CompetitiveDistributor#plantsAtMost}
 * (none when that is 0, as with {@code count="0"}): each costs {@link #CANDIDATE_UNITS} to draw, plus
 * {@link #CLUMP_DRAW_UNITS} per extra draw of a clumped distribution (at most
 * {@link CompetitiveDistributor#CLUMP_TRIES} per tuft centre), one unit per distribution in the
 * interleaved acceptance order, and the footprint search;</li>
 * <li>the footprint search of one candidate of radius r, in every footprint class k that can hold
 * plants (see {@link OccupancyGrid}): the buckets within r + the class's largest radius (at most the
 * class's buckets), plus the discs in them: at most the class's plants, at most the hand placements of
 * the class plus the most discs of the class's smallest radius that fit, without overlapping, in the
 * buckets' area grown by that radius (area over the disc's area), whatever the clumping;</li>
 * <li>the resource maps: {@link #OVERLAP_CELL_UNITS} per map cell a footprint's box covers, for the
 * footprint means of every candidate whose footprint is free (of every placed plant only, when the
 * distribution accepts any water and nutrient level, [0, 1] both) and for the consumption of every
 * placed plant;</li>
 * <li>hand placements: their footprint means and consumption likewise (counted with the distribution
 * whose footprint they take).</li>
 * </ul>
 * The bound ignores that a search stops at its first clash and that most candidates are accepted, so
 * real placements take a small share of it; what it does bound is the worst case: a distribution
 * whose water range is never met, or a footprint far larger than its neighbours'. Immutable; any
 * thread; {@link #estimate} allocates a few small arrays.
 */
public final class PlacementWork {
    /** Units to draw and test one candidate (random cell, point, height, slope, azimuth, seed). */
    public static final double CANDIDATE_UNITS = 32;
    /** Units of one extra draw of a clumped candidate (two random numbers and the clump noise). */
    public static final double CLUMP_DRAW_UNITS = 16;
    /** Units per suitability-mask cell of one distribution (height, slope, two map samples; measured). */
    public static final double MASK_CELL_UNITS = 100;
    /** Units per resource-map cell under a footprint's box (its overlap by midpoint strips; measured). */
    public static final double OVERLAP_CELL_UNITS = 6.0 * ResourceMap.OVERLAP_STRIPS;

    private final double total;
    private final double[] work;
    private final long[] candidates;
    private final double[] searchPerCandidate;
    private final double[] costPerCandidate;
    private final double[] mapCells;
    private final double placements;

    private PlacementWork(double total, double[] work, long[] candidates, double[] searchPerCandidate,
                          double[] costPerCandidate, double[] mapCells, double placements) {
        this.total = total;
        this.work = work;
        this.candidates = candidates;
        this.searchPerCandidate = searchPerCandidate;
        this.costPerCandidate = costPerCandidate;
        this.mapCells = mapCells;
        this.placements = placements;
    }

    /**
     * The bound for a scene's placement. Any thread; allocates a few arrays per call.
     *
     * @param terrain       the terrain (extent, heightfield and map resolutions)
     * @param distributions the distributions, in order
     * @param placements    the hand placements
     * @return the bound, per distribution and in all
     */
    public static PlacementWork estimate(TerrainDef terrain, List<DistributionDef> distributions,
                                         List<PlacementDef> placements) {
        Require.nonNull("terrain", terrain);
        Require.nonNull("distributions", distributions);
        Require.nonNull("placements", placements);
        double sx = terrain.sizeX();
        double sz = terrain.sizeZ();
        int nd = distributions.size();
        double[] radii = CompetitiveDistributor.footprints(distributions);
        long[] discs = CompetitiveDistributor.discsAtMost(sx, sz, distributions, placements);
        Classes classes = new Classes(sx, sz, radii, discs, placements, distributions);
        int waterRes = terrain.water().resolution();
        int nutrientRes = terrain.nutrients().resolution();
        int maskRes = Math.max(CompetitiveDistributor.MASK_MIN_RESOLUTION, Math.min(CompetitiveDistributor.MASK_MAX_RESOLUTION,
                Math.max(terrain.resolution() - 1, Math.max(waterRes, nutrientRes))));
        double[] work = new double[nd];
        long[] cand = new long[nd];
        double[] search = new double[nd];
        double[] cost = new double[nd];
        double[] mapCells = new double[nd];
        double total = 0;
        for (int d = 0; d < nd; d++) {
            DistributionDef def = distributions.get(d);
            long plants = CompetitiveDistributor.plantsAtMost(sx, sz, def);
            double r = def.footprint();
            long c = plants == 0 ? 0 : CompetitiveDistributor.ATTEMPTS_BASE
                    + (long) CompetitiveDistributor.ATTEMPTS_PER_PLANT * plants;
            double draw = CANDIDATE_UNITS + nd;
            if (def.clumpStrength() > 0) {
                draw += CLUMP_DRAW_UNITS * Math.ceil((double) CompetitiveDistributor.CLUMP_TRIES / def.tuftCount());
            }
            double s = classes.searchVisits(r);
            double level = cells(r, sx, sz, waterRes) + cells(r, sx, sz, nutrientRes);
            boolean anyLevel = def.minWater() <= 0 && def.maxWater() >= 1 && def.minNutrients() <= 0
                    && def.maxNutrients() >= 1;
            double means = (anyLevel ? plants : c) * level * OVERLAP_CELL_UNITS;
            double consume = plants * ((def.waterUse() > 0 ? cells(r, sx, sz, waterRes) : 0)
                    + (def.nutrientUse() > 0 ? cells(r, sx, sz, nutrientRes) : 0)) * OVERLAP_CELL_UNITS;
            cand[d] = c;
            search[d] = s;
            cost[d] = c == 0 ? 0 : draw + s + means / c;
            mapCells[d] = level;
            work[d] = (double) maskRes * maskRes * MASK_CELL_UNITS + c * (draw + s) + means + consume;
            total += work[d];
        }
        double hand = 0;
        for (int slot : CompetitiveDistributor.placementSlots(distributions, placements)) {
            double r = radii[slot];
            double u = 2 * (cells(r, sx, sz, waterRes) + cells(r, sx, sz, nutrientRes)) * OVERLAP_CELL_UNITS;
            if (slot < nd) { // it takes that distribution's footprint: counted with it
                work[slot] += u;
            } else {
                hand += u;
            }
            total += u;
        }
        return new PlacementWork(total, work, cand, search, cost, mapCells, hand);
    }

    /** {@return the whole bound, units} */
    public double total() {
        return total;
    }

    /**
     * Distribution d's share of the bound: its mask, candidates, searches, resource maps, and the hand
     * placements that take its footprint.
     *
     * @param d distribution index
     * @return units
     */
    public double work(int d) {
        return work[d];
    }

    /**
     * The most candidates distribution d examines (0 when it can place no plant).
     *
     * @param d distribution index
     * @return candidates
     */
    public long candidates(int d) {
        return candidates[d];
    }

    /**
     * The most buckets and discs the footprint search of one candidate of distribution d looks at.
     *
     * @param d distribution index
     * @return buckets and discs (units)
     */
    public double searchPerCandidate(int d) {
        return searchPerCandidate[d];
    }

    /**
     * The most one candidate of distribution d costs: drawing it, its footprint search, and its share
     * of the resource maps' footprint means.
     *
     * @param d distribution index
     * @return units
     */
    public double costPerCandidate(int d) {
        return costPerCandidate[d];
    }

    /**
     * The most water- and nutrient-map cells one footprint mean of distribution d covers (both maps).
     *
     * @param d distribution index
     * @return cells
     */
    public double mapCellsPerFootprint(int d) {
        return mapCells[d];
    }

    /** {@return the share of the hand placements whose species has no distribution, units} */
    public double placements() {
        return placements;
    }

    /** {@return the index of the distribution with the largest share, or -1 when there is none} */
    public int largest() {
        int best = -1;
        for (int d = 0; d < work.length; d++) {
            if (best < 0 || work[d] > work[best]) {
                best = d;
            }
        }
        return best;
    }

    /** Cells of a res x res map over sx x sz that the box of a footprint of radius r covers, at most. */
    static double cells(double r, double sx, double sz, int res) {
        double ci = Math.min(res, Math.floor(2 * r / (sx / res)) + 2);
        double cj = Math.min(res, Math.floor(2 * r / (sz / res)) + 2);
        return ci * cj;
    }

    /** The footprint classes of a scene as {@link OccupancyGrid} makes them, and their bounds. */
    private static final class Classes {
        private final double sx;
        private final double sz;
        private final double[] max;
        private final double[] min;
        private final long[] discs;
        private final long[] hand;
        private final int[] nx;
        private final int[] nz;

        Classes(double sx, double sz, double[] radii, long[] perSlot, List<PlacementDef> placements,
                List<DistributionDef> distributions) {
            this.sx = sx;
            this.sz = sz;
            int[] exps = OccupancyGrid.classes(radii);
            int k = exps.length;
            max = new double[k];
            min = new double[k];
            discs = new long[k];
            hand = new long[k];
            nx = new int[k];
            nz = new int[k];
            java.util.Arrays.fill(min, Double.POSITIVE_INFINITY);
            long[] handPerSlot = new long[radii.length];
            for (int slot : CompetitiveDistributor.placementSlots(distributions, placements)) {
                handPerSlot[slot]++;
            }
            for (int i = 0; i < radii.length; i++) {
                int c = java.util.Arrays.binarySearch(exps, Math.getExponent((float) radii[i]));
                double r = (float) radii[i];
                max[c] = Math.max(max[c], r);
                if (perSlot[i] > 0) {
                    min[c] = Math.min(min[c], r);
                }
                discs[c] += perSlot[i];
                hand[c] += handPerSlot[i];
            }
            for (int c = 0; c < k; c++) {
                int[] b = OccupancyGrid.buckets(sx, sz, max[c], discs[c]);
                nx[c] = b[0];
                nz[c] = b[1];
            }
        }

        /** Most buckets and discs the search for a disc of radius r looks at, over every class. */
        double searchVisits(double r) {
            double v = 0;
            for (int c = 0; c < discs.length; c++) {
                if (discs[c] == 0) {
                    continue;
                }
                double reach = r + max[c];
                double bx = sx / nx[c];
                double bz = sz / nz[c];
                double spanX = Math.min(nx[c], Math.floor(2 * reach / bx) + 2);
                double spanZ = Math.min(nz[c], Math.floor(2 * reach / bz) + 2);
                double rho = min[c];
                double packed = (spanX * bx + 2 * rho) * (spanZ * bz + 2 * rho) / (Math.PI * rho * rho);
                v += spanX * spanZ + Math.min(discs[c], hand[c] + Math.ceil(packed));
            }
            return v;
        }
    }
}
