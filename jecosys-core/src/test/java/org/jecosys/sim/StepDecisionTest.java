package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.ViewCamera;
import org.junit.jupiter.api.Test;

/**
 * The step's draw decision, with its shortcuts for chunks (the sphere test skipped for a chunk the
 * frustum holds whole, one level per species for a chunk all within one level's plain window), decides
 * every plant as the per-plant decision of {@link ViewDecision} does for the same camera: the same level
 * and dither window for each plant the field saw, -1 for the others. Checked from near cameras (chunks
 * across level edges and the frustum's planes), far ones (whole chunks in one level) and one in between.
 */
class StepDecisionTest {
    @Test
    void theStepDecidesAsThePerPlantDecision() throws Exception {
        World world = SimFixtures.world();
        ViewDecision reference = new ViewDecision(world);
        int compared = 0;
        int drawnFar = 0;
        try (Simulation sim = SimFixtures.c1(2)) {
            double[][] cams = {{0, 2, 12, 0, -0.3}, {3, 1.5, -4, 2.5, -0.2}, {0, 25, 0, 0, -1.5}, {0, 80, 0, 0.3, -1.5},
                {-20, 40, 30, 0.8, -0.9}};
            for (double[] c : cams) {
                ViewCamera cam = new ViewCamera();
                cam.setPosition(c[0], c[1], c[2]);
                cam.setOrientation(c[3], c[4]);
                cam.setLens(Math.toRadians(60), 16 / 9.0, 0.05, 400);
                // the step decides for the camera of the step before: two steps with it
                sim.stepFixed(cam);
                sim.stepFixed(cam);
                Frame f = sim.latestFrame();
                reference.decide(f, cam);
                for (int p = 0; p < world.plantCount(); p++) {
                    String at = "plant " + p + ", camera at (" + c[0] + ", " + c[1] + ", " + c[2] + ")";
                    if (!f.plantVisible[p]) {
                        assertEquals(-1, f.drawLevel(p), at);
                        continue;
                    }
                    assertEquals(reference.levels()[p], f.drawLevel(p), at);
                    assertEquals(reference.keeps()[p], f.drawKeep[p], at);
                    compared++;
                    drawnFar += c[1] >= 40 && f.drawLevel(p) >= 0 ? 1 : 0;
                }
            }
        }
        assertTrue(compared > 200 && drawnFar > 50, "compared " + compared + ", drawn from afar " + drawnFar);
    }
}
