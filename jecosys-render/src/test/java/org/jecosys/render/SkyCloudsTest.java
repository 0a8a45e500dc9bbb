package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * Issue 41, "a sky with clouds" ({@code <light clouds>}): the sky alone at 480x270. Looking 25 degrees up
 * with clouds 0.4, the pixels the clouds brighten by more than 20/255 over the clear sky cover 15 to 70%
 * of the picture, and the brightness along a row varies at least 3 times as much as the clear sky's
 * (whose gradient runs up the picture); looking level, in the 12 rows just above the horizon they thin
 * into the haze (under a third of that share).
 */
class SkyCloudsTest {
    private static final int W = 480;
    private static final int H = 270;

    @Test
    void cloudsCoverTheSkyAndThinIntoTheHaze() {
        SceneDef def = RenderScenes.load("c1.xml");
        World world = RenderScenes.build(def);
        RenderSettings clear = RenderScenes.settings(def);
        RenderSettings cloudy = RenderScenes.settings(def);
        cloudy.lighting().setClouds(0.4f);
        // 25 degrees up (the picture spans 0 to 50 degrees), and level (the horizon in the middle row)
        ViewCamera up = Shots.lookAt(0, 1.6, 0, 0, 1.6 + 10 * Math.tan(Math.toRadians(25)), -10, Math.toRadians(50),
                W / (double) H, 0.05, 1000);
        ViewCamera level = Shots.lookAt(0, 1.6, 0, 0, 1.6, -10, Math.toRadians(50), W / (double) H, 0.05, 1000);
        Img[] clearShots = shots(world, clear, up, level);
        Img[] cloudyShots = shots(world, cloudy, up, level);
        // looking up: the share the clouds brighten, and the brightness s.d. along each row (the clear sky's
        // gradient runs up the picture)
        long clouded = 0;
        double rowSdClear = 0;
        double rowSdCloudy = 0;
        for (int y = 0; y < H; y++) {
            double[] a = new double[3];
            double[] b = new double[3];
            for (int x = 0; x < W; x++) {
                double la = ImageMetrics.luma(clearShots[0].at(x, y));
                double lb = ImageMetrics.luma(cloudyShots[0].at(x, y));
                clouded += lb - la > 20 ? 1 : 0;
                a[0] += la;
                a[1] += la * la;
                b[0] += lb;
                b[1] += lb * lb;
            }
            rowSdClear += Math.sqrt(Math.max(0, a[1] / W - Math.pow(a[0] / W, 2))) / H;
            rowSdCloudy += Math.sqrt(Math.max(0, b[1] / W - Math.pow(b[0] / W, 2))) / H;
        }
        double share = clouded / (double) (W * H);
        // level: the 12 rows just above the horizon (Img rows run from the bottom)
        long low = 0;
        long lowClouded = 0;
        for (int y = H / 2 + 1; y < H / 2 + 13; y++) {
            for (int x = 0; x < W; x++) {
                low++;
                lowClouded += ImageMetrics.luma(cloudyShots[1].at(x, y)) - ImageMetrics.luma(clearShots[1].at(x, y)) > 20
                        ? 1 : 0;
            }
        }
        double lowShare = lowClouded / (double) low;
        System.out.printf(Locale.ROOT, "[look] clouds 0.4, looking 25 deg up: %.1f%% of the sky brighter by > 20/255, "
                + "brightness s.d. along a row %.1f (clear sky %.1f); just above the horizon %.1f%%%n", 100 * share,
                rowSdCloudy, rowSdClear, 100 * lowShare);
        assertTrue(share >= 0.15 && share <= 0.7, "clouds cover a fair share of the sky: " + share);
        assertTrue(lowShare < share / 3, "clouds thin into the haze at the horizon: " + lowShare);
        assertTrue(rowSdCloudy >= 3 * rowSdClear, "the clouds make the sky uneven: " + rowSdCloudy + " against "
                + rowSdClear);
    }

    /** The sky alone (no plants, no ground) through each camera. */
    private static Img[] shots(World world, RenderSettings settings, ViewCamera... cams) {
        Img[] out = new Img[cams.length];
        try (Shots s = new Shots(world, settings, W, H)) {
            for (int i = 0; i < cams.length; i++) {
                out[i] = s.render(TestFrames.rest(world, cams[i]), cams[i], false, false);
            }
        }
        return out;
    }
}
