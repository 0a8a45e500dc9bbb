package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import org.junit.jupiter.api.Test;

/**
 * Issue 41, "Done when", from 15 m up and oblique (the camera of {@link BeyondTerrainTest}, 480x270): the
 * meadow in its own wind (the simulation stepping at its fixed step) does not shimmer: of the pixels whose
 * luma changed by more than 2/255 from one frame to the next, at most 30% change back the other way (by
 * more than 2/255) in the frame after. A picture that flickers (sub-pixel blades aliasing as they sway)
 * reverses about half its changes; wind that moves the light along reverses few.
 */
class FromAboveFlickerTest {
    private static final int W = 480;
    private static final int H = 270;
    private static final int FRAMES = 10;

    @Test
    void fromFifteenMetresUpFewChangesReverse() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        Heightfield hf = world.terrain().heightfield();
        double cx = hf.minX() + hf.sizeX() / 2;
        double cz = hf.minZ() + hf.sizeZ() / 2;
        double gy = hf.height(cx, cz);
        ViewCamera cam = Shots.lookAt(cx, gy + 15, cz + 10, cx, gy, cz - 30, Math.toRadians(50), W / (double) H, 0.05,
                1000);
        long changing = 0;
        long reversing = 0;
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H);
             Simulation sim = Simulation.of(world, def.simulationDef(), 2)) {
            int[] prev = null;
            int[] prevDelta = null;
            for (int f = 0; f < FRAMES; f++) {
                sim.stepFixed(cam);
                Img img = s.render(sim.latestFrame(), cam, true, true);
                int[] luma = new int[W * H];
                for (int i = 0; i < luma.length; i++) {
                    luma[i] = (int) Math.round(ImageMetrics.luma(img.rgb()[i]));
                }
                if (prev != null) {
                    int[] delta = new int[W * H];
                    for (int k = 0; k < delta.length; k++) {
                        delta[k] = luma[k] - prev[k];
                        if (prevDelta != null && Math.abs(prevDelta[k]) > 2) {
                            changing++;
                            if (Math.abs(delta[k]) > 2 && Integer.signum(delta[k]) != Integer.signum(prevDelta[k])) {
                                reversing++;
                            }
                        }
                    }
                    prevDelta = delta;
                }
                prev = luma;
            }
        }
        double share = changing == 0 ? 0 : reversing / (double) changing;
        System.out.printf(Locale.ROOT, "[look] meadow from 15 m up in its wind: %d pixel changes over 2/255 in %d frames, "
                + "%.3f of them reversed in the next frame (<= 0.3)%n", changing, FRAMES, share);
        assertTrue(changing > 1000, "the meadow moves in the wind: " + changing + " changes");
        assertTrue(share <= 0.3, "frame-to-frame reversals from 15 m up: " + share);
    }
}
