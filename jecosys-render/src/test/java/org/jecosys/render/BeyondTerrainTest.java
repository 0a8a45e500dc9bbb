package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import org.junit.jupiter.api.Test;

/**
 * Issue 41, "the world beyond the terrain", from 15 m up and oblique over the meadow (480x270): the ground
 * beyond the terrain's square (every pixel whose world point lies more than 5 m outside it, the horizon
 * skirt) is still in the wind (two frames of a travelling breeze 1 s apart differ there by under 0.5/255 on
 * average) and carries no streaks (the mean absolute difference of a pixel from its left and right
 * neighbours' mean, across the rows of that band, at most 1/255; the clamped rim of the cover map used
 * to smear into streaks toward the horizon that swayed with the wind).
 */
class BeyondTerrainTest {
    private static final int W = 480;
    private static final int H = 270;

    @Test
    void theGroundBeyondTheTerrainIsStillAndHasNoStreaks() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        Heightfield hf = world.terrain().heightfield();
        ViewCamera cam = Shots.fromAbove(hf, W, H);
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            double[] p = s.points(TestFrames.wind(world, 0, cam), cam, false);
            boolean[] beyond = new boolean[W * H];
            int n = 0;
            for (int i = 0; i < beyond.length; i++) {
                double x = p[3 * i];
                double z = p[3 * i + 2];
                beyond[i] = !Double.isNaN(x) && (x < hf.minX() - 5 || x > hf.minX() + hf.sizeX() + 5
                        || z < hf.minZ() - 5 || z > hf.minZ() + hf.sizeZ() + 5);
                n += beyond[i] ? 1 : 0;
            }
            Img a = s.render(TestFrames.wind(world, 0, cam), cam, true, true);
            Img b = s.render(TestFrames.wind(world, 1, cam), cam, true, true);
            double change = 0;
            double streak = 0;
            int ns = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    int i = y * W + x;
                    if (!beyond[i]) {
                        continue;
                    }
                    change += Math.abs(ImageMetrics.luma(a.at(x, y)) - ImageMetrics.luma(b.at(x, y)));
                    if (x > 0 && x < W - 1 && beyond[i - 1] && beyond[i + 1]) {
                        streak += Math.abs(ImageMetrics.luma(a.at(x, y))
                                - 0.5 * (ImageMetrics.luma(a.at(x - 1, y)) + ImageMetrics.luma(a.at(x + 1, y))));
                        ns++;
                    }
                }
            }
            change /= Math.max(1, n);
            streak /= Math.max(1, ns);
            System.out.printf(Locale.ROOT, "[look] beyond the terrain from 15 m up: %d pixels; change in 1 s of wind "
                    + "%.3f/255, horizontal high-pass %.3f/255%n", n, change, streak);
            assertTrue(n > 2000, "the view shows the ground beyond the terrain: " + n + " pixels");
            assertTrue(change < 0.5, "the ground beyond the terrain is still in the wind: " + change);
            assertTrue(streak <= 1, "no streaks beyond the terrain: " + streak);
        }
    }
}
