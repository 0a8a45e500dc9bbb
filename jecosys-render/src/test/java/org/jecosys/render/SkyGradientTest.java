package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Locale;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * Issue 41, "a sky without seams": the clear sky's gradient from the horizon colour to the zenith's has no
 * step of more than 1/255 from one row to the next (480x270; the sky alone, no ground), looking level and
 * from 15 m up at 30 degrees down, in every column (the 95th percentile over the columns of each column's
 * largest step of the green channel). The gradient once followed the square root of the height above the
 * horizon, whose slope is infinite there: a bright seam a few rows above the horizon.
 */
class SkyGradientTest {
    private static final int W = 480;
    private static final int H = 270;

    @Test
    void theSkyHasNoSeam() {
        SceneDef def = RenderScenes.load("c1.xml");
        World world = RenderScenes.build(def);
        ViewCamera level = Shots.lookAt(0, 1.6, 0, 0, 1.6, -10, Math.toRadians(50), W / (double) H, 0.05, 1000);
        ViewCamera above = Shots.lookAt(0, 15, 0, 0, 15 - 10 * Math.tan(Math.toRadians(30)), -10, Math.toRadians(50),
                W / (double) H, 0.05, 1000);
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            for (ViewCamera cam : new ViewCamera[] {level, above}) {
                Img img = s.render(TestFrames.rest(world, cam), cam, false, false);
                int[] worst = new int[W];
                for (int x = 0; x < W; x++) {
                    for (int y = 0; y + 1 < H; y++) {
                        int a = ImageMetrics.g(img.at(x, y));
                        int b = ImageMetrics.g(img.at(x, y + 1));
                        worst[x] = Math.max(worst[x], Math.abs(a - b));
                    }
                }
                Arrays.sort(worst);
                int p95 = worst[(int) (0.95 * (W - 1))];
                System.out.printf(Locale.ROOT, "[look] sky %s: largest step between rows, 95th percentile of the "
                        + "columns: %d/255%n", cam == level ? "level" : "from 15 m up", p95);
                assertTrue(p95 <= 1, "the sky gradient steps by " + p95 + "/255 between rows");
            }
        }
    }
}
