package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * Issue 41's sharpness measures, on the meadow's start view as shipped (4 samples, the resolve's default
 * filter), reported so that a change of the resolve is judged by them:
 * <ul>
 * <li><b>fine detail</b>: the mean absolute Laplacian of the luma over the vegetation
 * ({@link ImageMetrics#meanAbsLaplacian}) of the native 960x540 picture, as a share of the same over the
 * same pixels of the view rendered at 1920x1080 and shrunk 2x2 to 960x540 (the issue asks 0.8 or more);</li>
 * <li><b>8 px contrast</b>: the luma standard deviation (0-255) within 8x8 blocks at least half
 * vegetation, averaged over the blocks of the near field (the lowest 40% of the rows; the issue asks 15)
 * and of the middle distance (rows 20-60% from the top; the issue asks 14).</li>
 * </ul>
 * The view is measured twice: as one frame shows it, and held still for {@link Shots#ACCUMULATED} frames
 * with the framebuffer's temporal accumulation ({@code GlFramebuffer.setAccumulation}), which the viewer
 * and the render command turn on. The accumulated view must meet the three figures (and, in the
 * nightly {@link AntiAliasingTest}, issue 13's half-pixel residual, so that the detail it keeps is not
 * aliasing); the one-frame
 * view keeps its earlier floors (fine detail 0.25 of the reference, contrast 8), so that the one-frame
 * resolve, which a moving view and a frame without history show, does not get softer unnoticed. The
 * targets conflict with issue 13's half-pixel residual ({@link AntiAliasingTest}, at most 2/255) for
 * any one-frame resolve filter: measured on this view (under the meadow's earlier, flatter light) with {@code GlFramebuffer.setResolveFilter}, fine
 * detail / near / middle contrast / residual were 40.7 / 23.7 / 18.2 / 5.97 for the plain average (0),
 * 24.5 / 19.5 / 15.2 / 3.89 for 0.5, 11.2 / 16.3 / 13.0 / 2.44 for 1 and 6.8 / 13.8 / 11.4 / 1.77 for the
 * default 2 (the supersampled reference: 21.4, 20.5, 15.9); sharpening mixes (negative weights on the
 * wide filter) moved along the same curve. Both at once need more samples than one frame has, which
 * temporal accumulation with a jittered projection gathers over frames.
 */
class SharpnessTest {
    private static final int W = 960;
    private static final int H = 540;

    /** The 2x2 box average of a picture twice as large: a supersampled reference. */
    static Img shrink(Img big) {
        int w = big.width() / 2;
        int h = big.height() / 2;
        int[] out = new int[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int r = 0;
                int g = 0;
                int b = 0;
                for (int j = 0; j < 2; j++) {
                    for (int i = 0; i < 2; i++) {
                        int c = big.at(2 * x + i, 2 * y + j);
                        r += ImageMetrics.r(c);
                        g += ImageMetrics.g(c);
                        b += ImageMetrics.b(c);
                    }
                }
                out[y * w + x] = ImageMetrics.rgb((r + 2) / 4, (g + 2) / 4, (b + 2) / 4);
            }
        }
        return new Img(w, h, out);
    }

    /**
     * Mean luma s.d. in the 8x8 blocks of rows [y0, y1) (GL order, from the bottom) that are at least half
     * in the mask; NaN when none is.
     */
    static double blockContrast(Img img, boolean[] mask, int y0, int y1) {
        double sum = 0;
        int blocks = 0;
        for (int by = y0; by + 8 <= y1; by += 8) {
            for (int bx = 0; bx + 8 <= img.width(); bx += 8) {
                int in = 0;
                double s = 0;
                double s2 = 0;
                for (int y = by; y < by + 8; y++) {
                    for (int x = bx; x < bx + 8; x++) {
                        double l = ImageMetrics.luma(img.at(x, y));
                        s += l;
                        s2 += l * l;
                        in += mask[y * img.width() + x] ? 1 : 0;
                    }
                }
                if (in >= 32) {
                    double mean = s / 64;
                    sum += Math.sqrt(Math.max(0, s2 / 64 - mean * mean));
                    blocks++;
                }
            }
        }
        return blocks == 0 ? Double.NaN : sum / blocks;
    }

    @Test
    void theMeadowsDetailAndContrastAreMeasured() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        Shots.View native0;
        Img still;
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            ViewCamera cam = RenderScenes.camera(def, world, W, H);
            native0 = s.view(TestFrames.rest(world, cam), cam);
            still = s.accumulated(TestFrames.rest(world, cam), cam);
        }
        Img reference;
        try (Shots s = new Shots(world, RenderScenes.settings(def), 2 * W, 2 * H)) {
            ViewCamera cam = RenderScenes.camera(def, world, 2 * W, 2 * H);
            reference = shrink(s.render(TestFrames.rest(world, cam), cam, true, true));
        }
        boolean[] veg = native0.vegetation();
        double detail = ImageMetrics.meanAbsLaplacian(native0.full(), veg);
        double detailRef = ImageMetrics.meanAbsLaplacian(reference, veg);
        double near = blockContrast(native0.full(), veg, 0, (int) (0.4 * H));
        double middle = blockContrast(native0.full(), veg, (int) (0.4 * H), (int) (0.8 * H));
        double nearRef = blockContrast(reference, veg, 0, (int) (0.4 * H));
        double middleRef = blockContrast(reference, veg, (int) (0.4 * H), (int) (0.8 * H));
        System.out.printf("[look] meadow sharpness at %dx%d, one frame: fine detail %.2f against %.2f supersampled 2x "
                + "(%.2f); 8 px contrast near %.1f (reference %.1f), middle %.1f (reference %.1f)%n", W, H, detail,
                detailRef, detail / detailRef, near, nearRef, middle, middleRef);
        double stillDetail = ImageMetrics.meanAbsLaplacian(still, veg) / detailRef;
        double stillNear = blockContrast(still, veg, 0, (int) (0.4 * H));
        double stillMiddle = blockContrast(still, veg, (int) (0.4 * H), (int) (0.8 * H));
        System.out.printf("[look] meadow sharpness at %dx%d, held still %d frames with temporal accumulation: fine "
                + "detail %.2f of the reference (issue 41 asks >= 0.8); 8 px contrast near %.1f (asks >= 15), middle "
                + "%.1f (asks >= 14)%n", W, H, Shots.ACCUMULATED, stillDetail, stillNear, stillMiddle);
        assertTrue(detail / detailRef >= 0.25, "one frame's fine detail kept: " + detail / detailRef);
        assertTrue(near >= 8 && middle >= 8, "one frame's 8 px contrast near " + near + ", middle " + middle);
        assertTrue(stillDetail >= 0.8, "fine detail of the accumulated view: " + stillDetail);
        assertTrue(stillNear >= 15, "near-field 8 px contrast of the accumulated view: " + stillNear);
        assertTrue(stillMiddle >= 14, "middle-distance 8 px contrast of the accumulated view: " + stillMiddle);
    }

    /**
     * The same figures while the wind blows, as the viewer draws it: 20 frames of {@link TestFrames#wind}
     * 1/30 s apart, each jittered and accumulated with the scene animating (the running mean holds 4
     * frames), against the last moment drawn at 1920x1080 and shrunk. Nightly: 26 renders of the meadow.
     */
    @Test
    @org.junit.jupiter.api.Tag("slow")
    void inTheWindTheAccumulatingViewKeepsItsDetail() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        double start = 2.0;
        int frames = 20;
        double end = start + (frames - 1) / 30.0;
        Img reference;
        try (Shots s = new Shots(world, RenderScenes.settings(def), 2 * W, 2 * H)) {
            ViewCamera cam = RenderScenes.camera(def, world, 2 * W, 2 * H);
            reference = shrink(s.render(TestFrames.wind(world, end, cam), cam, true, true));
        }
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            ViewCamera cam = RenderScenes.camera(def, world, W, H);
            Shots.View one = s.view(TestFrames.wind(world, end, cam), cam);
            boolean[] veg = one.vegetation();
            s.fb.setAccumulation(Shots.ACCUMULATED);
            Img last = null;
            for (int i = 0; i < frames; i++) {
                last = s.render(TestFrames.wind(world, start + i / 30.0, cam), s.fb.jittered(cam, false), true, true);
            }
            s.fb.setAccumulation(0);
            double ref = ImageMetrics.meanAbsLaplacian(reference, veg);
            double detail = ImageMetrics.meanAbsLaplacian(last, veg) / ref;
            double near = blockContrast(last, veg, 0, (int) (0.4 * H));
            double middle = blockContrast(last, veg, (int) (0.4 * H), (int) (0.8 * H));
            System.out.printf("[look] meadow in the wind at %dx%d, accumulating as the viewer does: fine detail %.2f of the "
                    + "last moment supersampled 2x (one frame %.2f); 8 px contrast near %.1f, middle %.1f%n", W, H, detail,
                    ImageMetrics.meanAbsLaplacian(one.full(), veg) / ref, near, middle);
            assertTrue(detail >= 0.8, "fine detail in the wind: " + detail);
            assertTrue(near >= 15 && middle >= 14, "8 px contrast in the wind: near " + near + ", middle " + middle);
        }
    }
}
