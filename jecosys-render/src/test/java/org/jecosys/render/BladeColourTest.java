package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * Issue 41's anatomy: a blade has colour across it and along it. One broad upright blade (4 cm wide,
 * 50 cm long, dry tips) seen from 0.6 m against the sky, from the side that shows it widest, 480x480:
 * <ul>
 *   <li><b>across</b>: in the rows where it is at least 15 pixels wide, the middle third of the blade is
 *       at least 8% brighter than its outer thirds (median over the rows): a lighter midrib (1.13 with
 *       plant.frag's MIDRIB 0.3). A blade lit by its folded normals alone grows lighter toward one edge,
 *       and its middle, a linear blend of the two edges encoded to sRGB, is darker than their mean (0.87
 *       without the midrib);</li>
 *   <li><b>along</b>: its tip is yellower than its base (hue at least 8 degrees lower in the top tenth
 *       of its rows than in the lowest quarter): the dry tips.</li>
 * </ul>
 */
class BladeColourTest {
    private static final int W = 480;
    private static final int H = 480;

    private static final String SCENE = """
            <scene version="1" name="blade" seed="5">
              <terrain sizeX="4" sizeZ="4" resolution="9" heightScale="0"/>
              <species id="blade" maxBend="68.8">
                <lod/>
                <variation variants="1" dryTips="0.6"/>
                <component id="leaf" type="leaf" segments="8" length="0.5" baseWidth="0.04" tipWidth="0.03"
                    mass="0.0002" stiffness="0.5" colour="#4f9430" lodSegments="8"/>
              </species>
              <plant species="blade" x="0" z="0"/>
            </scene>
            """;

    @Test
    void aBladeIsLighterAlongItsMiddleAndYellowerAtItsTip() throws Exception {
        SceneDef def = SceneFiles.parse(SCENE.getBytes(StandardCharsets.UTF_8), "blade.xml", Path.of("scenes"));
        World world = RenderScenes.build(def);
        RenderSettings settings = RenderSettings.standalone();
        settings.lighting().setSun(Math.toRadians(60), Math.toRadians(40));
        Img best = null;
        boolean[] bestMask = null;
        int most = 0;
        try (Shots s = new Shots(world, settings, W, H)) {
            for (int k = 0; k < 8; k++) {
                double a = k * Math.PI / 4;
                ViewCamera cam = Shots.lookAt(0.6 * Math.cos(a), 0.25, 0.6 * Math.sin(a), 0, 0.25, 0,
                        Math.toRadians(50), 1, 0.05, 20);
                Frame frame = TestFrames.rest(world, cam);
                Img with = s.render(frame, cam, true, false);
                Img without = s.render(frame, cam, false, false);
                boolean[] mask = ImageMetrics.differ(with, without, 6);
                int n = ImageMetrics.count(mask);
                if (n > most) {
                    most = n;
                    best = with;
                    bestMask = mask;
                }
            }
        }
        assertTrue(most > 2000, "the blade is seen: " + most + " pixels");
        List<Double> ratios = new ArrayList<>();
        int top = -1;
        int bottom = H;
        for (int y = 0; y < H; y++) {
            int lo = -1;
            int hi = -1;
            for (int x = 0; x < W; x++) {
                if (bestMask[y * W + x]) {
                    lo = lo < 0 ? x : lo;
                    hi = x;
                }
            }
            if (lo < 0) {
                continue;
            }
            top = Math.max(top, y);
            bottom = Math.min(bottom, y);
            int width = hi - lo + 1;
            if (width < 15) {
                continue;
            }
            // the run's inner pixels (one left off each edge: coverage there mixes in the sky)
            double mid = 0;
            double out = 0;
            int nm = 0;
            int no = 0;
            for (int x = lo + 1; x < hi; x++) {
                double f = (x - lo) / (double) (width - 1);
                double l = ImageMetrics.luma(best.at(x, y));
                if (f > 1 / 3.0 && f < 2 / 3.0) {
                    mid += l;
                    nm++;
                } else {
                    out += l;
                    no++;
                }
            }
            ratios.add((mid / nm) / (out / no));
        }
        assertTrue(ratios.size() >= 40, "rows where the blade is 15 px wide: " + ratios.size());
        Collections.sort(ratios);
        double across = ratios.get(ratios.size() / 2);
        double baseHue = meanHue(best, bestMask, bottom, bottom + (top - bottom) / 4);
        double tipHue = meanHue(best, bestMask, top - (top - bottom) / 10, top + 1);
        System.out.printf("[look] a blade's middle third against its outer thirds: %.3f (median of %d rows, >= 1.08); "
                + "hue at its base %.1f deg, at its tip %.1f deg (tip >= 8 lower)%n", across, ratios.size(), baseHue,
                tipHue);
        assertTrue(across >= 1.08, "a lighter midrib: middle/outer " + across);
        assertTrue(baseHue - tipHue >= 8, "a yellower tip: base hue " + baseHue + ", tip " + tipHue);
    }

    /** Mean hue, degrees, of the mask's pixels in rows [y0, y1). */
    private static double meanHue(Img img, boolean[] mask, int y0, int y1) {
        double s = 0;
        int n = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = 0; x < img.width(); x++) {
                if (mask[y * img.width() + x]) {
                    s += ImageMetrics.hsv(img.at(x, y))[0];
                    n++;
                }
            }
        }
        return s / Math.max(1, n);
    }
}
