package org.jecosys.terrain;

import java.util.List;
import org.jecosys.math.Noise;
import org.jecosys.math.Progress;
import org.jecosys.math.Rng;

/**
 * The candidate rounds of {@link CompetitiveDistributor} (paper §4.3): parallel candidate generation
 * in fixed chunks, then sequential acceptance in a fixed, proportionally interleaved order.
 * One call of {@link #run}; package-private; allocates its candidate buffers once.
 */
final class Rounds {
    private final List<DistributionDef> defs;
    private final int[] speciesOf;
    private final SuitabilityMask[] masks;
    private final int[] target;
    private final long seed;
    private final Heightfield hf;
    private final ResourceMap water;
    private final ResourceMap nutrients;
    private final OccupancyGrid grid;
    private final PlantLayout.Builder out;
    private final int nd;
    private final int[] placed;
    private final long[] examined;
    private final long[] budget;
    private final int[] batch;
    // candidate buffers, per distribution
    private final float[][] cx;
    private final float[][] cy;
    private final float[][] cz;
    private final float[][] caz;
    private final long[][] cseed;
    private final boolean[][] cok;

    Rounds(List<DistributionDef> defs, int[] speciesOf, SuitabilityMask[] masks, int[] target, long seed,
           Heightfield hf, ResourceMap water, ResourceMap nutrients, OccupancyGrid grid, PlantLayout.Builder out) {
        this.defs = defs;
        this.speciesOf = speciesOf;
        this.masks = masks;
        this.target = target;
        this.seed = seed;
        this.hf = hf;
        this.water = water;
        this.nutrients = nutrients;
        this.grid = grid;
        this.out = out;
        this.nd = defs.size();
        this.placed = new int[nd];
        this.examined = new long[nd];
        this.budget = new long[nd];
        this.batch = new int[nd];
        this.cx = new float[nd][];
        this.cy = new float[nd][];
        this.cz = new float[nd][];
        this.caz = new float[nd][];
        this.cseed = new long[nd][];
        this.cok = new boolean[nd][];
        for (int d = 0; d < nd; d++) {
            // a target beyond what the footprints can ever pack is never reached: spend attempts only on
            // what fits, so an impossible density (10000 per m^2) ends in seconds with a shortfall
            long reachable = Math.min(target[d], CompetitiveDistributor.capacity(hf.sizeX(), hf.sizeZ(),
                    defs.get(d).footprint()));
            budget[d] = CompetitiveDistributor.ATTEMPTS_BASE + CompetitiveDistributor.ATTEMPTS_PER_PLANT * reachable;
            int cap = (int) Math.min(CompetitiveDistributor.BATCH_MAX, budget[d]);
            if (target[d] == 0 || masks[d].suitable == 0) {
                cap = 0;
            }
            cx[d] = new float[cap];
            cy[d] = new float[cap];
            cz[d] = new float[cap];
            caz[d] = new float[cap];
            cseed[d] = new long[cap];
            cok[d] = new boolean[cap];
        }
    }

    int placed(int d) {
        return placed[d];
    }

    long examined(int d) {
        return examined[d];
    }

    void run(Workers workers, Progress progress) {
        long total = 0;
        for (int d = 0; d < nd; d++) {
            if (masks[d].suitable > 0) {
                total += target[d];
            }
        }
        if (total > 0) {
            progress.report("distribution", 0, total);
        }
        long done = 0;
        int[] chunkDist = new int[0];
        int[] chunkIndex = new int[0];
        for (int round = 0; ; round++) {
            int chunks = 0;
            for (int d = 0; d < nd; d++) {
                batch[d] = batchSize(d);
                chunks += (batch[d] + CompetitiveDistributor.CHUNK - 1) / CompetitiveDistributor.CHUNK;
            }
            if (chunks == 0) {
                break;
            }
            if (chunkDist.length < chunks) {
                chunkDist = new int[chunks];
                chunkIndex = new int[chunks];
            }
            int t = 0;
            for (int d = 0; d < nd; d++) {
                int nc = (batch[d] + CompetitiveDistributor.CHUNK - 1) / CompetitiveDistributor.CHUNK;
                for (int c = 0; c < nc; c++) {
                    chunkDist[t] = d;
                    chunkIndex[t++] = c;
                }
            }
            int[] cd = chunkDist;
            int[] ci = chunkIndex;
            long r = round;
            workers.run(chunks, k -> generate(r, cd[k], ci[k]));
            accept();
            if (total > 0) {
                // a distribution that has spent its attempts is done: progress never stalls on a shortfall
                done = 0;
                for (int d = 0; d < nd; d++) {
                    if (masks[d].suitable > 0) {
                        done += examined[d] >= budget[d] ? target[d] : placed[d];
                    }
                }
                progress.report("distribution", Math.min(done, total), total);
            }
        }
    }

    /** Candidates for distribution d this round: 0 when it is done, out of budget or has no ground. */
    private int batchSize(int d) {
        int need = target[d] - placed[d];
        long left = budget[d] - examined[d];
        if (need <= 0 || left <= 0 || masks[d].suitable == 0) {
            return 0;
        }
        double rate = (placed[d] + 1.0) / (examined[d] + 2.0);
        double want = Math.ceil(need * CompetitiveDistributor.BATCH_SLACK / rate);
        long b = (long) Math.max(CompetitiveDistributor.BATCH_MIN, Math.min(CompetitiveDistributor.BATCH_MAX, want));
        return (int) Math.min(b, Math.min(left, cx[d].length));
    }

    /** Fills chunk c of distribution d's batch; touches only that chunk's slots. */
    private void generate(long round, int d, int c) {
        DistributionDef def = defs.get(d);
        SuitabilityMask m = masks[d];
        Rng rng = Rng.forStream(seed, (round << 40) ^ ((long) d << 16) ^ c);
        int from = c * CompetitiveDistributor.CHUNK;
        int to = Math.min(batch[d], from + CompetitiveDistributor.CHUNK);
        double minX = hf.minX();
        double minZ = hf.minZ();
        double strength = def.clumpStrength();
        long clumpSeed = Rng.mix(seed ^ Rng.mix(0xC1L + ((long) d << 8)));
        double clumpScale = 1 / (2 * def.clumpSize());
        int tuft = def.tuftCount();
        double spread = def.tuftSize();
        int bunches = tuft > 1 ? def.tuftBunches() : 1;
        double[] bunchX = new double[bunches];
        double[] bunchZ = new double[bunches];
        float x = 0;
        float z = 0;
        for (int i = from; i < to; i++) {
            int member = (i - from) % tuft;
            if (tuft == 1 || member == 0) {
                int tries = 0;
                while (true) {
                    int cell = m.possible[rng.nextInt(m.possible.length)];
                    int mi = cell % m.res;
                    int mj = cell / m.res;
                    x = inside(minX + (mi + rng.nextDouble()) * m.cellX, minX, hf.maxX());
                    z = inside(minZ + (mj + rng.nextDouble()) * m.cellZ, minZ, hf.maxZ());
                    // strength 0 draws nothing more: the paper's uniform candidates, bit for bit
                    if (strength == 0 || ++tries >= CompetitiveDistributor.CLUMP_TRIES
                            || rng.nextDouble() < clumpAcceptance(clumpSeed, clumpScale, strength, x, z)) {
                        break;
                    }
                }
                if (bunches > 1) {
                    def.bunchCentres(rng, x, z, bunchX, bunchZ);
                } else { // one bunch, at the centre, draws nothing more: the tufts without bunches, bit for bit
                    bunchX[0] = x;
                    bunchZ[0] = z;
                }
            }
            float px = x;
            float pz = z;
            if (tuft > 1) { // a tuft member: normal offsets from its bunch's centre; one tuft count draws none
                int b = bunches > 1 ? rng.nextInt(bunches) : 0; // each joins a bunch at random: bunches of uneven size
                px = inside(bunchX[b] + spread * rng.nextGaussian(), minX, hf.maxX());
                pz = inside(bunchZ[b] + spread * rng.nextGaussian(), minZ, hf.maxZ());
            }
            double y = hf.height(px, pz);
            cx[d][i] = px;
            cz[d][i] = pz;
            cy[d][i] = (float) y;
            cok[d][i] = y >= def.minAltitude() && y <= def.maxAltitude() && hf.slope(px, pz) <= def.maxSlope();
            caz[d][i] = (float) (rng.nextDouble() * 2 * Math.PI);
            cseed[d][i] = rng.nextLong();
        }
    }

    /** Accepts candidates in the fixed interleaved order; returns the plants placed this round. */
    private int accept() {
        int[] next = new int[nd];
        int accepted = 0;
        while (true) {
            int best = -1;
            double bestKey = Double.POSITIVE_INFINITY;
            for (int d = 0; d < nd; d++) {
                if (next[d] < batch[d]) {
                    double key = (next[d] + 0.5) / batch[d];
                    if (key < bestKey) {
                        bestKey = key;
                        best = d;
                    }
                }
            }
            if (best < 0) {
                return accepted;
            }
            int d = best;
            int i = next[d]++;
            if (placed[d] >= target[d]) {
                continue;
            }
            examined[d]++;
            if (!cok[d][i]) {
                continue;
            }
            DistributionDef def = defs.get(d);
            double x = cx[d][i];
            double z = cz[d][i];
            double r = def.footprint();
            if (!grid.free(x, z, r)) {
                continue;
            }
            double w = water.footprintLevel(x, z, r);
            if (w < def.minWater() || w > def.maxWater()) {
                continue;
            }
            double n = nutrients.footprintLevel(x, z, r);
            if (n < def.minNutrients() || n > def.maxNutrients()) {
                continue;
            }
            out.add(cx[d][i], cy[d][i], cz[d][i], caz[d][i], (float) r, w, n, speciesOf[d], d, cseed[d][i]);
            grid.add(x, z, r);
            water.consume(x, z, r, def.waterUse());
            nutrients.consume(x, z, r, def.nutrientUse());
            placed[d]++;
            accepted++;
        }
    }

    /**
     * The chance a candidate at (x, z) is kept by the clumping: {@code 1 - strength + strength g}, where
     * g in [0, 1] is a smooth step of seeded value noise with lattice cells of twice the clump radius,
     * so that about 40% of the ground lies inside clumps (g &gt; 0).
     */
    static double clumpAcceptance(long clumpSeed, double scale, double strength, double x, double z) {
        double n = Noise.value2(clumpSeed, x * scale, z * scale);
        double t = Math.max(0, Math.min(1, (n - CompetitiveDistributor.CLUMP_EDGE_LO)
                / (CompetitiveDistributor.CLUMP_EDGE_HI - CompetitiveDistributor.CLUMP_EDGE_LO)));
        double g = t * t * (3 - 2 * t);
        return 1 - strength + strength * g;
    }

    /** v as a float inside [lo, hi]. */
    private static float inside(double v, double lo, double hi) {
        float f = (float) Math.max(lo, Math.min(hi, v));
        if (f < lo) {
            f = Math.nextUp(f);
        } else if (f > hi) {
            f = Math.nextDown(f);
        }
        return f;
    }
}
