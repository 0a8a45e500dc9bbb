package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.World;
import org.joml.Matrix4f;
import org.joml.Vector2d;
import org.joml.Vector4f;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The wind's sheen (issue 26's first part), measured as issue 26 asks: a still camera (the meadow's
 * start camera) over the showcase meadow in its wind, 150 frames at 480x270, one fixed step each. The
 * ground of the picture (rows from the bottom up to the highest row the terrain reaches in the middle
 * column) is cut into thirds: near, middle and far. In each, over the 16x16-pixel blocks that lie
 * wholly in it, the temporal standard deviation of the block's mean luminance is taken, and its median
 * over the blocks. Asserted: with the sheen on it is at least 4/255 in the middle and far bands (and
 * at least 1.5 times what it is with the sheen off); with no wind (the scene without its flows) it is
 * exactly 0 everywhere; flicker does not grow with the sheen: among pixels that change by more than
 * 2/255 from one frame to the next, the share that reverse direction on the next frame is no higher
 * with the sheen on than off (within 0.02). And the light travels with the gusts: for pairs of ground
 * points 2 m apart along the wind, 8-30 m from the eye, the cross-correlation of the mean luminance of
 * the 9x9 pixels around each (the upwind one's now against the downwind one's later) averaged over
 * the pairs peaks at a lag that gives a speed within 30% of the gusts' travel speed the simulation
 * reports ({@code WindField.gustTravel}), and clearly above its value at lag 0. Tagged
 * {@code slow} (330 frames of the whole meadow, about two minutes on llvmpipe): it runs in
 * {@code mvn -B verify -Pnightly}, not in the default run.
 */
@Tag("slow")
class WindSheenTest {
    private static final int W = 480;
    private static final int H = 270;
    private static final int FRAMES = 150;
    private static final int BLOCK = 16;

    /** Metres between the two ground points of a pair, along the wind. */
    private static final double PAIR_SPACING = 2.0;
    /**
     * The pairs' distances from the eye, metres: the middle of the ground and the near part of its far
     * third. Farther, a 9-pixel window spans tens of metres of ground toward the horizon, so what it
     * shows hardly moves when the pattern moves a few metres.
     */
    private static final double NEAREST = 8;
    private static final double FARTHEST = 30;
    /** The largest time lag tried, frames. */
    private static final int MAX_LAG = 80;

    /**
     * A run's measures: per ground band the median temporal s.d. of block luminance (1/255), the share of
     * reversing pixels, and the travel measure: the lag (frames) at which the pairs' cross-correlation
     * peaks, its value, the value at lag 0, the gust travel speed the simulation reports (m/s) and the
     * frame time (s); the lag is -1 without pairs.
     */
    private record Run(double[] medianSd, double reversals, int peakLag, double peak, double atZero, double gustSpeed,
            double dt, int pairs) {
        /** The on-screen speed the peak lag gives, m/s. */
        double screenSpeed() {
            return PAIR_SPACING / (peakLag * dt);
        }
    }

    @Test
    void gustsShowAsLightInTheMiddleAndFarField() throws Exception {
        SceneDef def = RenderScenes.load("meadow.xml");
        Run on = run(def, 1f, FRAMES);
        Run off = run(def, 0f, FRAMES);
        SceneDef still = stillMeadow();
        Run calm = run(still, 1f, 30);
        System.out.printf("[look] meadow in wind, median temporal s.d. of 16x16 block luminance near/middle/far:"
                + " %.2f / %.2f / %.2f (>= 4 middle and far); sheen off %.2f / %.2f / %.2f; no wind %.2f / %.2f /"
                + " %.2f (0)%n", on.medianSd[0], on.medianSd[1], on.medianSd[2], off.medianSd[0], off.medianSd[1],
                off.medianSd[2], calm.medianSd[0], calm.medianSd[1], calm.medianSd[2]);
        System.out.printf("[look] meadow in wind, frame-to-frame reversals among pixels changing > 2/255: sheen on"
                + " %.3f, off %.3f%n", on.reversals, off.reversals);
        for (int band = 1; band <= 2; band++) {
            String name = band == 1 ? "middle" : "far";
            assertTrue(on.medianSd[band] >= 4.0, name + " band s.d. " + on.medianSd[band] + "/255, issue 26 asks 4");
            assertTrue(on.medianSd[band] >= 1.5 * off.medianSd[band], name + " band s.d. " + on.medianSd[band]
                    + " vs sheen off " + off.medianSd[band]);
        }
        for (double sd : calm.medianSd) {
            assertEquals(0.0, sd, "no wind: the picture stands exactly still");
        }
        assertTrue(on.reversals <= off.reversals + 0.02, "flicker grows with the sheen: " + on.reversals + " vs "
                + off.reversals);
        System.out.printf("[look] meadow in wind, %d ground point pairs %.1f m apart along the wind (%.0f-%.0f m from the"
                + " eye): cross-correlation peaks at %d frames (%.3f; %.3f at lag 0): %.2f m/s on screen, gusts"
                + " travel at %.2f m/s%n", on.pairs, PAIR_SPACING, NEAREST, FARTHEST, on.peakLag, on.peak, on.atZero, on.screenSpeed(),
                on.gustSpeed);
        assertTrue(on.pairs >= 100, "ground point pairs in view: " + on.pairs);
        assertTrue(on.peakLag > 0 && Math.abs(on.screenSpeed() - on.gustSpeed) <= 0.3 * on.gustSpeed,
                "the on-screen pattern travels at " + on.screenSpeed() + " m/s (peak at " + on.peakLag
                        + " frames), the gusts at " + on.gustSpeed + " m/s");
        assertTrue(on.peak >= on.atZero + 0.05, "the travelling pattern correlates " + on.peak + ", at lag 0 "
                + on.atZero);
    }

    /** The meadow without its flows (no wind at all). */
    static SceneDef stillMeadow() throws Exception {
        String xml = Files.readString(Path.of("scenes", "meadow.xml"), StandardCharsets.UTF_8)
                .replaceAll("(?s)<wind>.*</wind>", "");
        return SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "meadow-still.xml", Path.of("scenes"));
    }

    private static Run run(SceneDef def, float sheen, int frames) {
        World world = RenderScenes.build(def);
        ViewCamera cam = RenderScenes.camera(def, world, W, H);
        RenderSettings settings = RenderScenes.settings(def);
        settings.setSheen(sheen);
        int bx = W / BLOCK;
        int by = H / BLOCK;
        double[][] series = new double[bx * by][frames];
        Reversals reversals = new Reversals(2);
        int top;
        int[] pairPixels = new int[0];
        double[][] pairSeries = new double[0][];
        double gustSpeed;
        double t0 = 0;
        double t1 = 0;
        try (Shots s = new Shots(world, settings, W, H); Simulation sim = Simulation.of(world, def.simulationDef(), 2)) {
            Img ground = s.render(TestFrames.rest(world, cam), cam, false, true);
            top = 0;
            for (int y = 0; y < H; y++) {
                if (ImageMetrics.hsv(ground.at(W / 2, y))[2] < 0.55) {
                    top = y; // the highest ground row (GL rows, bottom up) in the middle column
                }
            }
            Vector2d travel = sim.inspect().windField().gustTravel(new Vector2d());
            gustSpeed = travel.length();
            if (gustSpeed > 0) {
                pairPixels = pairs(world, cam, top, travel.x / gustSpeed, travel.y / gustSpeed);
                pairSeries = new double[pairPixels.length / 2][frames];
            }
            for (int f = 0; f < frames; f++) {
                sim.stepFixed(cam);
                if (f == 0) {
                    t0 = sim.latestFrame().time();
                } else if (f == 1) {
                    t1 = sim.latestFrame().time();
                }
                Img img = s.render(sim.latestFrame(), cam, true, true);
                for (int k = 0; k < pairSeries.length; k++) {
                    pairSeries[k][f] = window(img, pairPixels[2 * k], pairPixels[2 * k + 1]);
                }
                int[] luma = new int[W * H];
                for (int y = 0; y < H; y++) {
                    for (int x = 0; x < W; x++) {
                        luma[y * W + x] = (int) Math.round(ImageMetrics.luma(img.at(x, y)));
                    }
                }
                ImageMetrics.blockLuma(img, BLOCK, series, f);
                reversals.add(luma);
            }
        }
        double[] medians = new double[3];
        for (int band = 0; band < 3; band++) {
            int y0 = band * top / 3;
            int y1 = (band + 1) * top / 3;
            double[] sds = new double[bx * by];
            int n = 0;
            for (int j = 0; j < by; j++) {
                if (j * BLOCK < y0 || (j + 1) * BLOCK > y1) {
                    continue;
                }
                for (int i = 0; i < bx; i++) {
                    sds[n++] = ImageMetrics.sd(series[j * bx + i]);
                }
            }
            assertTrue(n > 0, "blocks in band " + band + " (ground rows 0.." + top + ")");
            double[] v = Arrays.copyOf(sds, n);
            Arrays.sort(v);
            medians[band] = n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
        }
        double[] corr = new double[MAX_LAG + 1];
        int peakLag = -1;
        int n = pairSeries.length / 2;
        for (int lag = 0; lag <= MAX_LAG && n > 0 && lag < frames - 20; lag++) {
            double sum = 0;
            for (int k = 0; k < n; k++) {
                sum += correlation(pairSeries[2 * k], pairSeries[2 * k + 1], lag);
            }
            corr[lag] = sum / n;
            if (peakLag < 0 || corr[lag] > corr[peakLag]) {
                peakLag = lag;
            }
        }
        return new Run(medians, reversals.share(), peakLag,
                peakLag < 0 ? 0 : corr[peakLag], corr[0], gustSpeed, t1 - t0, n);
    }

    /**
     * Ground points on a 1 m grid {@link #NEAREST}-{@link #FARTHEST} m from the eye, each with the point {@link #PAIR_SPACING} metres
     * downwind (wx, wz: the wind's unit direction), both seen on the ground of the picture (below its
     * row top, at least 4 pixels in): their pixels, x then y, the upwind point of each pair first.
     */
    private static int[] pairs(World world, ViewCamera cam, int top, double wx, double wz) {
        Matrix4f vp = cam.viewProjection(new Matrix4f());
        int[] out = new int[4096 * 4];
        int n = 0;
        int[] a = new int[2];
        int[] b = new int[2];
        for (int iz = -60; iz <= 60 && n + 4 <= out.length; iz++) {
            for (int ix = -60; ix <= 60 && n + 4 <= out.length; ix++) {
                double x = cam.x() + ix;
                double z = cam.z() + iz;
                double d = Math.hypot(x - cam.x(), z - cam.z());
                if (d < NEAREST || d > FARTHEST) {
                    continue;
                }
                double x2 = x + PAIR_SPACING * wx;
                double z2 = z + PAIR_SPACING * wz;
                if (pixel(world, vp, x, z, top, a) && pixel(world, vp, x2, z2, top, b)) {
                    out[n++] = a[0];
                    out[n++] = a[1];
                    out[n++] = b[0];
                    out[n++] = b[1];
                }
            }
        }
        return Arrays.copyOf(out, n);
    }

    /** Whether ground point (x, z) is seen on the picture's ground; its pixel (GL rows, bottom up) to px. */
    private static boolean pixel(World world, Matrix4f vp, double x, double z, int top, int[] px) {
        Vector4f c = new Vector4f((float) x, (float) world.terrain().heightfield().height(x, z), (float) z, 1f).mul(vp);
        if (c.w <= 0) {
            return false;
        }
        px[0] = (int) Math.floor((c.x / c.w * 0.5 + 0.5) * W);
        px[1] = (int) Math.floor((c.y / c.w * 0.5 + 0.5) * H);
        return px[0] >= 4 && px[0] < W - 4 && px[1] >= 4 && px[1] < Math.min(top, H - 4) - 4;
    }

    /** The mean luminance of the 9x9 pixels around (x, y), 0-255. */
    private static double window(Img img, int x, int y) {
        double sum = 0;
        for (int j = -4; j <= 4; j++) {
            for (int i = -4; i <= 4; i++) {
                sum += ImageMetrics.luma(img.at(x + i, y + j));
            }
        }
        return sum / 81;
    }

    /** Pearson correlation of a(t) with b(t + lag) over the frames both have; 0 when either is constant. */
    private static double correlation(double[] a, double[] b, int lag) {
        int n = a.length - lag;
        double ma = 0;
        double mb = 0;
        for (int t = 0; t < n; t++) {
            ma += a[t];
            mb += b[t + lag];
        }
        ma /= n;
        mb /= n;
        double ab = 0;
        double aa = 0;
        double bb = 0;
        for (int t = 0; t < n; t++) {
            double da = a[t] - ma;
            double db = b[t + lag] - mb;
            ab += da * db;
            aa += da * da;
            bb += db * db;
        }
        return aa > 0 && bb > 0 ? ab / Math.sqrt(aa * bb) : 0;
    }
}
