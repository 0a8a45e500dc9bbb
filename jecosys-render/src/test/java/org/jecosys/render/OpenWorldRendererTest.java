package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.OpenWorld;
import org.jecosys.world.TilePlacer;
import org.junit.jupiter.api.Test;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.system.MemoryUtil;

/**
 * The open world drawn ({@link OpenWorldRenderer}): {@code scenes/openworld.xml}'s plants within 12 m of
 * a camera that runs 63 m in a second and then stands still, 30 frames a second on llvmpipe, thinned as
 * the viewer's low quality. Each live tile gets a renderer sharing
 * the programs, at most {@link OpenWorldRenderer#NEW_TILES_PER_FRAME} a frame; renderers of tiles let go
 * are closed; the plants cover the lower part of the picture, the sky the upper; no GL error. Prints
 * the frame's median and 99th percentile.
 */
class OpenWorldRendererTest {
    private static final int W = 192;
    private static final int H = 108;

    private static double covered(ByteBuffer px, int y0, int y1) {
        return org.jecosys.render.SkyShare.covered(px, W, y0, y1);
    }

    @Test
    void theLiveTilesAreDrawnAndTheirRenderersFollowTheWalk() throws Exception {
        SceneDef scene = SceneFiles.parse(Path.of("scenes", "openworld.xml"));
        TilePlacer placer = RenderScenes.placer(scene);
        RenderSettings settings = RenderSettings.of(scene.render());
        settings.setClear(true);
        settings.setTerrain(true);
        ByteBuffer px = MemoryUtil.memAlloc(4 * W * H);
        try (OpenWorld w = OpenWorld.create(scene.simulationDef(), placer, 12, 2, 1, 8);
             GlContext gl = GlContext.headless(DebugOutput.ON);
             GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), W, H);
             OpenWorldRenderer r = new OpenWorldRenderer(gl, w, settings)) {
            ViewCamera cam = new ViewCamera();
            cam.setOrientation(Math.PI / 2, Math.toRadians(-10));
            cam.setLens(Math.toRadians(60), W / (double) H, 0.1, 500);
            cam.setPosition(0, scene.world().relief().height(0, 0) + 1.7, 0);
            w.setThinning(4, 16, 0.15); // the low quality, as the viewer takes on llvmpipe
            w.stepFixed(cam);
            w.settle();
            fb.bind();
            int frames = 40;
            double[] ms = new double[frames];
            int most = 0;
            for (int f = 0; f < frames; f++) {
                double x = Math.min(30, f) * 2.1; // 63 m/s for a second, past the tiles' reach, then still
                cam.setPosition(x, scene.world().relief().height(x, 0) + 1.7, 0);
                w.step(1 / 30.0, cam);
                long t0 = System.nanoTime();
                r.render(cam, W, H);
                GL11C.glFinish();
                ms[f] = (System.nanoTime() - t0) / 1e6;
                most = Math.max(most, r.tileRenderers());
                assertTrue(r.renderersMade() - r.tileRenderers() >= 0, "renderers closed are not counted live");
            }
            assertEquals(w.liveTiles(), r.tileRenderers(), "every live tile has its renderer after the walk");
            assertTrue(r.renderersMade() > r.tileRenderers(), "tiles let go had their renderers closed: made "
                    + r.renderersMade() + ", live " + r.tileRenderers());
            assertTrue(r.tilesDrawn() > 4, "tiles drawn: " + r.tilesDrawn());
            fb.resolve();
            Screenshot.read(W, H, px);
            if (System.getenv("JECOSYS_KEEP_SHOTS") != null) {
                Screenshot.writePng(Path.of("target", "open-world.png"), px, W, H);
            }
            double low = covered(px, 0, H / 3);
            double high = covered(px, 5 * H / 6, H);
            assertTrue(low > 0.9, "ground and plants cover the lower third: " + low);
            assertTrue(high < 0.2, "the sky shows at the top: " + high);
            GlContexts.debug(gl).check("the open-world renderer test");
            double[] sorted = ms.clone();
            Arrays.sort(sorted);
            System.out.printf(Locale.ROOT, "[bench] open-world frames on %s, %dx%d, %d tiles live: median %.1f ms,"
                    + " p99 %.1f ms; %d tile renderers made, at most %d live; plants cover %.0f%% of the lower third"
                    + "%n", gl.describe(), W, H, w.liveTiles(), sorted[frames / 2], sorted[frames - 1],
                    r.renderersMade(), most, 100 * low);
        } finally {
            MemoryUtil.memFree(px);
        }
    }
}
