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
 * On a target without samples (the engines' default back buffers) the plants in a level-switch or
 * thinning band are drawn whole at one level instead of dithered over two, so the bands show no
 * checker: the meadow's default view with the low quality's thinning (4 m to 16 m, down to 15%), plants
 * alone over the sky colour at 480x270. A 2x2 block is a checker when its diagonals agree and differ
 * from each other (plant, sky / sky, plant). The same frame dithered at 0 samples is the failing
 * case. (Without samples the thin blades are drawn opaque at their widened width, so the plants
 * weigh more in the picture than at 4 samples, where the same blades cover part of a pixel: reported,
 * and checked only to be no less.)
 */
class ZeroSamplesTest {
    private static final int W = 480;
    private static final int H = 270;

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
            SceneParts.plants(renderer).setWholePlantsBelow(0); // dither always: the old way
            boolean[] dithered = plants(shot(renderer, single, frame, cam, px, false), empty);
            int[] sampledShot = shot(renderer, multi, frame, cam, px, true);
            gl.debug().check("rendering the bands");
            double checkerWhole = checkerShare(whole);
            double checkerDithered = checkerShare(dithered);
            double coverWhole = weight(wholeShot, empty);
            double coverSampled = weight(sampledShot, empty);
            System.out.printf("[look] 0 samples: checker blocks %.4f whole plants, %.4f dithered; plants' weight "
                    + "%.4f whole plants, %.4f at 4 samples%n", checkerWhole, checkerDithered, coverWhole, coverSampled);
            // what is left is the plants' own geometry (one-pixel diagonals of thin blades), over the whole picture
            assertTrue(checkerWhole <= 0.015, "checker blocks with whole plants: " + checkerWhole);
            assertTrue(checkerDithered > 4 * checkerWhole, "the dithered bands do show a checker: " + checkerDithered);
            assertTrue(coverWhole >= coverSampled, "no plant left out: weight " + coverWhole + " vs " + coverSampled);
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
        long sum = 0;
        for (int i = 0; i < rgb.length; i++) {
            for (int shift = 0; shift <= 16; shift += 8) {
                sum += Math.abs((rgb[i] >> shift & 255) - (empty[i] >> shift & 255));
            }
        }
        return sum / (3.0 * 255 * rgb.length);
    }

    /** Checker blocks among the 2x2 blocks (aligned) that hold both plant and sky. */
    private static double checkerShare(boolean[] m) {
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
                mixed++;
                if (a == d && b == c && a != b) {
                    checker++;
                }
            }
        }
        return checker / (double) Math.max(1, mixed);
    }
}
