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
 * nothing on the render thread; a disposed layer refuses both; a layer disposed and made again in a
 * new context draws the same picture; every camera that draws is a view (its own viewport animates)
 * until it stops drawing. Drawing inside a real libGDX application is the example's test.
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

    /**
     * Issue 38: three viewports side by side (the scene C1 seen from its middle in three directions,
     * 120 degrees apart), no {@code addView} call: the layer steps with the first camera and draws
     * all three; each viewport's picture changes between frames (what each camera sees animates).
     * Once the third viewport stops drawing, its view is dropped and fewer plants are animated (it
     * stops costing animation), while the other two keep changing.
     */
    @Test
    void threeViewportsAnimateWithoutAddViewAndARemovedOneStopsCosting() throws Exception {
        int w = 320;
        int h = 180;
        try (GlContext owner = GlContext.headless(DebugOutput.ON)) {
            GlFramebuffer target = new GlFramebuffer(GlContexts.tracker(owner), 3 * w, h);
            org.jecosys.scene.Scene scene = org.jecosys.scene.SceneFiles.read(java.nio.file.Path.of("scenes/c1.xml"));
            PlantLayer layer = new PlantLayer(org.jecosys.scene.Scenes.simulation(scene, 0,
                    org.jecosys.math.Progress.NONE), org.jecosys.render.RenderSettings.of(scene.def()));
            java.nio.ByteBuffer earlier = org.lwjgl.system.MemoryUtil.memAlloc(4 * 3 * w * h);
            java.nio.ByteBuffer later = org.lwjgl.system.MemoryUtil.memAlloc(earlier.capacity());
            try {
                org.jecosys.sim.World world = layer.simulation().world();
                float y = (float) world.terrain().heightfield().height(0, 0) + 1.6f;
                PerspectiveCamera[] cams = new PerspectiveCamera[3];
                for (int c = 0; c < cams.length; c++) {
                    double a = Math.toRadians(120 * c);
                    cams[c] = new PerspectiveCamera(50, w, h);
                    cams[c].near = 0.05f;
                    cams[c].far = 100f;
                    cams[c].position.set(0, y, 0);
                    cams[c].lookAt((float) (4 * Math.sin(a)), y - 1.6f, (float) (-4 * Math.cos(a)));
                    cams[c].update();
                }
                target.bind();
                int[] changed = frames(layer, cams, 3, w, h, earlier, later);
                int animated = animatedPlants(layer);
                assertEquals(2, layer.drawnViews(), "the two other cameras are views");
                System.out.println("[look] libGDX, three viewports without addView: pixels changed over 6 frames "
                        + java.util.Arrays.toString(changed) + ", " + animated + " plants animated");
                for (int c = 0; c < cams.length; c++) {
                    assertTrue(changed[c] >= 100, "viewport " + c + " animates: " + changed[c] + " pixels changed");
                }
                int[] two = null;
                for (int i = 0; i <= RenderedViews.IDLE_FRAMES / 10; i++) { // the third viewport is gone
                    two = frames(layer, cams, 2, w, h, earlier, later);
                }
                int fewer = animatedPlants(layer);
                System.out.println("[look] libGDX, the third viewport removed: its view dropped after "
                        + RenderedViews.IDLE_FRAMES + " updates, " + fewer + " plants animated (" + animated
                        + " with it), the other two change " + java.util.Arrays.toString(two));
                assertEquals(1, layer.drawnViews(), "the third camera's view is dropped");
                assertEquals(1, layer.simulation().inspect().viewCount(), "registered views");
                assertTrue(fewer < animated, "plants animated without the third viewport " + fewer + ", with it "
                        + animated);
                assertTrue(two[0] >= 100 && two[1] >= 100, "the other viewports animate: " + java.util.Arrays.toString(two));
            } finally {
                org.lwjgl.system.MemoryUtil.memFree(earlier);
                org.lwjgl.system.MemoryUtil.memFree(later);
                layer.dispose();
                target.close();
            }
            GlContexts.debug(owner).check("the three viewports test");
        }
    }

    /**
     * Ten frames: the layer steps with the first camera and draws the first {@code drawn} of them, each
     * in its own viewport, side by side. {@return per viewport, the pixels that differ between the
     * fourth frame and the tenth}
     */
    private static int[] frames(PlantLayer layer, PerspectiveCamera[] cams, int drawn, int w, int h,
                                java.nio.ByteBuffer earlier, java.nio.ByteBuffer later) {
        for (int i = 0; i < 10; i++) {
            layer.update(1 / 30f, cams[0]);
            org.lwjgl.opengl.GL11C.glViewport(0, 0, cams.length * w, h);
            org.lwjgl.opengl.GL11C.glClearColor(0.6f, 0.75f, 0.9f, 1f);
            org.lwjgl.opengl.GL11C.glClear(org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT
                    | org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT);
            for (int c = 0; c < drawn; c++) {
                org.lwjgl.opengl.GL11C.glViewport(c * w, 0, w, h);
                layer.render(cams[c]);
            }
            if (i == 3 || i == 9) {
                org.jecosys.render.gl.Pixels.read(cams.length * w, h, i == 3 ? earlier : later);
            }
        }
        int[] changed = new int[cams.length];
        for (int p = 0; p < earlier.capacity(); p += 4) {
            if (earlier.getInt(p) != later.getInt(p)) {
                changed[p / 4 % (cams.length * w) / w]++;
            }
        }
        return changed;
    }

    /** {@return the plants the simulation animates now (visible to one of its views)} */
    private static int animatedPlants(PlantLayer layer) {
        int n = 0;
        for (int p = 0; p < layer.simulation().world().plantCount(); p++) {
            n += layer.simulation().inspect().plantVisible(p) ? 1 : 0;
        }
        return n;
    }

    /**
     * Issue 38: a layer disposed and made again in a new GL context (a game that makes its window
     * again) draws the same picture: the scene C1 from its start camera with the simulation at the
     * same step, in a first headless context and, after the layer is disposed and that context
     * closed, in a second one; mean difference at most 1/255 a channel.
     */
    @Test
    void aLayerDisposedAndMadeAgainInANewContextDrawsTheSame() throws Exception {
        int[] before = c1Picture();
        int[] after = c1Picture();
        double diff = 0;
        int plant = 0;
        for (int i = 0; i < before.length; i++) {
            int p = before[i];
            int q = after[i];
            diff += Math.abs((p >> 16 & 255) - (q >> 16 & 255)) + Math.abs((p >> 8 & 255) - (q >> 8 & 255))
                    + Math.abs((p & 255) - (q & 255));
            plant += p != SKY ? 1 : 0;
        }
        diff /= 3.0 * before.length;
        System.out.printf("[look] libGDX, a plant layer disposed and made again in a new GL context: %d plant pixels,"
                + " mean difference %.4f levels a channel (<= 1)%n", plant, diff);
        assertTrue(plant > 1000, "plants drawn: " + plant + " pixels");
        assertTrue(diff <= 1.0, "mean difference " + diff + " levels a channel");
    }

    /** The sky colour the C1 pictures are cleared to, 0xRRGGBB. */
    private static final int SKY = 0x99BFE6;

    /**
     * C1's start view at 320 x 180 after 30 updates of 1/30 s, drawn by a layer made in a context of
     * its own; the layer is disposed and the context closed before it returns. {@return 0xRRGGBB, GL rows}
     */
    private static int[] c1Picture() throws Exception {
        int w = 320;
        int h = 180;
        try (GlContext owner = GlContext.headless(DebugOutput.ON)) {
            GlFramebuffer target = new GlFramebuffer(GlContexts.tracker(owner), w, h);
            org.jecosys.scene.Scene scene = org.jecosys.scene.SceneFiles.read(java.nio.file.Path.of("scenes/c1.xml"));
            PlantLayer layer = new PlantLayer(org.jecosys.scene.Scenes.simulation(scene, 0,
                    org.jecosys.math.Progress.NONE), org.jecosys.render.RenderSettings.of(scene.def()));
            java.nio.ByteBuffer px = org.lwjgl.system.MemoryUtil.memAlloc(4 * w * h);
            try {
                org.jecosys.math.CameraDef c = scene.def().camera();
                org.jecosys.math.ViewCamera v = org.jecosys.math.ViewCamera.of(c,
                        layer.simulation().world().terrain().heightfield().height(c.x(), c.z()), w / (double) h);
                org.joml.Vector3f ahead = v.forward(new org.joml.Vector3f());
                PerspectiveCamera cam = new PerspectiveCamera((float) Math.toDegrees(v.fovY()), w, h);
                cam.near = (float) v.near();
                cam.far = (float) v.far();
                cam.position.set((float) v.x(), (float) v.y(), (float) v.z());
                cam.direction.set(ahead.x, ahead.y, ahead.z);
                cam.update();
                target.bind();
                for (int i = 0; i < 30; i++) {
                    layer.update(1 / 30f, cam);
                }
                org.lwjgl.opengl.GL11C.glViewport(0, 0, w, h);
                org.lwjgl.opengl.GL11C.glClearColor((SKY >> 16 & 255) / 255f, (SKY >> 8 & 255) / 255f,
                        (SKY & 255) / 255f, 1f);
                org.lwjgl.opengl.GL11C.glClear(org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT
                        | org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT);
                layer.render(cam);
                org.jecosys.render.gl.Pixels.read(w, h, px);
                int[] rgb = new int[w * h];
                for (int i = 0; i < rgb.length; i++) {
                    rgb[i] = (px.get(4 * i) & 255) << 16 | (px.get(4 * i + 1) & 255) << 8 | (px.get(4 * i + 2) & 255);
                }
                return rgb;
            } finally {
                org.lwjgl.system.MemoryUtil.memFree(px);
                layer.dispose();
                target.close();
                GlContexts.debug(owner).check("a plant layer in a context of its own");
            }
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
