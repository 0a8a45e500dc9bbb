package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.World;
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
        ViewCamera cam = Shots.fromAbove(world.terrain().heightfield(), W, H);
        Reversals reversals = new Reversals(2);
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H);
             Simulation sim = Simulation.of(world, def.simulationDef(), 2)) {
            for (int f = 0; f < FRAMES; f++) {
                sim.stepFixed(cam);
                reversals.add(s.render(sim.latestFrame(), cam, true, true));
            }
        }
        long changing = reversals.changing();
        double share = reversals.share();
        System.out.printf(Locale.ROOT, "[look] meadow from 15 m up in its wind: %d pixel changes over 2/255 in %d frames, "
                + "%.3f of them reversed in the next frame (<= 0.3)%n", changing, FRAMES, share);
        assertTrue(changing > 1000, "the meadow moves in the wind: " + changing + " changes");
        assertTrue(share <= 0.3, "frame-to-frame reversals from 15 m up: " + share);
    }
}
