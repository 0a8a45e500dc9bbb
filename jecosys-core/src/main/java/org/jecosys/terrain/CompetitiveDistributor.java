package org.jecosys.terrain;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.jecosys.math.Progress;
import org.jecosys.math.Require;
import org.jecosys.math.Rng;

/**
 * The paper's plant distribution (§4.3): "the algorithm creates plants concurrently for different
 * plant distributions. One plant can occupy the area that other one could be occupying, removing the
 * nutrient or water needed for the development of other distribution."
 *
 * <p>Hand placements first, then rounds of random candidates per distribution (drawn in parallel
 * chunks where its {@link SuitabilityMask} allows, optionally gathered into clumps and tufts),
 * accepted in one fixed interleaved order when the footprint is free and the remaining water and
 * nutrients suit the species, which then consumes them ({@link ResourceMap#consume}). A hand placement
 * uses the footprint and resource use of its species' first distribution, or
 * {@link #PLACEMENT_FOOTPRINT} and {@link #PLACEMENT_USE}. A distribution's attempts are bounded by
 * {@link #ATTEMPTS_BASE} + {@link #ATTEMPTS_PER_PLANT} x its target. The algorithm step by step is in
 * docs/model.md, "Competitive distribution".
 *
 * <p>Counts are exact when achievable: a distribution places exactly its target unless it runs out of
 * attempts; it then keeps what it placed and the layout carries a warning with the shortfall. Nothing
 * here is an error except bad arguments.
 *
 * <p>Deterministic for a seed whatever {@code workers}: randomness comes only from per-chunk streams
 * keyed by (round, distribution, chunk), batch sizes depend only on earlier rounds, and conflicts
 * are resolved in the fixed acceptance order. Stateless: one instance may serve several threads.
 * Allocates its working state per call.
 */
public final class CompetitiveDistributor implements TerrainDistributor {
    /** Candidates per parallel chunk. */
    public static final int CHUNK = 1024;
    /** Smallest batch of candidates per distribution and round. */
    public static final int BATCH_MIN = 64;
    /** Largest batch of candidates per distribution and round. */
    public static final int BATCH_MAX = 32768;
    /** Batch = remaining need / acceptance rate x this slack. */
    public static final double BATCH_SLACK = 1.25;
    /** Candidates a distribution may examine per plant of its target before it gives up. */
    public static final int ATTEMPTS_PER_PLANT = 40;
    /** Candidates a distribution may examine in any case. */
    public static final int ATTEMPTS_BASE = 5000;
    /** Footprint radius, metres, of a hand-placed plant whose species has no distribution. */
    public static final double PLACEMENT_FOOTPRINT = 0.25;
    /** Water and nutrient use of a hand-placed plant whose species has no distribution. */
    public static final double PLACEMENT_USE = 0.25;
    /** Mask cells per side, at least. */
    public static final int MASK_MIN_RESOLUTION = 64;
    /** Mask cells per side, at most. */
    public static final int MASK_MAX_RESOLUTION = 512;

    /** Candidate draws a clumped distribution makes for one candidate before it keeps the last drawn. */
    public static final int CLUMP_TRIES = 64;
    /** Clump noise value where a clump's edge starts (value noise in [-1, 1]). */
    static final double CLUMP_EDGE_LO = -0.05;
    /** Clump noise value where a clump's inside is reached. */
    static final double CLUMP_EDGE_HI = 0.2;

    /** Densest packing of equal discs in the plane (hexagonal), as a share of the area. */
    static final double PACKING = Math.PI / (2 * Math.sqrt(3));

    /**
     * The most plants of footprint radius {@code footprint} whose discs fit, without overlapping, on a
     * terrain of {@code sizeX} by {@code sizeZ} metres (centres inside it): the hexagonal packing
     * density over the terrain grown by the radius on every side. A distribution's target beyond it
     * cannot be reached; its attempts are budgeted for this many. Any thread; no allocation.
     *
     * @param sizeX     terrain extent along X, metres, &gt; 0
     * @param sizeZ     terrain extent along Z, metres, &gt; 0
     * @param footprint footprint radius, metres, &gt; 0
     * @return plants, at least 1, at most {@link Long#MAX_VALUE}
     */
    public static long capacity(double sizeX, double sizeZ, double footprint) {
        double r = footprint;
        double n = Math.ceil(PACKING * (sizeX + 2 * r) * (sizeZ + 2 * r) / (Math.PI * r * r));
        return n >= Long.MAX_VALUE ? Long.MAX_VALUE : Math.max(1, (long) n);
    }

    /** A distributor; it holds no state. */
    public CompetitiveDistributor() {
    }

    @Override
    public PlantLayout distribute(Terrain terrain, List<String> speciesIds, List<DistributionDef> distributions,
                                  List<PlacementDef> placements, long seed, int workers, Progress progress) {
        Require.nonNull("terrain", terrain);
        Require.nonNull("speciesIds", speciesIds);
        Require.nonNull("distributions", distributions);
        Require.nonNull("placements", placements);
        Require.range("workers", workers, 1, 1024);
        Require.nonNull("progress", progress);
        int nd = distributions.size();
        int[] speciesOf = new int[nd];
        for (int d = 0; d < nd; d++) {
            DistributionDef def = Require.elementNonNull("distributions", d, distributions.get(d));
            speciesOf[d] = speciesIndex(speciesIds, def.species(), "distributions[" + d + "]");
        }
        for (int p = 0; p < placements.size(); p++) {
            Require.elementNonNull("placements", p, placements.get(p));
        }
        Heightfield hf = terrain.heightfield();
        ResourceMap water = terrain.water().copy();
        ResourceMap nutrients = terrain.nutrients().copy();
        OccupancyGrid grid = new OccupancyGrid(hf.minX(), hf.minZ(), hf.sizeX(), hf.sizeZ(),
                footprints(distributions), discsAtMost(hf.sizeX(), hf.sizeZ(), distributions, placements));
        PlantLayout.Builder out = new PlantLayout.Builder();
        List<String> warnings = new ArrayList<>();

        placeByHand(placements, speciesIds, distributions, seed, hf, water, nutrients, grid, out);

        int[] target = new int[nd];
        int[] placed = new int[nd];
        try (Workers pool = new Workers(workers)) {
            SuitabilityMask[] masks = new SuitabilityMask[nd];
            int maskRes = Math.max(MASK_MIN_RESOLUTION, Math.min(MASK_MAX_RESOLUTION,
                    Math.max(hf.resolution() - 1, Math.max(water.resolution(), nutrients.resolution()))));
            for (int d = 0; d < nd; d++) {
                DistributionDef def = distributions.get(d);
                masks[d] = SuitabilityMask.build(def, hf, water, nutrients, maskRes, pool);
                long want = def.count() >= 0 ? def.count() : Math.round(def.density() * masks[d].suitableArea());
                if (want > DistributionDef.MAX_COUNT) {
                    warnings.add("species '" + def.species() + "' (distribution " + d + "): density gives " + want
                            + " plants; capped at " + DistributionDef.MAX_COUNT);
                    want = DistributionDef.MAX_COUNT;
                }
                target[d] = (int) want;
                if (masks[d].suitable == 0 && def.count() != 0) {
                    warnings.add("species '" + def.species() + "' (distribution " + d
                            + ") matches nowhere on the terrain: 0 plants");
                }
            }
            Rounds rounds = new Rounds(distributions, speciesOf, masks, target, seed, hf, water, nutrients, grid, out);
            rounds.run(pool, progress);
            for (int d = 0; d < nd; d++) {
                placed[d] = rounds.placed(d);
                if (placed[d] < target[d] && masks[d].suitable > 0) {
                    warnings.add("species '" + distributions.get(d).species() + "' (distribution " + d + "): placed "
                            + placed[d] + " of " + target[d] + " plants, shortfall " + (target[d] - placed[d])
                            + " (no free ground with the right conditions found in " + rounds.examined(d)
                            + " candidates)");
                }
            }
        }
        out.occupancyVisits(grid.visits());
        return out.build(placed, target, warnings, water, nutrients);
    }

    /**
     * The most plants distribution {@code d} can place on a terrain of {@code sizeX} by {@code sizeZ}
     * metres: its count, or its density over the whole terrain (the suitable part is at most that),
     * capped at {@link DistributionDef#MAX_COUNT} and at the {@link #capacity} of its footprint. Any
     * thread; no allocation.
     *
     * @param sizeX terrain extent along X, metres, &gt; 0
     * @param sizeZ terrain extent along Z, metres, &gt; 0
     * @param d     the distribution
     * @return plants, in [0, {@link DistributionDef#MAX_COUNT}]
     */
    public static long plantsAtMost(double sizeX, double sizeZ, DistributionDef d) {
        double want = d.count() >= 0 ? d.count() : Math.ceil(d.density() * sizeX * sizeZ);
        long n = (long) Math.min(want, DistributionDef.MAX_COUNT);
        return Math.min(n, capacity(sizeX, sizeZ, d.footprint()));
    }

    /**
     * The footprint slot of each hand placement: the index of the first distribution of its species,
     * whose footprint and use it takes, or {@code distributions.size()} when its species has none
     * ({@link #PLACEMENT_FOOTPRINT}). Linear in the distributions and placements; allocates.
     */
    static int[] placementSlots(List<DistributionDef> distributions, List<PlacementDef> placements) {
        Map<String, Integer> first = new HashMap<>();
        for (int d = 0; d < distributions.size(); d++) {
            first.putIfAbsent(distributions.get(d).species(), d);
        }
        int[] slot = new int[placements.size()];
        for (int p = 0; p < slot.length; p++) {
            slot[p] = first.getOrDefault(placements.get(p).species(), distributions.size());
        }
        return slot;
    }

    /** Footprint radius per slot, metres: each distribution's, then {@link #PLACEMENT_FOOTPRINT}. */
    static double[] footprints(List<DistributionDef> distributions) {
        int nd = distributions.size();
        double[] r = new double[nd + 1];
        for (int d = 0; d < nd; d++) {
            r[d] = distributions.get(d).footprint();
        }
        r[nd] = PLACEMENT_FOOTPRINT;
        return r;
    }

    /**
     * Most discs per footprint slot ({@link #footprints}): each distribution's {@link #plantsAtMost},
     * plus the hand placements that take its footprint; the last slot counts the placements whose
     * species has no distribution.
     */
    static long[] discsAtMost(double sizeX, double sizeZ, List<DistributionDef> distributions,
                              List<PlacementDef> placements) {
        int nd = distributions.size();
        long[] n = new long[nd + 1];
        for (int d = 0; d < nd; d++) {
            n[d] = plantsAtMost(sizeX, sizeZ, distributions.get(d));
        }
        for (int slot : placementSlots(distributions, placements)) {
            n[slot]++;
        }
        return n;
    }

    private static void placeByHand(List<PlacementDef> placements, List<String> speciesIds,
                                    List<DistributionDef> distributions, long seed, Heightfield hf,
                                    ResourceMap water, ResourceMap nutrients, OccupancyGrid grid,
                                    PlantLayout.Builder out) {
        int[] slots = placementSlots(distributions, placements);
        for (int p = 0; p < placements.size(); p++) {
            PlacementDef pl = Require.elementNonNull("placements", p, placements.get(p));
            int sp = speciesIndex(speciesIds, pl.species(), "placements[" + p + "]");
            float x = (float) pl.x();
            float z = (float) pl.z();
            if (!hf.contains(x, z)) {
                throw new IllegalArgumentException("placements[" + p + "] at (" + pl.x() + ", " + pl.z()
                        + ") lies outside the terrain [" + hf.minX() + ", " + hf.maxX() + "] x ["
                        + hf.minZ() + ", " + hf.maxZ() + "]");
            }
            double r = PLACEMENT_FOOTPRINT;
            double wUse = PLACEMENT_USE;
            double nUse = PLACEMENT_USE;
            int slot = slots[p];
            if (slot < distributions.size()) {
                DistributionDef d = distributions.get(slot);
                r = d.footprint();
                wUse = d.waterUse();
                nUse = d.nutrientUse();
            }
            double w = water.footprintLevel(x, z, r);
            double n = nutrients.footprintLevel(x, z, r);
            double az = pl.azimuth() % (2 * Math.PI);
            if (az < 0) {
                az += 2 * Math.PI;
            }
            out.add(x, (float) hf.height(x, z), z, (float) az, (float) r, w, n, sp, -1, Rng.mix(seed ^ Rng.mix(p + 1L)));
            grid.add(x, z, r);
            water.consume(x, z, r, wUse);
            nutrients.consume(x, z, r, nUse);
        }
    }

    private static int speciesIndex(List<String> ids, String id, String where) {
        int i = ids.indexOf(id);
        if (i < 0) {
            throw new IllegalArgumentException(where + " names species '" + id + "', which is not among speciesIds "
                    + ids);
        }
        return i;
    }
}
