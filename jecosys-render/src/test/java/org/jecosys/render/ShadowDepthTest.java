package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * Issue 41, "Done when": ground in a plant's shadow is at most half as bright as the same ground in the
 * sun (the meadow's sun, 28 degrees up). The meadow's start view at 480x270, the ground alone on the
 * screen (the plants still cast), rendered with the scene's shadows and with shadows off: per pixel
 * the ratio of the two lumas, over the ground the shadows darken by more than 5%; the core of the
 * plants' shadows, the darkest tenth of that ground, must keep at most half its sunlit brightness.
 */
class ShadowDepthTest {
    private static final int W = 480;
    private static final int H = 270;

    @Test
    void groundInAPlantsShadowIsAtMostHalfAsBright() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        RenderSettings settings = RenderScenes.settings(def);
        assertTrue(settings.shadows() > 0, "the meadow has shadows");
        Img lit;
        Img shaded;
        try (Shots s = new Shots(world, settings, W, H)) {
            ViewCamera cam = RenderScenes.camera(def, world, W, H);
            shaded = s.render(TestFrames.rest(world, cam), cam, false, true);
            settings.setShadows(0);
            lit = s.render(TestFrames.rest(world, cam), cam, false, true);
        }
        double[] ratios = new double[lit.rgb().length];
        int n = 0;
        for (int i = 0; i < ratios.length; i++) {
            double l = ImageMetrics.luma(lit.rgb()[i]);
            double r = ImageMetrics.luma(shaded.rgb()[i]) / Math.max(1, l);
            if (l >= 20 && r < 0.95) {
                ratios[n++] = r;
            }
        }
        double[] r = Arrays.copyOf(ratios, n);
        Arrays.sort(r);
        double core = r[Math.max(0, n / 10 - 1)];
        double median = r[n / 2];
        System.out.printf("[look] meadow ground in the plants' shadows (sun %.0f deg up): %d pixels darker by 5%% or "
                + "more (%.1f%% of the picture); the darkest tenth at %.2f of its sunlit brightness or less (<= 0.5), "
                + "median %.2f%n", Math.toDegrees(settings.lighting().sunElevation()), n,
                100.0 * n / ratios.length, core, median);
        assertTrue(n > 0.05 * ratios.length, "the plants shade the ground: " + n + " pixels");
        assertTrue(core <= 0.5, "ground in a plant's shadow keeps " + core + " of its sunlit brightness");
    }
}
