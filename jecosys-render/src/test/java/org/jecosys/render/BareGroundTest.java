package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;

/**
 * Issue 25, "Done when": no soil shows between the meadow's plants. In the default meadow view
 * (960x540) at most 5% of the lower half of the picture has the bare ground's own colour, and at most
 * 10% of the picture from 10 m straight above the meadow's middle (the gallery's top view). "The
 * ground's own colour" is that of the same view rendered without plants and ground cover
 * ({@link SceneRenderer#drawPlants} off: terrain, contact darkening and haze only): a pixel counts
 * as bare when no channel differs from it by more than {@link ImageMetrics#sameColour}'s margin
 * (3 levels or 6%, whichever is larger), so the plants' darkening of the soil does not count as
 * cover.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class BareGroundTest {
    private static final int W = 960;
    private static final int H = 540;

    private SceneDef def;
    private World world;
    private Shots shots;

    @BeforeAll
    void setUp() {
        def = RenderScenes.load("meadow.xml");
        world = RenderScenes.build(def);
        shots = new Shots(world, RenderScenes.settings(def), W, H);
    }

    @AfterAll
    void tearDown() {
        if (shots != null) {
            shots.close();
        }
    }

    /** Share of the rows [y0, y1) (from the bottom) whose pixels have the bare ground's own colour. */
    private double bare(ViewCamera cam, int y0, int y1) {
        Img full = shots.render(TestFrames.rest(world, cam), cam, true, true);
        Img ground = shots.render(TestFrames.rest(world, cam), cam, false, true);
        int n = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = 0; x < W; x++) {
                if (ImageMetrics.sameColour(full.at(x, y), ground.at(x, y))) {
                    n++;
                }
            }
        }
        return n / (double) ((y1 - y0) * W);
    }

    @Test
    void theDefaultViewShowsAlmostNoBareSoil() {
        double share = bare(RenderScenes.camera(def, world, W, H), 0, H / 2);
        System.out.printf("[look] meadow default view: %.1f%% of the lower half is bare ground (<= 5%%)%n",
                100 * share);
        assertTrue(share <= 0.05, String.format("%.1f%% of the lower half has the bare ground's colour, want <= 5%%",
                100 * share));
    }

    @Test
    void fromAboveLittleSoilShows() {
        double gy = world.terrain().heightfield().height(0, 0);
        ViewCamera top = new ViewCamera();
        top.setPosition(0, gy + 10, 0);
        top.setOrientation(0, -Math.PI / 2 + 1e-3);
        top.setLens(def.camera().fovY(), W / (double) H, 0.1, 200);
        double share = bare(top, 0, H);
        System.out.printf("[look] meadow from 10 m above: %.1f%% of the picture is bare ground (<= 10%%)%n",
                100 * share);
        assertTrue(share <= 0.10, String.format("%.1f%% of the top view has the bare ground's colour, want <= 10%%",
                100 * share));
    }
}
