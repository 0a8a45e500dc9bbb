package org.jecosys.world;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jecosys.terrain.DistributionDef;
import org.junit.jupiter.api.Test;

/**
 * The tiles around a walking view ({@link TileStreamer}): along a straight walk of 2.2 km at 10 m/s,
 * 30 updates a second, the tiles alive stay within the streamer's bound and the plants alive within
 * that many tiles' worth, every tile within the radius of the view is alive once the walk has passed
 * its start (nothing missing but the ones just started), tiles far behind are let go; a tile visited,
 * left 2 km behind and visited again on the way back is the same tile, array for array; the tiles are
 * the same with 1, 2 and 8 workers; with a latency, what is live at each update is the same for 1 and
 * 3 workers (the fixed rule of {@code sim.OpenWorld}).
 */
class TileStreamerTest {
    private static final double TILE = 16;
    private static final double RADIUS = 40;

    /** A light meadow: one spaced distribution, so that a long walk stays fast in the default run. */
    private static TilePlacer placer() {
        List<DistributionDef> defs = List.of(DistributionDef.builder("tufts").density(0.5).footprint(0.3).build());
        return new TilePlacer(11, TILE, defs, new int[] {0}, TilePlacerTest.WAVES);
    }

    @Test
    void aWalkKeepsTheTilesAroundTheViewAndLetsTheRestGo() {
        try (TileStreamer<TilePlants> s = TileStreamer.of(placer(), RADIUS, 2, 8)) {
            double[] x = {0};
            double[] z = {5};
            int maxTiles = 0;
            long maxPlants = 0;
            TilePlants first = null;
            int updates = 6600; // 220 s at 30 Hz: 2.2 km
            for (int u = 0; u <= updates; u++) {
                x[0] = u * (10.0 / 30);
                s.update(x, z, 1);
                if (u % 300 == 0) {
                    for (int k = 0; k < 10 && (k == 0 || s.pendingTiles() > 0); k++) {
                        s.settle(); // a slow machine must not fail the check below
                        s.update(x, z, 1);
                    }
                    s.settle();
                    assertNull(missingWithin(s, x[0], z[0], RADIUS - TILE), "every tile near the view is alive at "
                            + x[0] + " m");
                }
                maxTiles = Math.max(maxTiles, s.liveTiles());
                maxPlants = Math.max(maxPlants, s.livePlants());
                if (u == 300) {
                    first = s.tile(6, 0); // around x = 100 m
                    assertNotNull(first);
                }
            }
            assertNull(s.tile(6, 0), "a tile 2.1 km behind is let go");
            assertTrue(maxTiles <= s.maxLiveTiles(), "tiles alive " + maxTiles + " <= " + s.maxLiveTiles());
            double perTile = 0.5 * TILE * TILE;
            assertTrue(maxPlants <= 1.3 * perTile * s.maxLiveTiles(), "plants alive " + maxPlants);
            System.out.printf("[bench] tile streamer: 2.2 km walk, %d tiles built, at most %d alive (bound %d), at "
                    + "most %d plants alive%n", s.builtTiles(), maxTiles, s.maxLiveTiles(), maxPlants);
            // back to x = 100 m: the tile comes back the same
            x[0] = 100;
            s.update(x, z, 1);
            s.settle();
            TilePlants again = s.tile(6, 0);
            assertNotNull(again);
            assertTrue(again != first, "made again");
            assertArrayEquals(first.x(), again.x());
            assertArrayEquals(first.z(), again.z());
            assertArrayEquals(first.species(), again.species());
            assertArrayEquals(first.variantSeed(), again.variantSeed());
        }
    }

    @Test
    void theTilesAreTheSameWhateverTheWorkersAndTheBudget() {
        double[] x = {20};
        double[] z = {-30};
        try (TileStreamer<TilePlants> one = TileStreamer.of(placer(), RADIUS, 1, 1);
             TileStreamer<TilePlants> two = TileStreamer.of(placer(), RADIUS, 2, 3);
             TileStreamer<TilePlants> eight = TileStreamer.of(placer(), RADIUS, 8, 64)) {
            for (int u = 0; u < 40; u++) {
                one.update(x, z, 1);
            }
            one.settle();
            for (TileStreamer<TilePlants> other : List.of(two, eight)) {
                for (int u = 0; u < 20; u++) {
                    other.update(x, z, 1);
                }
                other.settle();
                assertEquals(one.liveTiles(), other.liveTiles());
            }
            assertTrue(one.liveTiles() > 20, "tiles around the view: " + one.liveTiles());
            for (int i = -4; i <= 4; i++) {
                for (int j = -6; j <= 2; j++) {
                    TilePlants a = one.tile(i, j);
                    for (TileStreamer<TilePlants> other : List.of(two, eight)) {
                        TilePlants b = other.tile(i, j);
                        assertEquals(a == null, b == null, "tile " + i + ", " + j);
                        if (a != null) {
                            assertArrayEquals(a.x(), b.x());
                            assertArrayEquals(a.species(), b.species());
                            assertArrayEquals(a.variantSeed(), b.variantSeed());
                        }
                    }
                }
            }
        }
    }

    /** The live tiles of a streamer, as "i,j" in its list order. */
    private static String liveKeys(TileStreamer<TilePlants> s) {
        StringBuilder b = new StringBuilder();
        for (int k = 0; k < s.liveTiles(); k++) {
            b.append(s.liveI(k)).append(',').append(s.liveJ(k)).append(' ');
        }
        return b.toString();
    }

    @Test
    void withALatencyWhatIsLiveDependsOnlyOnThePath() {
        double[] x = {0};
        double[] z = {0};
        TileFactory<TilePlants> f = new TileFactory<>() {
            private final TilePlacer placer = placer();

            @Override
            public TilePlants build(int i, int j) {
                return placer.place(i, j);
            }

            @Override
            public int plants(TilePlants tile) {
                return tile.count();
            }
        };
        try (TileStreamer<TilePlants> one = new TileStreamer<>(TILE, f, RADIUS, TILE, 1, 2, 5);
             TileStreamer<TilePlants> three = new TileStreamer<>(TILE, f, RADIUS, TILE, 3, 2, 5)) {
            int started = 0;
            for (int u = 0; u < 600; u++) { // 20 s at 30 Hz, 6 m/s: 120 m
                x[0] = u * 0.2;
                z[0] = u * 0.05;
                one.update(x, z, 1);
                three.update(x, z, 1);
                assertEquals(liveKeys(one), liveKeys(three), "live tiles at update " + u);
                started = Math.max(started, one.pendingTiles());
                for (int k = 0; k < one.liveTiles(); k++) {
                    double cx = Math.max(0, Math.max(one.liveI(k) * TILE - x[0], x[0] - (one.liveI(k) + 1) * TILE));
                    double cz = Math.max(0, Math.max(one.liveJ(k) * TILE - z[0], z[0] - (one.liveJ(k) + 1) * TILE));
                    assertTrue(Math.hypot(cx, cz) <= RADIUS + TILE + 1e-9, "a live tile lies within the radius "
                            + "plus one tile");
                }
            }
            assertTrue(started > 0, "tiles are started ahead of the radius");
            assertTrue(one.liveTiles() > 10, "tiles live: " + one.liveTiles());
        }
    }

    @Test
    void argumentsAreChecked() {
        assertThrows(IllegalArgumentException.class, () -> TileStreamer.of(placer(), 0, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> TileStreamer.of(placer(), 10, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> TileStreamer.of(placer(), 10, 1, 0));
        TileStreamer<TilePlants> s = TileStreamer.of(placer(), 10, 1, 1);
        s.close();
        assertThrows(IllegalStateException.class, () -> s.update(new double[] {0}, new double[] {0}, 1));
    }

    /** A tile within {@code within} of the view that is not alive, as "i, j", or null. */
    private static String missingWithin(TileStreamer<TilePlants> s, double vx, double vz, double within) {
        int i0 = (int) Math.floor((vx - within) / TILE);
        int i1 = (int) Math.floor((vx + within) / TILE);
        int j0 = (int) Math.floor((vz - within) / TILE);
        int j1 = (int) Math.floor((vz + within) / TILE);
        for (int i = i0; i <= i1; i++) {
            for (int j = j0; j <= j1; j++) {
                double dx = Math.max(0, Math.max(i * TILE - vx, vx - (i + 1) * TILE));
                double dz = Math.max(0, Math.max(j * TILE - vz, vz - (j + 1) * TILE));
                if (Math.hypot(dx, dz) <= within && s.tile(i, j) == null) {
                    return i + ", " + j;
                }
            }
        }
        return null;
    }
}
