package org.jecosys.gdx;

import org.jecosys.render.gl.GlContexts;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.badlogic.gdx.backends.lwjgl3.Lwjgl3Files;
import com.badlogic.gdx.graphics.PerspectiveCamera;
import com.badlogic.gdx.utils.GdxNativesLoader;
import java.lang.management.ManagementFactory;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.terrain.Heightfield;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The plant layer's per-frame calls, in a headless OpenGL context standing in for libGDX's (the
 * layer needs only a current context and a libGDX camera): after warm-up, update and render allocate
 * nothing on the render thread; a disposed layer refuses both. Drawing inside a real libGDX
 * application is the example's test.
 */
class PlantLayerTest {
    @BeforeAll
    static void gdxNatives() {
        GdxNativesLoader.load();
    }

    @Test
    void updateAndRenderAllocateNothingAfterWarmUpAndADisposedLayerRefusesThem() throws Exception {
        try (GlContext owner = GlContext.headless(DebugOutput.ON)) {
            GlFramebuffer target = new GlFramebuffer(GlContexts.tracker(owner), 320, 180);
            PlantLayer layer = PlantLayer.load(new Lwjgl3Files().classpath("org/jecosys/gdx/tiny/tiny.xml"));
            try {
                Heightfield t = layer.simulation().world().terrain().heightfield();
                PerspectiveCamera cam = new PerspectiveCamera(55, 320, 180);
                cam.near = 0.05f;
                cam.far = 100f;
                cam.position.set(0, (float) t.height(0, 3) + 1.5f, 3);
                cam.lookAt(0, (float) t.height(0, 0), 0);
                cam.update();
                target.bind();
                com.sun.management.ThreadMXBean mx =
                        (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
                long self = Thread.currentThread().getId();
                for (int i = 0; i < 300; i++) { // warm up
                    layer.update(1 / 60f, cam);
                    layer.render(cam);
                }
                assertTrue(layer.renderer().triangles() > 0, "plants drawn");
                long least = Long.MAX_VALUE;
                for (int run = 0; run < 5; run++) {
                    long before = mx.getThreadAllocatedBytes(self);
                    for (int i = 0; i < 30; i++) {
                        layer.update(1 / 60f, cam);
                        layer.render(cam);
                    }
                    least = Math.min(least, mx.getThreadAllocatedBytes(self) - before);
                }
                assertEquals(0, least, "bytes allocated on the render thread by 30 frames of update and render");
            } finally {
                layer.dispose();
                target.close();
            }
            layer.dispose(); // idempotent
            PerspectiveCamera cam = new PerspectiveCamera();
            assertThrows(IllegalStateException.class, () -> layer.update(0.01f, cam));
            assertThrows(IllegalStateException.class, () -> layer.render(cam));
            GlContexts.debug(owner).check("the plant layer test");
        }
    }

    @Test
    void onASoftwareRasteriserTheLayerPicksTheLowQualityAndSaysSoOnceAndAGameChoiceWins() throws Exception {
        java.util.List<String> said = new java.util.concurrent.CopyOnWriteArrayList<>();
        java.util.logging.Logger log = java.util.logging.Logger.getLogger("org.jecosys.render");
        java.util.logging.Handler handler = new java.util.logging.Handler() {
            @Override
            public void publish(java.util.logging.LogRecord r) {
                said.add(r.getMessage());
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        log.addHandler(handler);
        try (GlContext owner = GlContext.headless(DebugOutput.ON)) {
            assertTrue(org.jecosys.render.ShadowPath.software(owner.describe()), "this test runs on llvmpipe: "
                    + owner.describe());
            PerspectiveCamera cam = new PerspectiveCamera(55, 320, 180);
            cam.update();
            PlantLayer auto = PlantLayer.load(new Lwjgl3Files().classpath("org/jecosys/gdx/tiny/tiny.xml"));
            try {
                assertEquals(org.jecosys.sim.DrawQuality.LOW, auto.quality());
                auto.update(1 / 30f, cam); // the thinning is a command: applied at the next step
                assertEquals(org.jecosys.sim.DrawQuality.LOW.thinStart(), auto.simulation().inspect().thinStart(), 0);
                assertEquals(org.jecosys.sim.DrawQuality.LOW.thinMinFraction(),
                        auto.simulation().inspect().thinMinFraction(), 0);
            } finally {
                auto.dispose();
            }
            assertEquals(1, said.size(), "said once for the layer: " + said);
            assertTrue(said.get(0).contains("low quality") && said.get(0).contains("llvmpipe"), said.get(0));
            org.jecosys.scene.Scene scene = GdxScenes.read(new Lwjgl3Files().classpath("org/jecosys/gdx/tiny/tiny.xml"));
            PlantLayer chosen = new PlantLayer(org.jecosys.scene.Scenes.simulation(scene, 0,
                    org.jecosys.math.Progress.NONE), org.jecosys.render.RenderSettings.of(scene.def()),
                    org.jecosys.sim.DrawQuality.HIGH);
            try {
                assertEquals(org.jecosys.sim.DrawQuality.HIGH, chosen.quality());
                chosen.update(1 / 30f, cam);
                assertEquals(org.jecosys.sim.DrawQuality.HIGH.thinMinFraction(),
                        chosen.simulation().inspect().thinMinFraction(), 0);
            } finally {
                chosen.dispose();
            }
            assertEquals(1, said.size(), "nothing said for the game's own choice: " + said);
        } finally {
            log.removeHandler(handler);
        }
    }

    @Test
    void everyCameraThatDrawsIsAViewUntilItStopsDrawing() throws Exception {
        try (GlContext owner = GlContext.headless(DebugOutput.ON)) {
            GlFramebuffer target = new GlFramebuffer(GlContexts.tracker(owner), 320, 180);
            PlantLayer layer = PlantLayer.load(new Lwjgl3Files().classpath("org/jecosys/gdx/tiny/tiny.xml"));
            try {
                Heightfield t = layer.simulation().world().terrain().heightfield();
                float y = (float) t.height(0, 0) + 1.5f;
                // the stepping camera looks at +X from the middle; the others at -X, +Z and -Z
                float[][] looks = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
                PerspectiveCamera[] cams = new PerspectiveCamera[looks.length];
                for (int c = 0; c < cams.length; c++) {
                    cams[c] = new PerspectiveCamera(40, 320, 180);
                    cams[c].near = 0.05f;
                    cams[c].far = 100f;
                    cams[c].position.set(0, y, 0);
                    cams[c].lookAt(looks[c][0], y - 0.8f, looks[c][1]);
                    cams[c].update();
                }
                org.jecosys.sim.World world = layer.simulation().world();
                target.bind();
                for (int i = 0; i < 5; i++) { // one camera only: plants behind it (x < -1) are not animated
                    layer.update(1 / 30f, cams[0]);
                    layer.render(cams[0]);
                }
                int behind = -1;
                for (int p = 0; p < world.plantCount() && behind < 0; p++) {
                    if (world.plantX(p) < -1.5 && Math.abs(world.plantZ(p)) < 1) {
                        behind = p;
                    }
                }
                assertTrue(behind >= 0, "a plant behind the stepping camera");
                assertTrue(!layer.simulation().inspect().plantVisible(behind), "not animated with one camera");
                assertEquals(0, layer.simulation().inspect().viewCount(), "registered views");
                for (int i = 0; i < 5; i++) { // four viewports, no addView call
                    layer.update(1 / 30f, cams[0]);
                    for (PerspectiveCamera c : cams) {
                        layer.render(c);
                    }
                }
                assertEquals(3, layer.drawnViews(), "the three other cameras are views");
                assertEquals(3, layer.simulation().inspect().viewCount(), "registered views");
                assertTrue(layer.simulation().inspect().plantVisible(behind), "animated for the camera that sees it");
                for (int i = 0; i < RenderedViews.IDLE_FRAMES + 3; i++) { // the other viewports are gone
                    layer.update(1 / 30f, cams[0]);
                    layer.render(cams[0]);
                }
                assertEquals(0, layer.drawnViews(), "their views dropped");
                assertEquals(0, layer.simulation().inspect().viewCount(), "registered views");
                assertTrue(!layer.simulation().inspect().plantVisible(behind), "no longer animated");
            } finally {
                layer.dispose();
                target.close();
            }
            GlContexts.debug(owner).check("the views test");
        }
    }
}
