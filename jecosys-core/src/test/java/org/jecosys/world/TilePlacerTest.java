package org.jecosys.world;

import org.jecosys.math.HeightFunction;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.jecosys.math.Rng;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.terrain.Heightfield;
import org.junit.jupiter.api.Test;

/** {@link TilePlacer}: a tile is a pure function of its inputs; the ground and the soil are obeyed. */
class TilePlacerTest {
    /** A game's own ground. */
    static final HeightFunction WAVES = (x, z) -> 0.5 * Math.sin(x / 3) + 0.3 * Math.cos(z / 5);

    static TilePlacer meadow(long seed, double tile) {
        return new TilePlacer(seed, tile, TileSeamTest.meadow(), TileSeamTest.SPECIES, WAVES);
    }

    static void assertSame(TilePlants a, TilePlants b) {
        assertEquals(a.tileI(), b.tileI());
        assertEquals(a.tileJ(), b.tileJ());
        assertTrue(a.count() > 0, "the tile has plants");
        assertTrue(Arrays.equals(a.x(), b.x()) && Arrays.equals(a.y(), b.y()) && Arrays.equals(a.z(), b.z())
                && Arrays.equals(a.species(), b.species()) && Arrays.equals(a.variantSeed(), b.variantSeed())
                && Arrays.equals(a.azimuth(), b.azimuth()), "identical arrays");
    }

    @Test
    void aTileIsTheSameWhateverWasPlacedBeforeAndInWhicheverOrder() throws Exception {
        TilePlants alone = meadow(5, 12).place(3, -2);
        TilePlacer afterNeighbours = meadow(5, 12);
        for (int j = -3; j <= -1; j++) {
            for (int i = 2; i <= 4; i++) {
                if (i != 3 || j != -2) {
                    afterNeighbours.place(i, j);
                }
            }
        }
        assertSame(alone, afterNeighbours.place(3, -2));
        TilePlacer reversed = meadow(5, 12);
        for (int j = -1; j >= -3; j--) {
            for (int i = 4; i >= 2; i--) {
                TilePlants t = reversed.place(i, j);
                if (i == 3 && j == -2) {
                    assertSame(alone, t);
                }
            }
        }
        TilePlacer busy = meadow(5, 12);
        Rng rng = new Rng(1);
        for (int k = 0; k < 200; k++) {
            busy.place(rng.nextInt(41) - 20, rng.nextInt(41) - 20);
        }
        assertSame(alone, busy.place(3, -2));
        // on worker threads, all at once
        ExecutorService pool = Executors.newFixedThreadPool(2);
        try {
            List<Future<TilePlants>> runs = new ArrayList<>();
            for (int k = 0; k < 4; k++) {
                runs.add(pool.submit(() -> busy.place(3, -2)));
            }
            for (Future<TilePlants> f : runs) {
                assertSame(alone, f.get());
            }
        } finally {
            pool.shutdown();
        }
        // another seed, another tile
        assertFalse(Arrays.equals(alone.x(), meadow(6, 12).place(3, -2).x()));
        assertFalse(Arrays.equals(alone.x(), meadow(5, 12).place(3, -1).x()));
    }

    @Test
    void placingAgainReusesTheCandidateBuffers() {
        TilePlacer p = meadow(5, 12);
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean)
                java.lang.management.ManagementFactory.getThreadMXBean();
        long id = Thread.currentThread().getId();
        long first = mx.getThreadAllocatedBytes(id);
        TilePlants a = p.place(3, -2);
        long firstBytes = mx.getThreadAllocatedBytes(id) - first;
        p.place(4, -2);
        long again = mx.getThreadAllocatedBytes(id);
        TilePlants b = p.place(3, -2);
        long againBytes = mx.getThreadAllocatedBytes(id) - again;
        assertSame(a, b);
        // the tile's own arrays: x, y, z, azimuth (4 bytes), species (4) and variant seeds (8) per plant
        long tile = 24L * a.count();
        System.out.printf("[placer] a %d-plant tile: %d bytes placed first, %d placed again (its arrays %d)%n",
                a.count(), firstBytes, againBytes, tile);
        assertTrue(againBytes < tile + 64 * 1024 && againBytes < firstBytes / 4, "placing a tile again allocated "
                + againBytes + " bytes (the first time " + firstBytes + ", its arrays " + tile + ")");
    }

    @Test
    void theReachGivesTheSamePlantsAsTheWholeHalo() {
        TilePlacer near = new TilePlacer(17, 24, TileSeamTest.meadow(), TileSeamTest.SPECIES, WAVES, null, null, false);
        TilePlacer whole = new TilePlacer(17, 24, TileSeamTest.meadow(), TileSeamTest.SPECIES, WAVES, null, null, true);
        assertEquals(9.6, near.reach(), 1e-9);
        assertEquals(24 - 3 * 0.12, whole.reach(), 1e-9);
        for (int k = 0; k < 3; k++) {
            assertSame(whole.place(k, -k), near.place(k, -k));
        }
    }

    @Test
    void plantsLieInTheirTileAndStandOnTheGamesGround() {
        TilePlacer placer = meadow(11, 12);
        int plants = 0;
        for (int j = -1; j <= 0; j++) {
            for (int i = -1; i <= 0; i++) {
                TilePlants t = placer.place(i, j);
                for (int p = 0; p < t.count(); p++) {
                    double x = t.x()[p];
                    double z = t.z()[p];
                    assertTrue(x >= i * 12.0 && x <= (i + 1) * 12.0 && z >= j * 12.0 && z <= (j + 1) * 12.0,
                            "(" + x + ", " + z + ") in tile " + i + ", " + j);
                    assertEquals(WAVES.height(x, z), t.y()[p], 0.01, "y on the ground");
                    assertTrue(t.azimuth()[p] >= 0 && t.azimuth()[p] < 2 * Math.PI);
                    assertTrue(t.species()[p] >= 0 && t.species()[p] <= 2);
                }
                plants += t.count();
            }
        }
        assertTrue(plants > 4 * 144 * 5, "about the meadow's density: " + plants);
    }

    @Test
    void slopeAltitudeAndWaterLimitsHold() {
        // WAVES: slope up to atan(0.177) = 0.175 rad; heights in [-0.8, 0.8]
        ResourceFunction water = (x, z) -> 0.5 + 0.5 * Math.sin(x / 7);
        List<DistributionDef> defs = List.of(
                DistributionDef.builder("steep-shy").density(2).footprint(0.05).maxSlope(0.12).build(),
                DistributionDef.builder("lowland").density(2).footprint(0.05).altitude(-10, 0.2).build(),
                DistributionDef.builder("wet").density(2).footprint(0.05).water(0.6, 1).build());
        TilePlacer placer = new TilePlacer(3, 16, defs, new int[] {0, 1, 2}, WAVES, water, null);
        int[] count = new int[3];
        for (int j = -1; j <= 0; j++) {
            for (int i = -1; i <= 0; i++) {
                TilePlants t = placer.place(i, j);
                for (int p = 0; p < t.count(); p++) {
                    double x = t.x()[p];
                    double z = t.z()[p];
                    count[t.species()[p]]++;
                    switch (t.species()[p]) {
                        case 0 -> {
                            double gx = 0.5 / 3 * Math.cos(x / 3);
                            double gz = -0.3 / 5 * Math.sin(z / 5);
                            assertTrue(Math.atan(Math.hypot(gx, gz)) <= 0.12 + 1e-3, "slope at " + x + ", " + z);
                        }
                        case 1 -> assertTrue(t.y()[p] <= 0.2 + 1e-6, "altitude " + t.y()[p]);
                        default -> assertTrue(water.level(x, z) >= 0.6, "water at " + x);
                    }
                }
            }
        }
        // each limit keeps some of the 2 per m² over 1024 m² but not all
        for (int s = 0; s < 3; s++) {
            assertTrue(count[s] > 200 && count[s] < 1800, "species " + s + ": " + count[s]);
        }
    }

    /**
     * Bunched tufts (issue 41) stream like the rest: a tile is the same whatever was placed before, its
     * plants stand in bunches on their tufts' rings (nearest plant of another bunch at the ring's chord
     * or further), and the halo grows by the ring, refused with its name where the tile is too small.
     */
    @Test
    void bunchedTuftsStreamAndReachByTheirRing() {
        DistributionDef def = DistributionDef.builder("crowns").density(2).footprint(0.004).tufts(0.005, 6)
                .bunches(0.2, 3).build();
        TilePlacer a = new TilePlacer(9, 8, List.of(def), new int[] {0}, WAVES);
        TilePlants alone = a.place(1, 1);
        TilePlacer b = new TilePlacer(9, 8, List.of(def), new int[] {0}, WAVES);
        b.place(2, 1);
        b.place(1, 2);
        assertSame(alone, b.place(1, 1));
        assertEquals(TilePlacer.TUFT_REACH * 0.005 + 0.2, TilePlacer.tuftReach(def), 1e-12);
        // within 5 cm: the same bunch; the next plant beyond that stands at least a chord of the ring away
        int n = alone.count();
        int far = 0;
        for (int i = 0; i < n; i++) {
            double best = Double.POSITIVE_INFINITY;
            for (int j = 0; j < n; j++) {
                double d = Math.hypot(alone.x()[j] - alone.x()[i], alone.z()[j] - alone.z()[i]);
                if (j != i && d >= 0.05) {
                    best = Math.min(best, d);
                }
            }
            far += best >= 2 * 0.2 * Math.sin(Math.toRadians(48)) - 0.03 ? 1 : 0;
        }
        assertTrue(n > 60, "the tile has plants: " + n);
        assertTrue(far >= 0.8 * n, far + " of " + n + " plants have no other bunch nearer than the ring's chord");
        DistributionDef wide = def.toBuilder().bunches(8, 3).build();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new TilePlacer(9, 8, List.of(wide), new int[] {0}, WAVES));
        assertTrue(e.getMessage().contains("tuftRing"), e.getMessage());
    }

    @Test
    void clumpsFollowAFieldOfWorldPosition() {
        DistributionDef def = DistributionDef.builder("patches").density(1).footprint(0.02).clump(1.5, 1).build();
        TilePlacer placer = new TilePlacer(8, 16, List.of(def), new int[] {4}, WAVES);
        int n = 0;
        for (int j = -2; j <= 1; j++) {
            for (int i = -2; i <= 1; i++) {
                TilePlants t = placer.place(i, j);
                for (int p = 0; p < t.count(); p++) {
                    assertEquals(4, t.species()[p]);
                    // strength 1: none where the field is 0
                    assertTrue(TilePlacer.clumpAcceptance(placer.clumpSeed(0), 1 / 3.0, 1, t.x()[p], t.z()[p]) > 0);
                }
                n += t.count();
            }
        }
        // the count is raised by the field's mean: about 1 per m² over 64 m x 64 m
        assertEquals(1, n / 4096.0, 0.2, "mean density of the clumped plants");
        // the same world with other tiles: the same clumps (the field does not depend on the tile)
        TilePlacer big = new TilePlacer(8, 32, List.of(def), new int[] {4}, WAVES);
        TilePlants t = big.place(0, 0);
        for (int p = 0; p < t.count(); p++) {
            assertTrue(TilePlacer.clumpAcceptance(placer.clumpSeed(0), 1 / 3.0, 1, t.x()[p], t.z()[p]) > 0);
        }
    }

    @Test
    void aHeightFunctionGivesNormals() {
        // a plane rising 0.5 m per metre along X: its normal leans back along -X
        HeightFunction plane = (x, z) -> 0.5 * x + 2;
        org.joml.Vector3f n = plane.normal(3, -7, new org.joml.Vector3f());
        assertEquals(1, n.length(), 1e-6);
        assertEquals(-0.5 / Math.sqrt(1.25), n.x, 1e-5);
        assertEquals(1 / Math.sqrt(1.25), n.y, 1e-5);
        assertEquals(0, n.z, 1e-6);
        assertEquals(Math.atan(0.5), plane.slope(3, -7), 1e-6);
        // the rolling hills' normals agree with their slope
        HeightFunction hills = RollingTerrain.gentle(5);
        for (int k = 0; k < 20; k++) {
            double x = 13.7 * k;
            double z = -9.1 * k;
            org.joml.Vector3f h = hills.normal(x, z, new org.joml.Vector3f());
            assertEquals(Math.cos(hills.slope(x, z)), h.y, 1e-5, "normal and slope at " + x + ", " + z);
        }
        // a heightfield through the interface gives its own blended vertex normals
        Heightfield hf = Heightfield.of(10, 10, 3, new float[] {0, 1, 2, 0, 1, 2, 0, 1, 2});
        HeightFunction f = hf;
        assertEquals(hf.normal(1, 1, new org.joml.Vector3f()), f.normal(1, 1, new org.joml.Vector3f()));
    }

    @Test
    void aHeightfieldIsAHeightFunction() {
        float[] h = {0, 1, 2, 3, 4, 5, 6, 7, 8};
        Heightfield hf = Heightfield.of(10, 10, 3, h);
        HeightFunction f = hf;
        for (int j = 0; j < 3; j++) {
            for (int i = 0; i < 3; i++) {
                assertEquals(hf.vertexHeight(i, j), f.height(-5 + 5 * i, -5 + 5 * j), 1e-9);
            }
        }
        assertEquals(hf.height(1.3, -2.7), f.height(1.3, -2.7));
        assertEquals(hf.slope(1.3, -2.7), f.slope(1.3, -2.7));
        assertEquals(1.5, f.height(2.5, -5), 1e-9); // half way between vertices (1, 0) and (2, 0)
        // plants stand on it through the interface
        TilePlacer placer = new TilePlacer(2, 5, List.of(TileSeamTest.meadow().get(2)), new int[] {0}, hf);
        TilePlants t = placer.place(0, -1);
        assertTrue(t.count() > 10);
        for (int p = 0; p < t.count(); p++) {
            assertEquals(hf.height(t.x()[p], t.z()[p]), t.y()[p], 1e-5);
        }
    }

    @Test
    void onlyDensitiesAreTakenAndTilesMustHoldTheFootprints() {
        DistributionDef counted = DistributionDef.builder("oak").count(100).footprint(0.5).build();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new TilePlacer(1, 32, List.of(counted), new int[] {0}, WAVES));
        assertTrue(e.getMessage().contains("'oak'"), e.getMessage());
        DistributionDef wide = DistributionDef.builder("tree").density(0.01).footprint(3).build();
        assertThrows(IllegalArgumentException.class, () -> new TilePlacer(1, 4, List.of(wide), new int[] {0}, WAVES));
        assertThrows(IllegalArgumentException.class, () -> new TilePlacer(1, 32, List.of(wide), new int[] {0, 1}, WAVES));
        assertThrows(IllegalArgumentException.class, () -> new TilePlacer(1, 32, List.of(), new int[] {}, WAVES));
        assertThrows(IllegalArgumentException.class, () -> new TilePlacer(1, 32, List.of(wide), new int[] {0}, null));
        DistributionDef dense = DistributionDef.builder("moss").density(10_000).footprint(0.001).build();
        assertThrows(IllegalArgumentException.class, () -> new TilePlacer(1, 64, List.of(dense), new int[] {0}, WAVES));
        assertEquals(32, new TilePlacer(1, 32, List.of(wide), new int[] {0}, WAVES).tileSize());
    }
}
