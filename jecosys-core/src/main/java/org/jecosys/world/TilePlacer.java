package org.jecosys.world;

import org.jecosys.math.HeightFunction;
import java.util.List;
import org.jecosys.math.Noise;
import org.jecosys.math.Require;
import org.jecosys.math.Rng;
import org.jecosys.terrain.DistributionDef;

/**
 * The paper's competitive distribution (§4.3) over an unbounded world cut into square tiles, each a
 * pure function of (seed, tile coordinates, distributions, height and soil functions), so a streaming
 * runtime can build tiles on workers in any order and evict and rebuild them at will (docs/ARCHITECTURE.md,
 * the {@code world} package).
 *
 * <p><b>Candidates.</b> Tile (i, j) covers [i size, (i + 1) size) x [j size, (j + 1) size) metres
 * along X and Z. For each distribution d its candidates come from the stream
 * {@code Rng.forStream(seed, hash(i, j, d))}: a count of density x tile area (the fractional part
 * drawn from the stream), positions uniform in the tile, an azimuth and a variant seed each. The
 * density is that of the candidates, so the placed density is lower where footprints crowd (with the
 * meadow's footprints and tufts, 7.6 candidates per m² give 5.7 plants per m²). With {@code tuftCount > 1} the candidates come in tufts: offsets
 * around a shared centre, normal with s.d. {@code tuftSize}, clamped to {@link #TUFT_REACH} s.d. (so
 * a tuft reaches a known distance beyond its tile); with {@code tuftBunches > 1} each joins one of the
 * tuft's bunches at random, on a ring round the centre ({@link DistributionDef#bunchCentres}), and
 * the reach grows by the ring's radius. With {@code clumpStrength > 0} each tuft centre
 * (each candidate without tufts) is kept with the chance {@code 1 - strength + strength g(x, z)} where
 * g is the clump field, smooth value noise of world position seeded by (seed, d), never of the tile;
 * the count is raised by the field's mean so the mean density stays the def's.
 *
 * <p><b>Competition.</b> To place tile T, the candidates of T and of its 8 neighbours are generated,
 * those outside T grown by the {@link #reach()} are dropped, and so are the unsuitable ones: water
 * and nutrient levels (read at the candidate's centre from the functions, when given), altitude and
 * slope (from the {@link HeightFunction}; its default slope is central differences). Every candidate
 * has a rank, a hash of its variant seed, so every tile that sees two candidates orders them alike;
 * in rank order a candidate is accepted when its footprint disc overlaps no accepted disc. The
 * accepted ones inside T are T's plants. A decision near T's border depends on its halo only through
 * chains of overlapping candidates of ever lower rank; the reach is chosen so that such a chain
 * crossing it is astronomically unlikely (see {@link #reach()}), so a border's plants are the same
 * seen from either side: no seam, and no dependence on the visit order.
 *
 * <p><b>Left out</b>, because they cannot be made local: resource consumption (a plant lowering the
 * water and nutrients around it for later ones, an order-dependent state over the whole terrain; in
 * the finite distributor it acts mostly through the resource grid's cells, since accepted footprints
 * never overlap), exact counts ({@code count} must be
 * -1), hand placements and the finite distributor's rounds (candidates beyond the target). Levels are
 * read at a candidate's centre, not averaged over its footprint.
 *
 * <p>Thread-safe: any thread may call {@link #place} concurrently, provided the height and soil
 * functions allow concurrent calls; a tile's plants depend only on the placer's inputs and the tile.
 * {@link #place} allocates the tile's arrays and reuses its working buffers from call to call (kept by
 * the placer, about one per thread placing at once).
 */
public final class TilePlacer {
    /** Smallest tile side, metres. */
    public static final double MIN_TILE_SIZE = 0.5;
    /** Largest tile side, metres. */
    public static final double MAX_TILE_SIZE = 4096;
    /** Largest |tile index| along either axis. */
    public static final int MAX_TILE_INDEX = 1 << 30;
    /** Most candidates one tile may generate (all distributions together). */
    public static final int MAX_CANDIDATES_PER_TILE = 1 << 22;
    /** Tuft offsets are clamped to this many standard deviations ({@code tuftSize}) along each axis. */
    public static final double TUFT_REACH = 3;
    /** The reach around a tile, in largest footprint diameters, when candidates are sparse enough. */
    public static final double REACH_DIAMETERS = 32;
    /**
     * The most candidates expected within one largest footprint diameter of a candidate for which the
     * reach is {@link #REACH_DIAMETERS}; denser layouts use the whole halo.
     */
    public static final double SPARSE_NEIGHBOURS = 4;
    /** Clump field value where a clump's edge starts (as in the finite distributor). */
    static final double CLUMP_EDGE_LO = -0.05;
    /** Clump field value where a clump's inside is reached. */
    static final double CLUMP_EDGE_HI = 0.2;
    /** Samples per side, over {@link #CLUMP_MEAN_CELLS} noise cells, of the clump field's mean. */
    private static final int CLUMP_MEAN_SAMPLES = 192;
    private static final int CLUMP_MEAN_CELLS = 48;
    /** Candidate buffers kept for reuse, about one per thread that places at once. */
    private static final int SPARE_BUFFERS = 8;

    private final long seed;
    private final double size;
    private final DistributionDef[] defs;
    private final int[] speciesOf;
    private final HeightFunction height;
    private final ResourceFunction water;
    private final ResourceFunction nutrients;
    private final double[] radius;
    private final double maxRadius;
    private final double[] candidatesPerTile;
    private final long[] clumpSeed;
    private final double reach;
    private final double tuftReachMax;
    /**
     * Candidate buffers no {@link #place} call holds now, at most {@link #SPARE_BUFFERS}: a call takes
     * one (or makes one) and gives it back, so placing tile after tile reuses the same arrays. Guarded
     * by itself; the only state the placer changes, and it changes no result.
     */
    private final java.util.ArrayDeque<Candidates> spare = new java.util.ArrayDeque<>();

    /**
     * A placer without soil functions: water and nutrient limits are not checked. Allocates.
     *
     * @param seed          the world's seed
     * @param tileSize      tile side, metres (see the full constructor)
     * @param distributions what grows, each with {@code count == -1}
     * @param speciesOf     species index of each distribution
     * @param height        the ground, not null
     * @throws IllegalArgumentException on a bad argument (see the full constructor)
     * @see #TilePlacer(long, double, List, int[], HeightFunction, ResourceFunction, ResourceFunction)
     */
    public TilePlacer(long seed, double tileSize, List<DistributionDef> distributions, int[] speciesOf,
                      HeightFunction height) {
        this(seed, tileSize, distributions, speciesOf, height, null, null);
    }

    /**
     * A placer. Validates and copies its arguments; estimates each clumped distribution's mean clump
     * field (about 37,000 noise samples each). Any thread; allocates.
     *
     * @param seed          the world's seed
     * @param tileSize      tile side, metres, in [{@link #MIN_TILE_SIZE}, {@link #MAX_TILE_SIZE}], and at
     *                      least the largest footprint diameter plus the largest tuft reach
     * @param distributions what grows, each with {@code count == -1} (density-based), not empty
     * @param speciesOf     species index of each distribution, &gt;= 0, as many as distributions
     * @param height        the ground, not null
     * @param water         water level of world position, or null to ignore the water limits
     * @param nutrients     nutrient level of world position, or null to ignore the nutrient limits
     * @throws IllegalArgumentException on a bad argument, an exact count (the message names the
     *                                  species), a tile too small for the footprints and tufts, or more
     *                                  than {@link #MAX_CANDIDATES_PER_TILE} candidates per tile
     */
    public TilePlacer(long seed, double tileSize, List<DistributionDef> distributions, int[] speciesOf,
                      HeightFunction height, ResourceFunction water, ResourceFunction nutrients) {
        this(seed, tileSize, distributions, speciesOf, height, water, nutrients, false);
    }

    /** The full constructor; {@code wholeHalo} makes the reach the whole halo (for tests of the reach). */
    TilePlacer(long seed, double tileSize, List<DistributionDef> distributions, int[] speciesOf,
               HeightFunction height, ResourceFunction water, ResourceFunction nutrients, boolean wholeHalo) {
        Require.range("tileSize", tileSize, MIN_TILE_SIZE, MAX_TILE_SIZE);
        Require.nonNull("distributions", distributions);
        Require.nonNull("speciesOf", speciesOf);
        this.height = Require.nonNull("height", height);
        int nd = distributions.size();
        if (nd == 0) {
            throw new IllegalArgumentException("distributions must not be empty");
        }
        if (speciesOf.length != nd) {
            throw new IllegalArgumentException("speciesOf must have one entry per distribution (" + nd + "), got "
                    + speciesOf.length);
        }
        this.seed = seed;
        this.size = tileSize;
        this.defs = new DistributionDef[nd];
        this.speciesOf = speciesOf.clone();
        this.water = water;
        this.nutrients = nutrients;
        this.radius = new double[nd];
        this.candidatesPerTile = new double[nd];
        this.clumpSeed = new long[nd];
        double rMax = 0;
        double lim = 0;
        double perM2 = 0;
        for (int d = 0; d < nd; d++) {
            DistributionDef def = Require.elementNonNull("distributions", d, distributions.get(d));
            if (def.count() != -1) {
                throw new IllegalArgumentException("distributions[" + d + "] (species '" + def.species()
                        + "') has count " + def.count() + "; tiled placement takes densities only (count -1)");
            }
            Require.elementRange("speciesOf", d, this.speciesOf[d], 0, Integer.MAX_VALUE);
            defs[d] = def;
            radius[d] = def.footprint();
            rMax = Math.max(rMax, radius[d]);
            lim = Math.max(lim, tuftReach(def));
            clumpSeed[d] = Rng.mix(seed ^ Rng.mix(0xC1L + ((long) d << 8)));
            double mean = def.clumpStrength() > 0 ? clumpMean(d) : 1;
            double density = def.density() / mean;
            candidatesPerTile[d] = density * tileSize * tileSize;
            perM2 += density;
        }
        double candidates = perM2 * tileSize * tileSize;
        if (candidates > MAX_CANDIDATES_PER_TILE) {
            throw new IllegalArgumentException("the distributions give about " + Math.round(candidates)
                    + " candidates per tile of " + tileSize + " m, more than " + MAX_CANDIDATES_PER_TILE
                    + "; use smaller tiles");
        }
        this.maxRadius = rMax;
        this.tuftReachMax = lim;
        double halo = tileSize - lim;
        if (halo < 2 * rMax) {
            throw new IllegalArgumentException("tileSize " + tileSize + " m is too small: it must be at least the"
                    + " largest footprint diameter (" + 2 * rMax + " m) plus the largest tuft reach ("
                    + TUFT_REACH + " tuftSize, plus tuftRing where a tuft has bunches: " + lim + " m)");
        }
        double neighbours = perM2 * Math.PI * 4 * rMax * rMax;
        this.reach = neighbours <= SPARSE_NEIGHBOURS && !wholeHalo ? Math.min(halo, REACH_DIAMETERS * 2 * rMax) : halo;
    }

    /** {@return the ground the plants stand on} */
    public HeightFunction ground() {
        return height;
    }

    /** {@return the tile side, metres} */
    public double tileSize() {
        return size;
    }

    /**
     * The margin, metres, around a tile within which the halo's candidates take part in its
     * competition: {@link #REACH_DIAMETERS} largest footprint diameters when a candidate has at most
     * {@link #SPARSE_NEIGHBOURS} others expected within one diameter (a chain of 32 overlapping
     * candidates of decreasing rank then has odds below 4^32 / 32!, about 1e-16), else the whole halo;
     * never more than the tile side less the largest tuft reach (no tuft from beyond the halo lands in
     * it). Any thread; no allocation.
     *
     * @return metres, in (0, tileSize]
     */
    public double reach() {
        return reach;
    }

    /**
     * The plants of tile (tileI, tileJ): those whose position lies in [tileI size, (tileI + 1) size) x
     * [tileJ size, (tileJ + 1) size). A pure function of the placer's inputs and the tile: the same
     * arrays whatever was placed before, on any thread. Allocates the tile's arrays; the candidates of
     * the gathered region (about 50,000 for a 32 m tile at meadow density) go in buffers the placer
     * keeps and reuses.
     *
     * @param tileI tile index along X, in [-{@link #MAX_TILE_INDEX}, {@link #MAX_TILE_INDEX}]
     * @param tileJ tile index along Z, in the same range
     * @return the tile's plants
     * @throws IllegalArgumentException when an index is out of range
     */
    public TilePlants place(int tileI, int tileJ) {
        Require.range("tileI", tileI, -MAX_TILE_INDEX, MAX_TILE_INDEX);
        Require.range("tileJ", tileJ, -MAX_TILE_INDEX, MAX_TILE_INDEX);
        double minX = (double) tileI * size - reach;
        double maxX = (double) (tileI + 1) * size + reach;
        double minZ = (double) tileJ * size - reach;
        double maxZ = (double) (tileJ + 1) * size + reach;
        Candidates c;
        synchronized (spare) {
            c = spare.poll();
        }
        if (c == null) {
            c = new Candidates();
        }
        try {
            return place(tileI, tileJ, minX, maxX, minZ, maxZ, c);
        } finally {
            c.clear();
            synchronized (spare) {
                if (spare.size() < SPARE_BUFFERS) {
                    spare.push(c);
                }
            }
        }
    }

    private TilePlants place(int tileI, int tileJ, double minX, double maxX, double minZ, double maxZ, Candidates c) {
        for (int dj = -1; dj <= 1; dj++) {
            for (int di = -1; di <= 1; di++) {
                for (int d = 0; d < defs.length; d++) {
                    generate(tileI + di, tileJ + dj, d, minX, maxX, minZ, maxZ, c);
                }
            }
        }
        int na = c.compete(radius, maxRadius, minX, minZ, maxX - minX, maxZ - minZ);
        int[] accepted = c.accepted;
        double x0 = (double) tileI * size;
        double x1 = (double) (tileI + 1) * size;
        double z0 = (double) tileJ * size;
        double z1 = (double) (tileJ + 1) * size;
        int n = 0;
        for (int k = 0; k < na; k++) {
            int a = accepted[k];
            if (inside(c.x[a], c.z[a], x0, x1, z0, z1)) {
                accepted[n++] = a;
            }
        }
        float[] px = new float[n];
        float[] py = new float[n];
        float[] pz = new float[n];
        int[] sp = new int[n];
        long[] vs = new long[n];
        float[] az = new float[n];
        for (int k = 0; k < n; k++) {
            int a = accepted[k];
            px[k] = (float) c.x[a];
            pz[k] = (float) c.z[a];
            py[k] = (float) height.height(px[k], pz[k]);
            sp[k] = speciesOf[c.dist[a]];
            vs[k] = c.seed[a];
            az[k] = c.azimuth[a];
        }
        return new TilePlants(tileI, tileJ, px, py, pz, sp, vs, az);
    }

    /**
     * The candidates of distribution d generated by tile (ti, tj) that land in the region and suit the
     * species. Every candidate takes the same draws from the stream whether or not it is kept.
     */
    private void generate(int ti, int tj, int d, double minX, double maxX, double minZ, double maxZ, Candidates out) {
        DistributionDef def = defs[d];
        Rng rng = Rng.forStream(seed, stream(ti, tj, d));
        double lambda = candidatesPerTile[d];
        int n = (int) Math.floor(lambda);
        if (rng.nextDouble() < lambda - n) {
            n++;
        }
        double x0 = (double) ti * size;
        double x1 = (double) (ti + 1) * size;
        double z0 = (double) tj * size;
        double z1 = (double) (tj + 1) * size;
        int tuft = def.tuftCount();
        double spread = def.tuftSize();
        double lim = tuftReach(def);
        double clampS = tuft > 1 ? TUFT_REACH * spread : 0;
        int bunches = tuft > 1 ? def.tuftBunches() : 1;
        double[] bunchX = new double[bunches];
        double[] bunchZ = new double[bunches];
        double strength = def.clumpStrength();
        double cx = 0;
        double cz = 0;
        boolean kept = true;
        for (int k = 0; k < n; k++) {
            if (k % tuft == 0) {
                cx = below(x0 + rng.nextDouble() * size, x1);
                cz = below(z0 + rng.nextDouble() * size, z1);
                // only a tuft that can reach the region is worked out further; the draws are taken anyway
                boolean near = cx >= minX - lim && cx < maxX + lim && cz >= minZ - lim && cz < maxZ + lim;
                kept = near;
                if (strength > 0) {
                    double u = rng.nextDouble();
                    kept = near && u < clumpAcceptance(clumpSeed[d], 1 / (2 * def.clumpSize()), strength, cx, cz);
                }
                if (bunches > 1) { // the ring's draws are taken whether or not the tuft is kept
                    def.bunchCentres(rng, cx, cz, bunchX, bunchZ);
                } else {
                    bunchX[0] = cx;
                    bunchZ[0] = cz;
                }
            }
            double x = cx;
            double z = cz;
            if (tuft > 1) {
                if (kept) {
                    int b = bunches > 1 ? rng.nextInt(bunches) : 0;
                    x = bunchX[b] + Math.max(-clampS, Math.min(clampS, spread * rng.nextGaussian()));
                    z = bunchZ[b] + Math.max(-clampS, Math.min(clampS, spread * rng.nextGaussian()));
                } else {
                    skip(rng, (bunches > 1 ? 1 : 0) + 4); // the bunch, and two normal draws of two longs each
                }
            }
            if (!kept) {
                skip(rng, 2); // azimuth and variant seed
                continue;
            }
            float az = (float) (rng.nextDouble() * 2 * Math.PI);
            long vs = rng.nextLong();
            if (x >= minX && x < maxX && z >= minZ && z < maxZ && suits(def, x, z)) {
                out.add(x, z, az < 2 * (float) Math.PI ? az : 0, vs, d, ti, tj, k);
            }
        }
    }

    /**
     * How far a plant of the distribution may stand from its tuft's drawn centre, metres: the bunches'
     * ring ({@link DistributionDef#tuftRing}, with more than one bunch) plus the clamped spread; 0
     * without tufts.
     */
    static double tuftReach(DistributionDef def) {
        if (def.tuftCount() <= 1) {
            return 0;
        }
        return TUFT_REACH * def.tuftSize() + (def.tuftBunches() > 1 ? def.tuftRing() : 0);
    }

    /** Advances the stream by n draws, as n calls of {@link Rng#nextLong} (or nextDouble) would. */
    private static void skip(Rng rng, int n) {
        for (int k = 0; k < n; k++) {
            rng.nextLong();
        }
    }

    /** Whether the soil and the ground at (x, z) suit the distribution. */
    private boolean suits(DistributionDef def, double x, double z) {
        if (water != null && (def.minWater() > 0 || def.maxWater() < 1)) {
            double w = water.level(x, z);
            if (w < def.minWater() || w > def.maxWater()) {
                return false;
            }
        }
        if (nutrients != null && (def.minNutrients() > 0 || def.maxNutrients() < 1)) {
            double v = nutrients.level(x, z);
            if (v < def.minNutrients() || v > def.maxNutrients()) {
                return false;
            }
        }
        if (def.minAltitude() > -DistributionDef.MAX_ALTITUDE || def.maxAltitude() < DistributionDef.MAX_ALTITUDE) {
            double y = height.height(x, z);
            if (y < def.minAltitude() || y > def.maxAltitude()) {
                return false;
            }
        }
        return def.maxSlope() >= Math.PI / 2 - 1e-9 || height.slope(x, z) <= def.maxSlope();
    }

    /** The stream of tile (ti, tj)'s candidates of distribution d. */
    static long stream(int ti, int tj, int d) {
        return Rng.mix(ti * 0x9E3779B97F4A7C15L ^ Rng.mix(tj * 0xC2B2AE3D27D4EB4FL ^ Rng.mix(d + 0x7F4A7C15L)));
    }

    /** Whether (x, z) lies in the half-open square [x0, x1) x [z0, z1). */
    static boolean inside(double x, double z, double x0, double x1, double z0, double z1) {
        return x >= x0 && x < x1 && z >= z0 && z < z1;
    }

    /** v, or the double just below hi when rounding put it at hi. */
    private static double below(double v, double hi) {
        return v < hi ? v : Math.nextDown(hi);
    }

    /**
     * The chance a candidate at world (x, z) survives the clumping: {@code 1 - strength + strength g},
     * g in [0, 1] a smooth step of seeded value noise with lattice cells of {@code 1 / scale} metres
     * (twice the clump radius), as in the finite distributor. Any thread; no allocation.
     */
    static double clumpAcceptance(long clumpSeed, double scale, double strength, double x, double z) {
        double n = Noise.value2(clumpSeed, x * scale, z * scale);
        double t = Math.max(0, Math.min(1, (n - CLUMP_EDGE_LO) / (CLUMP_EDGE_HI - CLUMP_EDGE_LO)));
        double g = t * t * (3 - 2 * t);
        return 1 - strength + strength * g;
    }

    /** The seed of distribution d's clump field. */
    long clumpSeed(int d) {
        return clumpSeed[d];
    }

    /**
     * Distribution d's mean {@link #clumpAcceptance} over {@link #CLUMP_MEAN_CELLS}^2 noise cells, at
     * least 0.05: a deterministic estimate of the share of candidates the clumping keeps.
     */
    private double clumpMean(int d) {
        DistributionDef def = defs[d];
        double scale = 1 / (2 * def.clumpSize());
        double step = CLUMP_MEAN_CELLS / scale / CLUMP_MEAN_SAMPLES;
        double sum = 0;
        for (int j = 0; j < CLUMP_MEAN_SAMPLES; j++) {
            for (int i = 0; i < CLUMP_MEAN_SAMPLES; i++) {
                sum += clumpAcceptance(clumpSeed[d], scale, def.clumpStrength(), (i + 0.5) * step, (j + 0.5) * step);
            }
        }
        return Math.max(0.05, sum / ((double) CLUMP_MEAN_SAMPLES * CLUMP_MEAN_SAMPLES));
    }
}
