package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.render.internal.SceneParts;
import org.jecosys.scene.RenderDef;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.DrawDecision;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.jecosys.sim.internal.DecisionWriter;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;

/**
 * Issue 38, "Done when": on a target without samples (the engines' default back buffers) the plants in a
 * level-switch or thinning band are drawn whole at one level instead of dithered over two, so the bands
 * show no checker: the meadow's default view with the low quality's thinning (4 m to 16 m, down to 15%),
 * plants alone over the sky colour at 480x270. A 2x2 block is a checker when its diagonals agree and
 * differ from each other (plant, sky / sky, plant). The same frame dithered at 0 samples is the failing
 * case; only 2x2 blocks with a plant pixel 4 m to 16.5 m from the eye (the bands, from the depth buffer)
 * count, at most 1%.
 *
 * <p>And far plants keep their coverage: their weight in the picture (mean channel difference to the
 * empty picture) over the pixels whose ground lies beyond 4 m, with no nearer plant in front, at 0
 * samples within 10% of a 4-sample render's; the same beyond the bands (16.5 m). Both targets blend thin
 * parts by the share of a pixel they cover (an opaque core writing depth, then the thin parts and far
 * lines blending), the 4-sample one on the samples each part's geometry covers, so both weigh what the
 * plants cover: the 4-sample picture is held within 10% of the truth (the same frame at 4 x 4 times the
 * pixels with blades at their real width, box-filtered down), the one without samples within 15%. The
 * GL's alpha-to-coverage ({@code setBlendOnSamples(false)}) is rendered too and must come out further
 * from the truth: it gives every thin part of one alpha the same samples, so overlapping blades count
 * once (about 28% light on llvmpipe).
 */
class ZeroSamplesTest {
    private static final int W = 480;
    private static final int H = 270;
    /** The level-switch and thinning bands of this view, metres from the eye: thinning 4-16 m, switches at 10 and 15 m. */
    private static final double BAND_NEAR = 4;
    private static final double BAND_FAR = 16.5;

    @Test
    void bandsShowNoCheckerWithoutSamplesAndKeepTheirCoverage() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        ViewCamera cam = RenderScenes.camera(def, world, W, H);
        DrawDecision decision = DrawDecision.of(world);
        DecisionWriter.setThinning(decision, 4, 16, 0.15);
        Frame frame = DecisionWriter.decideAll(decision, cam, TestFrames.rest(world));
        RenderSettings settings = RenderScenes.settings(def);
        settings.setGroundCover(RenderDef.GroundCover.NONE);
        ByteBuffer px = MemoryUtil.memAlloc(4 * W * H);
        try (GlContext gl = GlContext.headless(DebugOutput.ON);
             GlFramebuffer single = new GlFramebuffer(gl.tracker(), W, H);
             GlFramebuffer multi = new GlFramebuffer(gl.tracker(), W, H, 4);
             SceneRenderer renderer = new SceneRenderer(gl, world, settings)) {
            renderer.drawTerrain = false;
            renderer.drawPlants = false;
            int[] empty = shot(renderer, single, frame, cam, px, false);
            renderer.drawPlants = true;
            int[] wholeShot = shot(renderer, single, frame, cam, px, false);
            boolean[] whole = plants(wholeShot, empty);
            double[] plantDistance = distances(cam);
            boolean[] band = new boolean[W * H];
            for (int i = 0; i < band.length; i++) {
                band[i] = plantDistance[i] >= BAND_NEAR && plantDistance[i] <= BAND_FAR;
            }
            SceneParts.plants(renderer).setWholePlantsBelow(0); // dither always: the old way
            boolean[] dithered = plants(shot(renderer, single, frame, cam, px, false), empty);
            int[] sampledShot = shot(renderer, multi, frame, cam, px, true);
            SceneParts.plants(renderer).setBlendOnSamples(false);
            int[] alphaToCoverageShot = shot(renderer, multi, frame, cam, px, true);
            SceneParts.plants(renderer).setBlendOnSamples(true);
            // the far field: ground at least BAND_NEAR from the eye (or none) with no nearer plant in front
            renderer.drawTerrain = true;
            renderer.drawPlants = false;
            shot(renderer, single, frame, cam, px, false);
            double[] groundDistance = distances(cam);
            renderer.drawTerrain = false;
            renderer.drawPlants = true;
            boolean[] far = new boolean[W * H];
            boolean[] beyond = new boolean[W * H];
            for (int i = 0; i < far.length; i++) {
                far[i] = groundDistance[i] >= BAND_NEAR && plantDistance[i] >= BAND_NEAR;
                beyond[i] = groundDistance[i] >= BAND_FAR && plantDistance[i] >= BAND_FAR;
            }
            // the plants' true coverage: 4 x 4 times the pixels, blades at their real width, box-filtered down
            int[] truth;
            int[] truthEmpty;
            try (GlFramebuffer big = new GlFramebuffer(gl.tracker(), 4 * W, 4 * H)) {
                org.jecosys.render.plant.PlantRenderer pr = SceneParts.plants(renderer);
                pr.setWholePlantsBelow(2);
                pr.setThinParts(0f, 4 * org.jecosys.render.plant.PlantRenderer.DEFAULT_HEAD_PIXELS,
                        org.jecosys.render.plant.PlantRenderer.DEFAULT_FLOWER_TILT);
                truth = bigShot(renderer, big, frame, cam);
                renderer.drawPlants = false;
                truthEmpty = bigShot(renderer, big, frame, cam);
                renderer.drawPlants = true;
                pr.setThinParts(org.jecosys.render.plant.PlantRenderer.DEFAULT_MIN_PIXELS,
                        org.jecosys.render.plant.PlantRenderer.DEFAULT_HEAD_PIXELS,
                        org.jecosys.render.plant.PlantRenderer.DEFAULT_FLOWER_TILT);
            }
            double coverTruth = weight(truth, truthEmpty);
            gl.debug().check("rendering the bands");
            double checkerWhole = checkerShare(whole, null);
            double checkerDithered = checkerShare(dithered, null);
            double bandWhole = checkerShare(whole, band);
            double bandDithered = checkerShare(dithered, band);
            double coverWhole = weight(wholeShot, empty);
            double coverSampled = weight(sampledShot, empty);
            double coverAlphaToCoverage = weight(alphaToCoverageShot, empty);
            double farWhole = weight(wholeShot, empty, far);
            double farSampled = weight(sampledShot, empty, far);
            double farAlphaToCoverage = weight(alphaToCoverageShot, empty, far);
            double farTruth = weight(truth, truthEmpty, far);
            double beyondWhole = weight(wholeShot, empty, beyond);
            double beyondSampled = weight(sampledShot, empty, beyond);
            System.out.printf("[look] 0 samples: beyond the bands (ground beyond %.1f m, %.1f%% of the picture) %.4f at 0 "
                    + "samples, %.4f at 4: %+.1f%%%n", BAND_FAR, 100.0 * count(beyond) / beyond.length, beyondWhole,
                    beyondSampled, 100 * (beyondWhole / beyondSampled - 1));
            System.out.printf("[look] 0 samples: far plants (ground beyond %.0f m, %.1f%% of the picture) weigh %.4f at 0 "
                    + "samples, %.4f at 4 samples, %.4f with the GL's alpha-to-coverage, %.4f true: 0 samples "
                    + "%+.1f%% of 4 samples; 4 samples %+.1f%% of the truth, alpha-to-coverage %+.1f%%%n", BAND_NEAR,
                    100.0 * count(far) / far.length, farWhole, farSampled, farAlphaToCoverage,
                    farTruth, 100 * (farWhole / farSampled - 1), 100 * (farSampled / farTruth - 1),
                    100 * (farAlphaToCoverage / farTruth - 1));
            System.out.printf("[look] 0 samples: checker blocks in the bands (%.0f-%.1f m) %.4f whole plants, %.4f "
                    + "dithered; over the whole picture %.4f, %.4f; plants' weight %.4f at 0 samples, %.4f at 4 "
                    + "samples, %.4f true (16 x the pixels, real widths): 0 samples %+.1f%% of the truth, 4 samples "
                    + "%+.1f%%%n", BAND_NEAR, BAND_FAR, bandWhole, bandDithered, checkerWhole, checkerDithered,
                    coverWhole, coverSampled, coverTruth, 100 * (coverWhole / coverTruth - 1),
                    100 * (coverSampled / coverTruth - 1));
            assertTrue(bandWhole <= 0.01, "checker blocks in the bands with whole plants: " + bandWhole);
            assertTrue(bandDithered > 4 * bandWhole, "the dithered bands do show a checker: " + bandDithered);
            assertTrue(checkerWhole <= 0.015, "checker blocks over the whole picture: " + checkerWhole);
            assertTrue(Math.abs(farWhole / farSampled - 1) <= 0.10, "far plants keep their coverage: weight " + farWhole
                    + " at 0 samples vs " + farSampled + " at 4");
            assertTrue(Math.abs(beyondWhole / beyondSampled - 1) <= 0.10, "plants beyond the bands keep their "
                    + "coverage: weight " + beyondWhole + " at 0 samples vs " + beyondSampled + " at 4");
            assertTrue(Math.abs(coverSampled / coverTruth - 1) <= 0.10, "4 samples weigh what the plants cover: "
                    + coverSampled + " vs " + coverTruth + " true");
            assertTrue(Math.abs(farSampled / farTruth - 1) < Math.abs(farAlphaToCoverage / farTruth - 1),
                    "blending on the samples comes nearer the truth than alpha-to-coverage: " + farSampled + ", "
                    + farAlphaToCoverage + " vs " + farTruth);
            assertTrue(Math.abs(coverWhole / coverTruth - 1) <= 0.15, "the plants weigh what they cover: weight "
                    + coverWhole + " at 0 samples vs " + coverTruth + " true");
        } finally {
            MemoryUtil.memFree(px);
        }
    }

    /** A shot at 4 x 4 times the pixels, box-filtered down to W x H. */
    private static int[] bigShot(SceneRenderer renderer, GlFramebuffer fb, Frame frame, ViewCamera cam) {
        int bw = 4 * W;
        int bh = 4 * H;
        ViewCamera big = new ViewCamera();
        big.setPosition(cam.x(), cam.y(), cam.z());
        big.setOrientation(cam.yaw(), cam.pitch());
        big.setLens(cam.fovY(), bw / (double) bh, cam.near(), cam.far());
        fb.bind();
        renderer.render(frame, big, bw, bh);
        ByteBuffer px = MemoryUtil.memAlloc(4 * bw * bh);
        try {
            Pixels.read(bw, bh, px);
            int[] rgb = new int[W * H];
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    int r = 0;
                    int g = 0;
                    int b = 0;
                    for (int j = 0; j < 4; j++) {
                        for (int i = 0; i < 4; i++) {
                            int o = 4 * ((4 * y + j) * bw + 4 * x + i);
                            r += px.get(o) & 255;
                            g += px.get(o + 1) & 255;
                            b += px.get(o + 2) & 255;
                        }
                    }
                    rgb[y * W + x] = (r / 16) << 16 | (g / 16) << 8 | (b / 16);
                }
            }
            return rgb;
        } finally {
            MemoryUtil.memFree(px);
        }
    }

    private static int[] shot(SceneRenderer renderer, GlFramebuffer fb, Frame frame, ViewCamera cam, ByteBuffer px,
                              boolean resolve) {
        fb.bind();
        renderer.render(frame, cam, W, H);
        if (resolve) {
            fb.resolve();
        }
        Pixels.read(W, H, px);
        int[] rgb = new int[W * H];
        for (int i = 0; i < W * H; i++) {
            rgb[i] = (px.get(4 * i) & 255) << 16 | (px.get(4 * i + 1) & 255) << 8 | (px.get(4 * i + 2) & 255);
        }
        return rgb;
    }

    /** Pixels that differ from the empty picture by more than 3 in a channel. */
    private static boolean[] plants(int[] rgb, int[] empty) {
        boolean[] m = new boolean[rgb.length];
        for (int i = 0; i < rgb.length; i++) {
            int a = rgb[i];
            int b = empty[i];
            m[i] = Math.abs((a >> 16 & 255) - (b >> 16 & 255)) > 3 || Math.abs((a >> 8 & 255) - (b >> 8 & 255)) > 3
                    || Math.abs((a & 255) - (b & 255)) > 3;
        }
        return m;
    }

    /**
     * How much the plants change the picture: the mean channel difference against the empty picture,
     * /255 (a pixel a plant covers a quarter of counts about a quarter).
     */
    private static double weight(int[] rgb, int[] empty) {
        return weight(rgb, empty, null);
    }

    /** As {@link #weight(int[], int[])} over the pixels of {@code mask} only (null: all). */
    private static double weight(int[] rgb, int[] empty, boolean[] mask) {
        long sum = 0;
        int n = 0;
        for (int i = 0; i < rgb.length; i++) {
            if (mask != null && !mask[i]) {
                continue;
            }
            n++;
            for (int shift = 0; shift <= 16; shift += 8) {
                sum += Math.abs((rgb[i] >> shift & 255) - (empty[i] >> shift & 255));
            }
        }
        return sum / (3.0 * 255 * Math.max(1, n));
    }

    private static int count(boolean[] m) {
        int n = 0;
        for (boolean b : m) {
            n += b ? 1 : 0;
        }
        return n;
    }

    /**
     * The distance from the eye of what each pixel of the bound framebuffer shows by its depth, metres;
     * infinite where nothing wrote depth (the sky; the far level, blended, writes none).
     */
    private static double[] distances(ViewCamera cam) {
        java.nio.FloatBuffer depth = MemoryUtil.memAllocFloat(W * H);
        try {
            org.lwjgl.opengl.GL11C.glReadPixels(0, 0, W, H, org.lwjgl.opengl.GL11C.GL_DEPTH_COMPONENT,
                    org.lwjgl.opengl.GL11C.GL_FLOAT, depth);
            org.joml.Matrix4f inverse = cam.viewProjection(new org.joml.Matrix4f()).invert();
            org.joml.Vector4f p = new org.joml.Vector4f();
            double[] out = new double[W * H];
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    float d = depth.get(y * W + x);
                    if (d >= 1f) {
                        out[y * W + x] = Double.POSITIVE_INFINITY;
                        continue;
                    }
                    inverse.transform(p.set(2 * (x + 0.5f) / W - 1, 2 * (y + 0.5f) / H - 1, 2 * d - 1, 1));
                    double dx = p.x / p.w - cam.x();
                    double dy = p.y / p.w - cam.y();
                    double dz = p.z / p.w - cam.z();
                    out[y * W + x] = Math.sqrt(dx * dx + dy * dy + dz * dz);
                }
            }
            return out;
        } finally {
            MemoryUtil.memFree(depth);
        }
    }

    /**
     * Checker blocks among the 2x2 blocks (aligned) that hold both plant and sky; with a band, only
     * blocks with a pixel in it.
     */
    private static double checkerShare(boolean[] m, boolean[] band) {
        int mixed = 0;
        int checker = 0;
        for (int y = 0; y + 1 < H; y += 2) {
            for (int x = 0; x + 1 < W; x += 2) {
                boolean a = m[y * W + x];
                boolean b = m[y * W + x + 1];
                boolean c = m[(y + 1) * W + x];
                boolean d = m[(y + 1) * W + x + 1];
                if (a == b && b == c && c == d) {
                    continue;
                }
                if (band != null && !(band[y * W + x] || band[y * W + x + 1] || band[(y + 1) * W + x]
                        || band[(y + 1) * W + x + 1])) {
                    continue;
                }
                mixed++;
                if (a == d && b == c && a != b) {
                    checker++;
                }
            }
        }
        return checker / (double) Math.max(1, mixed);
    }
}
