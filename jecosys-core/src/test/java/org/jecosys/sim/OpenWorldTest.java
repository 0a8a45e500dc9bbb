package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.Camera;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneFiles;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.world.RollingTerrain;
import org.jecosys.world.TilePlacer;
import org.junit.jupiter.api.Test;

/**
 * The open world's runtime ({@link OpenWorld}): the meadow's species streamed in tiles around a
 * walking camera. Along a walk the live tiles stay within the bound, the plants seen move in the
 * meadow's gust, tiles behind are let go; every tile's state is bit-identical for 1 and 3 animation
 * workers and 1 and 2 tile workers; a camera standing in its tiles steps without allocating.
 */
class OpenWorldTest {
    private static final double TILE = 16;
    private static final double RADIUS = 24;

    /** The meadow's species, flows, field and animation. */
    static SimulationDef meadowDef() throws Exception {
        return SceneFiles.read(Path.of("scenes", "meadow.xml")).def().simulationDef();
    }

    /** A light mix of the meadow's species (about 1.3 plants per m²), so that the walks stay fast. */
    static TilePlacer placer(SimulationDef def) {
        List<DistributionDef> d = List.of(
                DistributionDef.builder("grassA").density(1.0).footprint(0.08).tufts(0.12, 3).build(),
                DistributionDef.builder("flowerB").density(0.4).footprint(0.08).clump(2, 0.6).build());
        return new TilePlacer(def.seed(), TILE, d, new int[] {index(def, "grassA"), index(def, "flowerB")},
                GROUND);
    }

    /** The ground of every walk here. */
    static final RollingTerrain GROUND = RollingTerrain.gentle(2005);

    private static int index(SimulationDef def, String id) {
        for (int s = 0; s < def.species().size(); s++) {
            if (def.species().get(s).id().equals(id)) {
                return s;
            }
        }
        throw new IllegalArgumentException(id);
    }

    /** A camera at eye height over the ground at (x, z), looking along +X, slightly down. */
    static ViewCamera walker(double x, double z) {
        ViewCamera c = new ViewCamera();
        c.setPosition(x, GROUND.height(x, z) + 1.7, z);
        c.setOrientation(Math.PI / 2, Math.toRadians(-10));
        c.setLens(Math.toRadians(60), 16.0 / 9, 0.1, 500);
        return c;
    }

    /** Walks 60 m along X at 10 m/s, 30 steps a second; returns each live tile's state hash at the end. */
    private static List<String> walk(SimulationDef def, int workers, int tileWorkers) {
        List<String> hashes = new ArrayList<>();
        try (OpenWorld w = OpenWorld.create(def, placer(def), RADIUS, workers, tileWorkers, 4)) {
            for (int s = 0; s < 180; s++) {
                w.stepFixed(walker(s * 10.0 / 30, 3));
            }
            for (int k = 0; k < w.liveTiles(); k++) {
                WorldTile t = w.tile(k);
                hashes.add(t.i() + "," + t.j() + ":" + t.simulation().inspect().stateHash());
            }
        }
        return hashes;
    }

    @Test
    void aWalkKeepsTheTilesAroundTheCameraAndAnimatesWhatItSees() throws Exception {
        SimulationDef def = meadowDef();
        try (OpenWorld w = OpenWorld.create(def, placer(def), RADIUS, 2, 2, 4)) {
            int most = 0;
            long animated = 0;
            for (int s = 0; s < 600; s++) { // 20 s: 200 m
                double x = s * 10.0 / 30;
                w.stepFixed(walker(x, 3));
                most = Math.max(most, w.liveTiles());
                animated = Math.max(animated, w.animatedComponents());
                for (int k = 0; k < w.liveTiles(); k++) {
                    WorldTile t = w.tile(k);
                    double dx = Math.max(0, Math.max(t.i() * TILE - x, x - (t.i() + 1) * TILE));
                    double dz = Math.max(0, Math.max(t.j() * TILE - 3, 3 - (t.j() + 1) * TILE));
                    assertTrue(Math.hypot(dx, dz) <= RADIUS + TILE + 10.0 / 30 + 1e-9,
                            "tile " + t.i() + "," + t.j() + " is live " + Math.hypot(dx, dz) + " m from the camera");
                    assertEquals(w.time(), t.simulation().inspect().time(), 1e-9,
                            "every live tile's clock is the world's");
                }
            }
            assertTrue(most <= w.maxLiveTiles(), most + " tiles live, bound " + w.maxLiveTiles());
            assertTrue(w.liveTiles() >= 6, "the tiles within the radius are live: " + w.liveTiles());
            assertTrue(animated > 1000, "the plants the camera sees are animated: " + animated);
            assertTrue(w.livePlants() > 0 && w.liveComponents() > w.livePlants());
            // the plants in view move with the gust: a visible plant's component leaves its rest
            boolean bent = false;
            for (int k = 0; k < w.liveTiles() && !bent; k++) {
                Simulation sim = w.tile(k).simulation();
                for (int c = 0; c < sim.componentCount() && !bent; c++) {
                    bent = Math.hypot(sim.inspect().state().deviationX(c), sim.inspect().state().deviationZ(c)) > 1e-3;
                }
            }
            assertTrue(bent, "some component is bent by the wind");
        }
    }

    @Test
    void tilesNoViewSeesOnlyKeepTimeAndWakeWhenSeen() throws Exception {
        SimulationDef def = meadowDef();
        try (OpenWorld w = OpenWorld.create(def, placer(def), RADIUS, 2, 1, 8)) {
            ViewCamera c = walker(0, 3);
            for (int s = 0; s < 60; s++) {
                w.stepFixed(c);
            }
            w.settle();
            for (int s = 0; s < 5; s++) {
                w.stepFixed(c);
            }
            int idle = w.idleTiles();
            assertTrue(idle > 0 && idle < w.liveTiles(), "the tiles behind the camera only keep time: " + idle
                    + " of " + w.liveTiles());
            WorldTile behind = null;
            for (int k = 0; k < w.liveTiles(); k++) {
                if (w.tile(k).i() == -2 && w.tile(k).j() == 0) {
                    behind = w.tile(k);
                }
            }
            assertTrue(behind != null, "tile -2,0 is live");
            long before = behind.simulation().inspect().stateHash();
            for (int s = 0; s < 30; s++) {
                w.stepFixed(c);
            }
            assertEquals(before, behind.simulation().inspect().stateHash(), "a tile behind the camera rests");
            assertEquals(w.time(), behind.simulation().inspect().time(), 1e-9, "and keeps the world's time");
            c.setOrientation(-Math.PI / 2, Math.toRadians(-10)); // turn round: look along -X
            for (int s = 0; s < 3; s++) {
                w.stepFixed(c);
            }
            assertNotEquals(before, behind.simulation().inspect().stateHash(), "the tile seen again moves");
        }
    }

    @Test
    void everyTileIsTheSameForAnyNumberOfWorkers() throws Exception {
        SimulationDef def = meadowDef();
        List<String> one = walk(def, 1, 1);
        List<String> three = walk(def, 3, 2);
        assertTrue(one.size() >= 4, "tiles live at the end: " + one);
        assertEquals(one, three, "tile states with 1 and 3 animation workers, 1 and 2 tile workers");
    }

    @Test
    void aCameraStandingInItsTilesStepsWithoutAllocating() throws Exception {
        SimulationDef def = meadowDef();
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        try (OpenWorld w = OpenWorld.create(def, placer(def), RADIUS, 1, 1, 8)) {
            Camera c = walker(5, 3);
            for (int s = 0; s < 40; s++) {
                w.stepFixed(c);
            }
            w.settle(); // the tiles started ahead (within the radius plus one tile) are built and live too
            w.stepFixed(c);
            assertEquals(0, w.pendingTiles(), "every tile around the camera is live");
            for (int s = 0; s < 2000; s++) {
                w.stepFixed(c); // warm-up: the JIT (its compile requests allocate in the stepping thread for a while)
            }
            // the JIT's compile requests allocate in the thread that triggers them until it settles (later
            // on a loaded machine): windows of 100 steps until one allocates nothing, 30 at most; a step that
            // allocated by itself would fail every window
            long id = Thread.currentThread().getId();
            long bytes = -1;
            for (int window = 0; window < 30 && bytes != 0; window++) {
                long before = threads.getThreadAllocatedBytes(id);
                for (int s = 0; s < 100; s++) {
                    w.stepFixed(c);
                }
                bytes = threads.getThreadAllocatedBytes(id) - before;
            }
            assertEquals(0, bytes, "bytes allocated by 100 steps");
            assertNotEquals(0, w.animatedComponents());
        }
    }

    /**
     * The loading screen runs the def's prewarm after the start area is live: the meadow's 1 s is 60 fixed
     * steps more than the same load without it, and the plants then move step to step.
     */
    @Test
    void loadingRunsThePrewarmAfterTheStartAreaIsLive() throws Exception {
        SimulationDef def = meadowDef();
        assertEquals(60, def.animation().prewarmSteps(), "the meadow prewarms 1 s at 60 Hz");
        SimulationDef none = new SimulationDef(def.terrain(), def.species(), def.distributions(), def.placements(),
                def.flows(), def.field(), def.animation().withPrewarm(0), def.seed());
        long[] steps = new long[2];
        SimulationDef[] defs = {none, def};
        for (int k = 0; k < 2; k++) {
            try (OpenWorld w = OpenWorld.create(defs[k], placer(defs[k]), RADIUS, 2, 1, 8)) {
                w.load(walker(5, 3));
                assertEquals(0, w.pendingTiles(), "every tile around the camera is live");
                steps[k] = w.steps();
                assertEquals(steps[k] * defs[k].animation().fixedStep(), w.time(), 1e-9, "the clock");
            }
        }
        assertEquals(steps[0] + 60, steps[1], "load's steps without and with the prewarm");
    }

    @Test
    void badArgumentsAreRefused() throws Exception {
        SimulationDef def = meadowDef();
        assertThrows(IllegalArgumentException.class, () -> OpenWorld.create(def, placer(def), 0, 1, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> OpenWorld.create(def, placer(def), 10, 0, 1, 1));
        OpenWorld w = OpenWorld.create(def, placer(def), 10, 1, 1, 1);
        w.close();
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> w.stepFixed(walker(0, 0)));
        assertTrue(e.getMessage().contains("closed"), e.getMessage());
    }
}
