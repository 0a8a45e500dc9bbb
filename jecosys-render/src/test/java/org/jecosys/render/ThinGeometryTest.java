package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * Issue 13, "Done when": thin geometry does not break into dots. Of the vegetation pixels of the
 * meadow's and c2's default views (960x540), at most 0.5% are isolated: no vegetation among their 8
 * neighbours.
 */
class ThinGeometryTest {
    private static final int W = 960;
    private static final int H = 540;

    @Test
    void fewIsolatedVegetationPixelsInTheMeadow() {
        check("meadow.xml");
    }

    @Test
    void fewIsolatedVegetationPixelsInC2() {
        check("c2.xml");
    }

    private static void check(String scene) {
        SceneDef def = RenderScenes.load(scene);
        World world = RenderScenes.build(def);
        ViewCamera cam = RenderScenes.camera(def, world, W, H);
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            Shots.View v = s.view(TestFrames.rest(world, cam), cam);
            int all = ImageMetrics.count(v.vegetation());
            double share = ImageMetrics.isolatedShare(v.vegetation(), W, H);
            System.out.printf("[look] %s default view: %.2f%% of %d vegetation pixels isolated (<= 0.5%%)%n",
                    scene, 100 * share, all);
            assertTrue(all > 0, scene + ": no vegetation in view");
            assertTrue(share <= 0.005, String.format("%s: %.2f%% of %d vegetation pixels are isolated, want <= 0.5%%",
                    scene, 100 * share, all));
        }
    }
}
