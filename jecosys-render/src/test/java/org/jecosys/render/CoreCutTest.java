package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.render.internal.SceneParts;
import org.jecosys.render.plant.PlantRenderer;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * On a multisampled target the near plants are drawn in two passes, their opaque core and then their
 * blended fringe. The default keeps them apart without discarding (the core's alpha cut to 0 or 1
 * through alpha-to-coverage, leaving out in the vertex shader the blades and stems too thin anywhere to
 * have a core, and the fringe behind a strict depth test that the core's own fragments fail);
 * the split programs, which discard, are the reference ({@link PlantRenderer#setCoreCut}). The
 * meadow's start view at 960x540 and 4 samples must come out the same both ways but for rounding (the
 * split programs blend a core of alpha 0.996 or more, the cut writes it opaque): no pixel more than
 * 4/255 apart in any channel, fewer than 0.5% of them apart at all (measured: 83 pixels, at most 3/255,
 * with both fringes on pixel centres; 857 pixels, at most 3/255, when both were on the samples). A
 * fringe pass that blended the core again (a depth test that is not strict) changed 11,456 pixels by up
 * to 129/255; the split programs' fringe on pixel centres without its strict depth test, 954 by up to
 * 8/255.
 */
class CoreCutTest {
    private static final int W = 960;
    private static final int H = 540;

    @Test
    void cuttingTheCoresAlphaDrawsWhatTheSplitProgramsDraw() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        RenderSettings settings = RenderScenes.settings(def);
        try (Shots s = new Shots(world, settings, W, H)) {
            PlantRenderer plants = SceneParts.plants(s.renderer);
            ViewCamera cam = RenderScenes.camera(def, world, W, H);
            Frame frame = TestFrames.rest(world, cam);
            plants.setCoreCut(false);
            Img split = s.render(frame, cam, true, true);
            plants.setCoreCut(true);
            Img cut = s.render(frame, cam, true, true);
            int apart = 0;
            int most = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    int a = split.at(x, y);
                    int b = cut.at(x, y);
                    int d = Math.max(Math.abs(ImageMetrics.r(a) - ImageMetrics.r(b)), Math.max(
                            Math.abs(ImageMetrics.g(a) - ImageMetrics.g(b)), Math.abs(ImageMetrics.b(a) - ImageMetrics.b(b))));
                    apart += d > 0 ? 1 : 0;
                    most = Math.max(most, d);
                }
            }
            System.out.printf("[look] core by alpha cut vs split programs, 4 samples: %d pixels apart, at most %d/255%n",
                    apart, most);
            assertTrue(most <= 4 && apart < W * H / 200, "the two ways differ: " + apart + " pixels, up to " + most);
        }
    }
}
