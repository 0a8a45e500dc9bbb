package org.jecosys.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.jecosys.terrain.DistributionDef;
import org.junit.jupiter.api.Test;

/**
 * Tiles without seams at about the meadow's density (scenes/meadow.xml): a 4 x 4 block of 16 m tiles
 * of three distributions (about 5.7 plants per m², footprints 0.05 to 0.15 m, tufts and clumps) is as
 * regular across tile borders as inside tiles (Clark–Evans ratio), as dense along the borders, and no
 * two footprints overlap anywhere, across borders included. Also prints the {@code [bench]} figures
 * of 32 m tiles on rolling hills.
 */
class TileSeamTest {
    static final double TILE = 16;
    static final int FIRST = -2;
    static final int TILES = 4;

    /**
     * Meadow-like distributions, species 0, 1, 2: 7.6 candidates per m² together, of which the
     * competition keeps about 5.7 plants per m² (the meadow's density).
     */
    static List<DistributionDef> meadow() {
        return List.of(
                DistributionDef.builder("grassA").density(4.3).footprint(0.05).tufts(0.12, 3).build(),
                DistributionDef.builder("flowerB").density(2.4).footprint(0.08).clump(2, 0.6).build(),
                DistributionDef.builder("grassS").density(0.9).footprint(0.15).build());
    }

    static final int[] SPECIES = {0, 1, 2};
    static final double[] FOOTPRINT = {0.05, 0.08, 0.15};

    /** The block's plants: x, z, species, flattened from its tiles. */
    record Block(double[] x, double[] z, int[] species) {
        int n() {
            return x.length;
        }
    }

    static Block block(TilePlacer placer) {
        TilePlants[] tiles = new TilePlants[TILES * TILES];
        int n = 0;
        for (int j = 0; j < TILES; j++) {
            for (int i = 0; i < TILES; i++) {
                tiles[j * TILES + i] = placer.place(FIRST + i, FIRST + j);
                n += tiles[j * TILES + i].count();
            }
        }
        double[] x = new double[n];
        double[] z = new double[n];
        int[] s = new int[n];
        int k = 0;
        for (TilePlants t : tiles) {
            for (int p = 0; p < t.count(); p++) {
                x[k] = t.x()[p];
                z[k] = t.z()[p];
                s[k++] = t.species()[p];
            }
        }
        return new Block(x, z, s);
    }

    /** A spatial grid over the block for neighbour searches: cells of 0.5 m. */
    static final class Grid {
        static final double CELL = 0.5;
        final double min = FIRST * TILE;
        final int side = (int) Math.ceil(TILES * TILE / CELL);
        final int[] head;
        final int[] next;
        final Block b;

        Grid(Block b) {
            this.b = b;
            head = new int[side * side];
            next = new int[b.n()];
            Arrays.fill(head, -1);
            for (int p = 0; p < b.n(); p++) {
                int c = cell(b.z()[p]) * side + cell(b.x()[p]);
                next[p] = head[c];
                head[c] = p;
            }
        }

        int cell(double v) {
            return Math.max(0, Math.min(side - 1, (int) ((v - min) / CELL)));
        }

        /** Distance from plant p to its nearest other plant within 2 cells (else 2 cells). */
        double nearest(int p) {
            double best = 2 * CELL;
            int ci = cell(b.x()[p]);
            int cj = cell(b.z()[p]);
            for (int j = Math.max(0, cj - 2); j <= Math.min(side - 1, cj + 2); j++) {
                for (int i = Math.max(0, ci - 2); i <= Math.min(side - 1, ci + 2); i++) {
                    for (int q = head[j * side + i]; q >= 0; q = next[q]) {
                        if (q != p) {
                            best = Math.min(best, Math.hypot(b.x()[q] - b.x()[p], b.z()[q] - b.z()[p]));
                        }
                    }
                }
            }
            return best;
        }
    }

    /** Clark–Evans ratio in the 4 m window at (wx, wz): centres 0.5 m inside it, neighbours anywhere. */
    static double clarkEvans(Block b, Grid g, double wx, double wz) {
        int inWindow = 0;
        double sum = 0;
        int centres = 0;
        for (int p = 0; p < b.n(); p++) {
            double x = b.x()[p] - wx;
            double z = b.z()[p] - wz;
            if (x >= 0 && x < 4 && z >= 0 && z < 4) {
                inWindow++;
                if (x >= 0.5 && x < 3.5 && z >= 0.5 && z < 3.5) {
                    sum += g.nearest(p);
                    centres++;
                }
            }
        }
        double density = inWindow / 16.0;
        return sum / centres / (0.5 / Math.sqrt(density));
    }

    @Test
    void bordersAreAsRegularAndAsDenseAsTheInsideOfTiles() {
        TilePlacer placer = new TilePlacer(2024, TILE, meadow(), SPECIES, (x, z) -> 0);
        Block b = block(placer);
        Grid g = new Grid(b);
        double lo = FIRST * TILE;
        double hi = lo + TILES * TILE;
        // windows inside tiles: 3 x 3 per tile, at least 2 m from its borders
        double insideSum = 0;
        int inside = 0;
        double[] insideRatio = new double[TILES * TILES * 9];
        for (int t = 0; t < TILES * TILES; t++) {
            double tx = lo + (t % TILES) * TILE;
            double tz = lo + (t / TILES) * TILE;
            for (int wj = 0; wj < 3; wj++) {
                for (int wi = 0; wi < 3; wi++) {
                    insideRatio[inside] = clarkEvans(b, g, tx + 2 + 4 * wi, tz + 2 + 4 * wj);
                    insideSum += insideRatio[inside++];
                }
            }
        }
        double insideMean = insideSum / inside;
        double insideWorst = 0;
        for (double r : insideRatio) {
            insideWorst = Math.max(insideWorst, Math.abs(r - insideMean));
        }
        // windows centred on the inner borders, along them, 2 m from the block's edge
        double straddleSum = 0;
        double worst = 0;
        int straddle = 0;
        for (int line = 1; line < TILES; line++) {
            double border = lo + line * TILE;
            for (double w = lo + 2; w + 4 <= hi - 2; w += 4) {
                double v = clarkEvans(b, g, border - 2, w);
                double h = clarkEvans(b, g, w, border - 2);
                straddleSum += v + h;
                straddle += 2;
                worst = Math.max(worst, Math.max(Math.abs(v - insideMean), Math.abs(h - insideMean)));
            }
        }
        double straddleMean = straddleSum / straddle;
        double[] bands = bandDensities(b);
        double interiorDensity = bands[0];
        double beforeRatio = bands[1];
        double afterRatio = bands[2];
        double minDistance = minDistanceAndNoOverlap(b, g);
        System.out.printf(Locale.ROOT, "[bench] seams: %d plants on %.0f m^2 (%.2f per m^2 inside tiles); Clark-Evans"
                        + " inside tiles %.3f (%d windows, worst off by %.3f), straddling borders %.3f (%d windows,"
                        + " worst off by %.3f); density in the 1 m bands before/after a border %.3f/%.3f of the inside; nearest"
                        + " two plants %.4f m%n", b.n(), TILES * TILE * TILES * TILE, interiorDensity, insideMean, inside,
                insideWorst, straddleMean, straddle, worst, beforeRatio, afterRatio, minDistance);
        assertTrue(interiorDensity > 5.2 && interiorDensity < 6.2, "about the meadow's density: " + interiorDensity);
        assertEquals(insideMean, straddleMean, 0.1, "Clark-Evans ratio straddling borders vs inside tiles");
        assertTrue(Math.abs(beforeRatio - 1) <= 0.1 && Math.abs(afterRatio - 1) <= 0.1,
                "border band densities " + beforeRatio + ", " + afterRatio + " of the inside's");
        assertTrue(minDistance >= 0.01, "no two plants closer than 1 cm: " + minDistance);
    }

    /**
     * The density inside the tiles (1 m from any border), per m², and the densities of the 1 m bands
     * just before and just after the inner borders (all six lines together), as shares of it.
     */
    static double[] bandDensities(Block b) {
        double lo = FIRST * TILE;
        double hi = lo + TILES * TILE;
        int before = 0;
        int after = 0;
        int interior = 0;
        for (int p = 0; p < b.n(); p++) {
            double x = b.x()[p];
            double z = b.z()[p];
            double fx = Math.floorMod((long) Math.floor(x - lo), (long) TILE) + (x - Math.floor(x));
            double fz = Math.floorMod((long) Math.floor(z - lo), (long) TILE) + (z - Math.floor(z));
            if (fx >= 1 && fx < TILE - 1 && fz >= 1 && fz < TILE - 1) {
                interior++;
            }
            // a plant near a vertical inner border counts in that border's band (and likewise horizontal)
            if (x > lo + 1 && x < hi - 1) {
                if (fx >= TILE - 1) {
                    before++;
                } else if (fx < 1) {
                    after++;
                }
            }
            if (z > lo + 1 && z < hi - 1) {
                if (fz >= TILE - 1) {
                    before++;
                } else if (fz < 1) {
                    after++;
                }
            }
        }
        double bandArea = 2.0 * (TILES - 1) * (TILES * TILE); // per side: 3 lines each way, 64 m long
        double interiorDensity = interior / (TILES * TILES * (TILE - 2) * (TILE - 2));
        double beforeRatio = before / bandArea / interiorDensity;
        double afterRatio = after / bandArea / interiorDensity;
        return new double[] {interiorDensity, beforeRatio, afterRatio};
    }

    /** The distance of the closest two plants; fails when two footprints overlap (across borders too). */
    static double minDistanceAndNoOverlap(Block b, Grid g) {
        double min = Double.POSITIVE_INFINITY;
        for (int p = 0; p < b.n(); p++) {
            int ci = g.cell(b.x()[p]);
            int cj = g.cell(b.z()[p]);
            for (int j = Math.max(0, cj - 1); j <= Math.min(g.side - 1, cj + 1); j++) {
                for (int i = Math.max(0, ci - 1); i <= Math.min(g.side - 1, ci + 1); i++) {
                    for (int q = g.head[j * g.side + i]; q >= 0; q = g.next[q]) {
                        if (q > p) {
                            double d = Math.hypot(b.x()[q] - b.x()[p], b.z()[q] - b.z()[p]);
                            min = Math.min(min, d);
                            // float positions: allow a micrometre of rounding
                            double rr = FOOTPRINT[b.species()[p]] + FOOTPRINT[b.species()[q]] - 1e-6;
                            if (d < rr) {
                                throw new AssertionError("footprints overlap: plants at (" + b.x()[p] + ", "
                                        + b.z()[p] + ") and (" + b.x()[q] + ", " + b.z()[q] + "), " + d + " m apart");
                            }
                        }
                    }
                }
            }
        }
        return min;
    }

    @Test
    void benchThirtyTwoMetreTilesOnRollingHills() {
        RollingTerrain hills = RollingTerrain.gentle(7);
        ResourceFunction wet = (x, z) -> 0.5 + 0.5 * Math.sin(x / 23) * Math.cos(z / 31);
        List<DistributionDef> defs = List.of(
                meadow().get(0).toBuilder().water(0.3, 1).maxSlope(0.3).build(),
                meadow().get(1),
                meadow().get(2).toBuilder().water(0, 0.8).build());
        TilePlacer placer = new TilePlacer(99, 32, defs, SPECIES, hills, wet, null);
        for (int w = 0; w < 10; w++) {
            placer.place(100 + w, -7); // warm-up
        }
        int tiles = 16;
        long plants = 0;
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        long c0 = mx.getCurrentThreadCpuTime();
        long t0 = System.nanoTime();
        for (int t = 0; t < tiles; t++) {
            plants += placer.place(t % 4, t / 4).count();
        }
        double ms = (System.nanoTime() - t0) / 1e6 / tiles;
        double cpuMs = (mx.getCurrentThreadCpuTime() - c0) / 1e6 / tiles; // less disturbed by other processes
        System.out.printf(Locale.ROOT, "[bench] 32 m tile (meadow-like, 3 distributions, rolling hills, water"
                + " limits, reach %.1f m): %.1f ms per tile (%.1f ms CPU), %d plants per tile, one thread%n",
                placer.reach(), ms, cpuMs, plants / tiles);
        assertTrue(plants > 0);
    }
}
