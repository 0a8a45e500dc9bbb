package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.terrain.DistributionDef;
import org.junit.jupiter.api.Test;

/** Distance thinning of the draw decision: drawn counts fall as set, the same plants stay, off is bit-identical. */
class ThinningTest {
    private static World world;
    private static SimulationDef def;

    /** C1's terrain and species with 2,400 small-footprint plants, so that distance shells hold many. */
    static synchronized World world() throws Exception {
        if (world == null) {
            SimulationDef c1 = SimFixtures.scene().simulationDef();
            List<DistributionDef> dists = new ArrayList<>();
            for (DistributionDef d : c1.distributions()) {
                dists.add(d.toBuilder().count(800).footprint(0.12).waterUse(0).nutrientUse(0).build());
            }
            def = new SimulationDef(c1.terrain(), c1.species(), dists, c1.placements(), c1.flows(), c1.field(),
                    c1.animation(), c1.seed());
            world = World.build(def, Path.of("scenes"), 2, Progress.NONE);
        }
        return world;
    }

    /** From one corner, looking across the field, level. */
    static ViewCamera camera(double dx) {
        ViewCamera cam = new ViewCamera();
        cam.setPosition(-11 + dx, 1.7, 11);
        cam.setOrientation(Math.toRadians(45), Math.toRadians(-5));
        cam.setLens(Math.toRadians(80), 16.0 / 9, 0.1, 500);
        return cam;
    }

    static Frame decide(DrawDecision dd, ViewCamera cam) {
        return dd.decideAll(cam, new Frame(world.plantCount(), world.bendGeometry()));
    }

    static double distance(int p, ViewCamera cam) {
        double dx = world.plantX(p) - cam.x();
        double dy = world.plantY(p) - cam.y();
        double dz = world.plantZ(p) - cam.z();
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    @Test
    void offByDefaultAndWithFractionOneFramesAreBitIdentical() throws Exception {
        World w = world();
        ViewCamera cam = camera(0);
        DrawDecision plain = DrawDecision.of(w);
        assertEquals(1.0, plain.thinMinFraction());
        assertEquals(ForceFieldDef.DEFAULT_THIN_START, plain.thinStart());
        Frame a = decide(plain, cam);
        DrawDecision one = DrawDecision.of(w);
        one.setThinning(2, 4, 1);
        Frame b = decide(one, cam);
        for (int p = 0; p < w.plantCount(); p++) {
            assertEquals(a.drawLevel(p), b.drawLevel(p));
            assertEquals(a.drawKeep(p), b.drawKeep(p));
        }
    }

    @Test
    void drawnCountsFallAsSetAndTheSamePlantsStay() throws Exception {
        World w = world();
        ViewCamera cam = camera(0);
        Frame full = decide(DrawDecision.of(w), cam);
        DrawDecision dd = DrawDecision.of(w);
        double start = 6;
        double end = 18;
        double min = 0.25;
        dd.setThinning(start, end, min);
        Frame thin = decide(dd, cam);
        int nearSeen = 0;
        int[] seen = new int[4];
        int[] drawn = new int[4];
        for (int p = 0; p < w.plantCount(); p++) {
            if (full.drawLevel(p) < 0) {
                assertEquals(-1, thin.drawLevel(p), "thinning never adds a plant");
                continue;
            }
            double d = distance(p, cam);
            double r = (1 + DrawDecision.THIN_FADE) * dd.thinKept(d);
            boolean kept = thin.drawLevel(p) >= 0;
            // the plants whose fixed rank lies below the reach are drawn, the others not
            double h = DrawDecision.thinRank(p);
            if (d > start && h >= r) {
                assertTrue(!kept, () -> "plant at " + d + " m rank " + h + " reach " + r + " is drawn");
            } else if (d <= start || h < r - 2 * DrawDecision.THIN_FADE / 255) {
                assertTrue(kept, () -> "plant at " + d + " m rank " + h + " reach " + r + " is not drawn");
            }
            if (d <= start) {
                nearSeen++;
                assertEquals(full.drawLevel(p), thin.drawLevel(p));
                assertEquals(full.drawKeep(p), thin.drawKeep(p), "untouched before thinStart");
            } else if (kept && DrawDecision.thinRank(p) < r - DrawDecision.THIN_FADE) {
                assertEquals(full.drawKeep(p), thin.drawKeep(p), "fully kept plants keep their windows");
            }
            int shell = d <= start ? 0 : d < (start + end) / 2 ? 1 : d < end ? 2 : 3;
            seen[shell]++;
            drawn[shell] += kept ? 1 : 0;
        }
        assertTrue(nearSeen > 50 && seen[3] > 300, nearSeen + " near, " + seen[3] + " far");
        assertEquals(seen[0], drawn[0]);
        double[] share = new double[4];
        for (int s = 0; s < 4; s++) {
            share[s] = (double) drawn[s] / seen[s];
        }
        assertTrue(share[1] > share[2] && share[2] > share[3], java.util.Arrays.toString(share));
        // beyond thinEnd the drawn share is min(1, (1 + fade) min) up to sampling noise
        double expect = (1 + DrawDecision.THIN_FADE) * min;
        assertTrue(Math.abs(share[3] - expect) < 4 * Math.sqrt(expect * (1 - expect) / seen[3]),
                share[3] + " vs " + expect);
        // the kept share is smooth and hits its ends
        assertEquals(1.0, dd.thinKept(start));
        assertEquals(min, dd.thinKept(end), 1e-12);
        assertEquals((1 + min) / 2, dd.thinKept((start + end) / 2), 1e-12);

        // the camera moves: far plants that stay drawn are the same ones (a subset chosen by rank alone)
        Frame moved = decide(dd, camera(0.5));
        for (int p = 0; p < w.plantCount(); p++) {
            if (moved.drawLevel(p) >= 0 && distance(p, camera(0.5)) > end) {
                assertTrue(DrawDecision.thinRank(p) < expect, "only low-rank plants are drawn far away");
            }
        }
    }

    @Test
    void fadingPlantsKeepAShareOfTheirFragments() {
        int full = 255;
        assertEquals(256 * 0 + 128, DrawDecision.scaleKeep(full, 0.5));
        int twoLevels = (256 * 100 + 255) | ((256 * 0 + 100) << 16);
        int half = DrawDecision.scaleKeep(twoLevels, 0.5);
        assertEquals(256 * 50 + 128, half & 0xFFFF);
        assertEquals(50, half >>> 16, "the windows still tile, now [0, 128)");
        assertEquals(0, DrawDecision.scaleKeep(full, 0.001));
    }

    @Test
    void simulationFramesAreThreadCountIndependentAndTheSceneSettingApplies() throws Exception {
        World w = world();
        ForceFieldDef f = def.field();
        SimulationDef thinDef = new SimulationDef(def.terrain(), def.species(), def.distributions(), def.placements(),
                def.flows(), ForceFieldDef.builder().enabled(f.enabled()).maxObjectsPerNode(f.maxObjectsPerNode())
                        .maxDepth(f.maxDepth()).lodDistances(f.lodDistances()).thinning(5, 15, 0.3).build(),
                        def.animation(), def.seed());
        Frame[] frames = new Frame[2];
        int[] threads = {1, 3};
        for (int i = 0; i < 2; i++) {
            try (Simulation sim = Simulation.of(w, thinDef, threads[i], SimFixtures.CHUNK)) {
                assertEquals(5, sim.inspect().thinStart());
                assertEquals(15, sim.inspect().thinEnd());
                assertEquals(0.3, sim.inspect().thinMinFraction());
                for (int k = 0; k < 30; k++) {
                    sim.step(1.0 / 60 + 1e-9, camera(0.01 * k));
                }
                frames[i] = sim.copyLatestFrame(new Frame(w.plantCount(), w.bendGeometry()));
                int far = 0;
                int farDrawn = 0;
                for (int p = 0; p < w.plantCount(); p++) {
                    if (frames[i].plantVisible(p) && distance(p, camera(0.29)) > 16) {
                        far++;
                        farDrawn += frames[i].drawLevel(p) >= 0 ? 1 : 0;
                    }
                }
                assertTrue(far > 100 && farDrawn < 0.45 * far, farDrawn + " of " + far + " far plants drawn");
                sim.setThinning(5, 15, 1);
                sim.step(1.0 / 60 + 1e-9, camera(0.3));
                sim.step(1.0 / 60 + 1e-9, camera(0.3));
                assertEquals(1.0, sim.inspect().thinMinFraction());
            }
        }
        byte[] l0 = new byte[w.plantCount()];
        byte[] l1 = new byte[w.plantCount()];
        int[] k0 = new int[w.plantCount()];
        int[] k1 = new int[w.plantCount()];
        for (int p = 0; p < w.plantCount(); p++) {
            l0[p] = (byte) frames[0].drawLevel(p);
            l1[p] = (byte) frames[1].drawLevel(p);
            k0[p] = frames[0].drawKeep(p);
            k1[p] = frames[1].drawKeep(p);
        }
        assertArrayEquals(l0, l1);
        assertArrayEquals(k0, k1);
    }

    @Test
    void badSettingsAreRefused() throws Exception {
        DrawDecision dd = DrawDecision.of(world());
        assertThrows(IllegalArgumentException.class, () -> dd.setThinning(10, 5, 0.5));
        assertThrows(IllegalArgumentException.class, () -> dd.setThinning(-1, 5, 0.5));
        assertThrows(IllegalArgumentException.class, () -> dd.setThinning(1, 5, 1.5));
        assertThrows(IllegalArgumentException.class, () -> dd.setThinning(1, 5, Double.NaN));
    }
}
