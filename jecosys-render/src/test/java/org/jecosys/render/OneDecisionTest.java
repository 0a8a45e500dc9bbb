package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;
import org.jecosys.render.plant.PlantBatches;

/**
 * One visibility and level decision per frame: the simulation's workers make it as they animate, and
 * the renderer's lists hold exactly what the frame says (no GL context needed). Moving the bands in
 * one place, the simulation, moves the animation's levels and the drawn levels alike.
 */
class OneDecisionTest {
    private static ViewCamera camera() {
        ViewCamera c = new ViewCamera();
        c.setPosition(0, 2.5, 16);
        c.setOrientation(0, -0.15);
        c.setLens(Math.toRadians(60), 16 / 9.0, 0.1, 500);
        return c;
    }

    /** Checks the lists against the frame and returns the lines a draw would submit. */
    private static long checkListsFollowTheFrame(World world, Frame f, PlantBatches b) {
        b.update(f);
        int levelsMax = 8;
        int[][] expected = new int[b.speciesCount()][levelsMax];
        int drawn = 0;
        for (int p = 0; p < world.plantCount(); p++) {
            int l = f.drawLevel(p);
            if (l < 0) {
                continue;
            }
            drawn++;
            assertTrue(f.plantVisible(p), "plant " + p + " is drawn, so it was visible to the field and animated");
            assertEquals(f.plantLevel(p), l, "plant " + p + " is drawn at the level it was animated at");
            int s = world.plantSpecies(p);
            expected[s][l]++;
            if (f.drawKeep(p) >>> 16 != 0) {
                expected[s][l + 1]++;
            }
        }
        assertTrue(drawn > 10, "the camera sees part of C1: " + drawn);
        int components = 0;
        for (int s = 0; s < b.speciesCount(); s++) {
            for (int l = 0; l < b.levels(s); l++) {
                int li = b.list(s, l);
                assertEquals(expected[s][l], b.count(li), "species " + s + " level " + l);
                components += b.count(li) * b.slots(s);
                for (int i = 0; i < b.count(li); i++) {
                    int p = b.plant(li, i);
                    int keep = f.drawKeep(p);
                    assertEquals(l == f.drawLevel(p) ? keep & 0xFFFF : keep >>> 16, b.keepOf(li, i));
                }
            }
        }
        assertEquals(components, b.components(), "components drawn = the frame's, per level");
        return b.lineCount();
    }

    @Test
    void theRendererDrawsWhatTheFrameSaysAndTheBandsMoveInOnePlace() throws Exception {
        try (Simulation sim = Scenes.simulation(Path.of("scenes/c1.xml"), Progress.NONE)) {
            World world = sim.world();
            PlantBatches b = new PlantBatches(world);
            ViewCamera cam = camera();
            sim.step(0.1, cam);
            long lines = checkListsFollowTheFrame(world, sim.latestFrame(), b);
            double edge = sim.drawDecision().edge(0, 0);
            for (int s = 0; s < world.plants().species().size(); s++) {
                sim.setLodDistances(s, new double[] {2, 3});
            }
            sim.step(0.1, cam);
            assertEquals(2.0, sim.drawDecision().edge(0, 0), "the drawing reads the animation's bands");
            long nearer = checkListsFollowTheFrame(world, sim.latestFrame(), b);
            assertTrue(nearer > lines, "lines from 3 m on: " + nearer + " > " + lines);
            sim.setLodScale(20);
            sim.step(0.1, cam);
            assertEquals(40.0, sim.drawDecision().edge(0, 0), 1e-9, "the LOD scale moves both too");
            long scaled = checkListsFollowTheFrame(world, sim.latestFrame(), b);
            assertTrue(scaled < nearer, "fewer lines with the bands 20x farther: " + scaled);
            assertTrue(edge > 2, "C1's own first band ends at " + edge + " m");
            sim.setLodTransition(0);
            sim.step(0.1, cam);
            Frame f = sim.latestFrame();
            for (int p = 0; p < world.plantCount(); p++) {
                assertEquals(0, f.drawKeep(p) >>> 16, "no plant in two levels without a transition band");
            }
            checkListsFollowTheFrame(world, f, b);
        }
    }
}
