package org.jecosys.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.Rng;
import org.junit.jupiter.api.Test;

/**
 * The footprint classes change where discs are kept, never which ones clash: {@link OccupancyGrid#free}
 * answers as a scan of every disc does, for mixes of footprints from a millimetre to 100 m, discs on the
 * terrain's edges, touching discs and radii at the edges of a class.
 */
class OccupancyGridTest {
    /** The clash test of the grid, over every disc: the reference. */
    private static boolean freeByScan(float[] x, float[] z, float[] r, int n, double qx, double qz, double qr) {
        for (int p = 0; p < n; p++) {
            double dx = x[p] - qx;
            double dz = z[p] - qz;
            double s = r[p] + qr;
            if (dx * dx + dz * dz < s * s) {
                return false;
            }
        }
        return true;
    }

    private static void compareWithScan(double[] radii, long[] discs, long seed, int queries) {
        double size = 60;
        OccupancyGrid g = new OccupancyGrid(-size / 2, -size / 2, size, size, radii, discs);
        Rng rng = new Rng(seed);
        float[] x = new float[queries];
        float[] z = new float[queries];
        float[] r = new float[queries];
        int n = 0;
        int clashes = 0;
        for (int q = 0; q < queries; q++) {
            // a third of the points on an edge or a corner of the terrain, the rest anywhere
            float qx = (float) (rng.nextDouble() < 0.15 ? -size / 2 : (rng.nextDouble() - 0.5) * size);
            float qz = (float) (rng.nextDouble() < 0.15 ? size / 2 : (rng.nextDouble() - 0.5) * size);
            double qr = radii[rng.nextInt(radii.length)];
            boolean expected = freeByScan(x, z, r, n, qx, qz, qr);
            assertEquals(expected, g.free(qx, qz, qr), "query " + q + " at (" + qx + ", " + qz + ") radius " + qr);
            if (expected) {
                g.add(qx, qz, qr);
                x[n] = qx;
                z[n] = qz;
                r[n] = (float) qr;
                n++;
            } else {
                clashes++;
            }
        }
        assertTrue(n > 0 && clashes > 0, "both answers were exercised: " + n + " added, " + clashes + " clashes");
    }

    @Test
    void oneClassAnswersAsTheScanDoes() {
        compareWithScan(new double[] {0.3}, new long[] {3000}, 1, 6000);
    }

    @Test
    void aMixFromAMillimetreTo100MetresAnswersAsTheScanDoes() {
        double[] radii = {0.001, 0.05, 0.04, 0.15, 0.25, 0.5, 0.4, 1, 3, 20, 100};
        long[] discs = {500, 2000, 2000, 300, 100, 100, 100, 50, 10, 2, 1};
        compareWithScan(radii, discs, 2, 8000);
    }

    @Test
    void radiiAtTheEdgesOfAClassAndUnderstatedCountsStillAnswerAsTheScanDoes() {
        // 0.25 and 0.4999 share a class; 0.5 starts the next; the counts given are far too small
        double[] radii = {0.25, 0.4999, 0.5, Math.nextDown(1.0), 1};
        compareWithScan(radii, new long[] {1, 1, 0, 1, 1}, 3, 4000);
    }

    @Test
    void aLargeFootprintWithNoDiscsCostsTheSmallOnesNothing() {
        OccupancyGrid with = new OccupancyGrid(-50, -50, 100, 100, new double[] {0.05, 100}, new long[] {20000, 0});
        OccupancyGrid without = new OccupancyGrid(-50, -50, 100, 100, new double[] {0.05}, new long[] {20000});
        Rng rng = new Rng(4);
        for (int i = 0; i < 20000; i++) {
            double x = (rng.nextDouble() - 0.5) * 100;
            double z = (rng.nextDouble() - 0.5) * 100;
            boolean free = without.free(x, z, 0.05);
            assertEquals(free, with.free(x, z, 0.05));
            if (free) {
                with.add(x, z, 0.05);
                without.add(x, z, 0.05);
            }
        }
        assertEquals(without.visits(), with.visits(), "the empty 100 m class is never visited");
        assertTrue(without.visits() < 20 * 20000L, "a few buckets and discs per query: " + without.visits());
    }

    @Test
    void aClassHasAtMostSixteenBucketsPerDiscItMayHold() {
        OccupancyGrid g = new OccupancyGrid(0, 0, 1000, 1000, new double[] {0.01, 5}, new long[] {10, 3});
        assertEquals(2, g.classCount());
        assertTrue(g.bucketCount(0) <= 10 * OccupancyGrid.BUCKETS_PER_DISC, "10 discs of 1 cm: " + g.bucketCount(0));
        assertTrue(g.bucketCount(1) <= 3 * OccupancyGrid.BUCKETS_PER_DISC, "3 discs of 5 m: " + g.bucketCount(1));
        OccupancyGrid dense = new OccupancyGrid(0, 0, 100, 100, new double[] {0.0625}, new long[] {1_000_000});
        assertEquals(800 * 800, dense.bucketCount(0), "buckets of twice the radius when the discs are many");
    }

    @Test
    void aRadiusNotDeclaredIsRefused() {
        OccupancyGrid g = new OccupancyGrid(0, 0, 10, 10, new double[] {0.3}, new long[] {1});
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> g.add(1, 1, 0.35));
        assertTrue(e.getMessage().contains("radius 0.35 m was not declared"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> g.add(1, 1, 2));
        assertThrows(IllegalArgumentException.class,
                () -> new OccupancyGrid(0, 0, 10, 10, new double[] {0}, new long[] {1}));
    }
}
