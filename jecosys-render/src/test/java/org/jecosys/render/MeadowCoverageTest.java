package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * Issue 13, "Done when": the default meadow view is mostly vegetation (at least 60% of the lower half
 * of the picture, 960x540), and from above the plants grow in clumps: the variance of the plant count
 * across 1 m cells is at least twice that of a uniform random layout of as many plants over the same
 * cells. The clumping is computed from the plant positions (the World), not from an image: a picture
 * of a uniform random layout to compare with would need a second scene.
 */
class MeadowCoverageTest {
    private static final int W = 960;
    private static final int H = 540;
    /** The top view's square, metres on a side, centred on the middle of the meadow. */
    static final double TOP_SIDE = 16;

    @Test
    void vegetationCoversMostOfTheLowerHalfOfTheDefaultView() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        ViewCamera cam = RenderScenes.camera(def, world, W, H);
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            Shots.View v = s.view(TestFrames.rest(world, cam), cam);
            double cover = ImageMetrics.lowerHalfCoverage(v.vegetation(), W, H);
            System.out.printf("[look] meadow default view: vegetation %.1f%% of the lower half (>= 60%%)%n",
                    100 * cover);
            assertTrue(cover >= 0.60, String.format("vegetation covers %.1f%% of the lower half, want >= 60%%",
                    100 * cover));
        }
    }

    @Test
    void plantsGrowInClumps() {
        World world = RenderScenes.build(RenderScenes.load("meadow.xml"));
        double ratio = clumping(world, 0, 0, TOP_SIDE);
        System.out.printf("[look] meadow from above: 1 m cell count variance %.2fx a uniform random layout"
                + " (>= 2)%n", ratio);
        assertTrue(ratio >= 2, String.format("variance across 1 m cells is %.2fx that of a uniform random layout,"
                + " want >= 2", ratio));
    }

    /**
     * Variance of the plant count over the 1 m cells of a square, divided by the variance expected when
     * as many plants fall uniformly at random into those cells, {@code n/k (1 - 1/k)}.
     */
    static double clumping(World world, double cx, double cz, double side) {
        int k1 = (int) side;
        int[] counts = new int[k1 * k1];
        int n = 0;
        for (int p = 0; p < world.plantCount(); p++) {
            double x = world.plantX(p) - (cx - side / 2);
            double z = world.plantZ(p) - (cz - side / 2);
            if (x >= 0 && z >= 0 && x < k1 && z < k1) {
                counts[(int) z * k1 + (int) x]++;
                n++;
            }
        }
        int k = counts.length;
        double mean = n / (double) k;
        double var = 0;
        for (int c : counts) {
            var += (c - mean) * (c - mean);
        }
        var /= k;
        double uniform = mean * (1 - 1.0 / k);
        return uniform == 0 ? 0 : var / uniform;
    }
}
