package org.jecosys.jme;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.light.AmbientLight;
import com.jme3.light.DirectionalLight;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import com.jme3.scene.Node;
import java.lang.management.ManagementFactory;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.Lighting;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Simulation;
import org.jecosys.terrain.Heightfield;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;

/**
 * The game's jME lights light the plants ({@link PlantAppState#setLightsFrom}): moving the root node's
 * sun changes the plants exactly as the same values set on the renderer's {@link Lighting} directly do
 * (within 2/255 per channel); the values are jME's (the sun opposite the light's direction, ambient
 * lights summed, the haze off for jME's fog filter), gamma-corrected colours are encoded to display
 * values, a node without lights keeps the settings' light, and reading the lights every frame
 * allocates nothing. jME's render manager needs no window; the renderer draws in a headless context
 * standing in for jME's, the paper's scene C1 seen from 4 m.
 */
class HostLightTest {
    private static final int W = 320;
    private static final int H = 180;

    @Test
    void theRootNodesSunLightsThePlantsAsTheSameValuesSetDirectly() throws Exception {
        Scene scene = SceneFiles.read(Path.of("scenes/c1.xml"));
        Simulation sim = Scenes.simulation(scene, 1, Progress.NONE);
        ByteBuffer px = MemoryUtil.memAlloc(4 * W * H);
        try (GlContext owner = GlContext.headless(DebugOutput.ON)) {
            GlFramebuffer target = new GlFramebuffer(GlContexts.tracker(owner), W, H);
            ViewPortsTest.Headless app = new ViewPortsTest.Headless();
            Heightfield t = sim.world().terrain().heightfield();
            Camera cam = app.getViewPort().getCamera();
            cam.setFrustumPerspective(55, W / (float) H, 0.05f, 100f);
            cam.setLocation(new Vector3f(0, (float) t.height(0, 4) + 1.2f, 4));
            cam.lookAt(new Vector3f(0, (float) t.height(0, 0), 0), Vector3f.UNIT_Y);
            Node root = new Node("root");
            DirectionalLight sun = new DirectionalLight(new Vector3f(-0.4f, -0.8f, -0.3f), new ColorRGBA(1.3f, 1.2f, 1f, 1f));
            root.addLight(sun);
            root.addLight(new AmbientLight(new ColorRGBA(0.2f, 0.25f, 0.3f, 1f)));
            root.addLight(new AmbientLight(new ColorRGBA(0.1f, 0.1f, 0.1f, 1f)));
            PlantAppState state = new PlantAppState(sim, RenderSettings.of(scene.def()));
            assertEquals(null, state.lightsFrom(), "the root node is chosen at initialisation");
            state.setLightsFrom(root);
            state.initialize(app);
            try {
                assertSame(root, state.lightsFrom());
                JmeCamera view = new JmeCamera();
                for (int i = 0; i < 10; i++) {
                    state.update(1 / 30f);
                }
                Lighting l = state.settings().lighting();
                float len = (float) Math.sqrt(0.16 + 0.64 + 0.09);
                assertEquals(0.4f / len, l.sunX(), 1e-5f, "toward the sun: opposite the light's direction");
                assertEquals(0.8f / len, l.sunY(), 1e-5f);
                assertEquals(1.3f, l.sunR(), 0f, "a light brighter than 1, kept (no gamma correction here)");
                assertEquals(0.35f, l.ambientG(), 1e-6f, "the ambient lights summed");
                assertFalse(l.hasFog(), "jME's fog is its filter's, over the plants too");
                int[] hosted = shot(state, view, cam, target, px);
                int[] none = blank(target, px);
                double plantsShare = changed(hosted, none, 8);
                // flower parts keep a least size in proportion to the picture (8 px at 540 rows): at 180 rows
                // a third of that, so C1's sparse plants cover about 0.9% of it
                assertTrue(plantsShare > 0.005, "plants in the picture: " + plantsShare);

                // the same values set directly, with the node no longer followed
                state.setLightsFrom(null);
                l.set(new Lighting());
                l.setSunDirection(0.4f, 0.8f, 0.3f);
                l.setSunColour(1.3f, 1.2f, 1f);
                l.setSunIntensity(1f);
                l.setAmbient(0.3f, 0.35f, 0.4f);
                l.setNoFog();
                state.update(0f);
                int[] direct = shot(state, view, cam, target, px);
                assertTrue(maxDiff(hosted, direct) <= 2, "the node's light vs the same values set directly: "
                        + maxDiff(hosted, direct));

                // moving the game's sun changes the plants as moving the renderer's does
                state.setLightsFrom(root);
                sun.setDirection(new Vector3f(0.6f, -0.5f, 0.2f));
                sun.setColor(new ColorRGBA(1f, 0.6f, 0.4f, 1f));
                state.update(0f);
                int[] moved = shot(state, view, cam, target, px);
                state.setLightsFrom(null);
                l.setSunDirection(-0.6f, 0.5f, -0.2f);
                l.setSunColour(1f, 0.6f, 0.4f);
                int[] movedDirect = shot(state, view, cam, target, px);
                double change = changed(hosted, moved, 6);
                System.out.printf("[look] jME root-node lights: plants %.3f of the picture; moving the sun changed "
                        + "%.3f of it; max channel difference to the same light set directly %d/255%n",
                        plantsShare, change, maxDiff(moved, movedDirect));
                assertTrue(change > 0.5 * plantsShare, "the plants changed with the sun: " + change);
                assertTrue(maxDiff(moved, movedDirect) <= 2, "moved: " + maxDiff(moved, movedDirect));

                // a node without lights leaves the light as it was
                Node unlit = new Node("unlit");
                state.setLightsFrom(unlit);
                state.update(0f);
                assertEquals(-0.6f / (float) Math.sqrt(0.36 + 0.25 + 0.04), l.sunX(), 1e-5f);
                assertEquals(1f, l.sunIntensity(), 0f);

                state.setLightsFrom(root);
                com.sun.management.ThreadMXBean mx =
                        (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
                long self = Thread.currentThread().getId();
                for (int i = 0; i < 200; i++) { // warm up
                    state.update(1 / 60f);
                }
                long least = Long.MAX_VALUE;
                for (int run = 0; run < 4; run++) {
                    long before = mx.getThreadAllocatedBytes(self);
                    for (int i = 0; i < 50; i++) {
                        state.update(1 / 60f);
                    }
                    least = Math.min(least, mx.getThreadAllocatedBytes(self) - before);
                }
                assertEquals(0, least, "bytes allocated by 50 updates reading the lights");
            } finally {
                state.cleanup(app);
                target.close();
                MemoryUtil.memFree(px);
            }
            GlContexts.debug(owner).check("the jME host light test");
        }
    }

    @Test
    void withGammaCorrectionLinearLightColoursAreEncodedToDisplayValues() {
        assertEquals(0f, JmeLights.display(0f, true), 0f);
        assertEquals(1f, JmeLights.display(1f, true), 1e-6f);
        assertEquals(0.7354f, JmeLights.display(0.5f, true), 1e-3f, "sRGB of linear 0.5");
        assertEquals(0.5f, JmeLights.display(0.5f, false), 0f);
        assertEquals(Lighting.MAX_LIGHT, JmeLights.display(9f, false), 0f, "clamped to the renderer's range");
    }

    private static int[] blank(GlFramebuffer target, ByteBuffer px) {
        target.bind();
        org.lwjgl.opengl.GL11C.glClearColor(0.2f, 0.2f, 0.2f, 1f);
        org.lwjgl.opengl.GL11C.glClear(org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT
                | org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT);
        return read(px);
    }

    private static int[] shot(PlantAppState state, JmeCamera view, Camera cam, GlFramebuffer target, ByteBuffer px) {
        blank(target, px);
        state.renderer().render(state.simulation().latestFrame(), view.update(cam));
        return read(px);
    }

    private static int[] read(ByteBuffer px) {
        Pixels.read(W, H, px);
        int[] rgb = new int[W * H];
        for (int i = 0; i < W * H; i++) {
            rgb[i] = (px.get(4 * i) & 255) << 16 | (px.get(4 * i + 1) & 255) << 8 | (px.get(4 * i + 2) & 255);
        }
        return rgb;
    }

    private static int maxDiff(int[] a, int[] b) {
        int m = 0;
        for (int i = 0; i < a.length; i++) {
            for (int s = 0; s <= 16; s += 8) {
                m = Math.max(m, Math.abs((a[i] >> s & 255) - (b[i] >> s & 255)));
            }
        }
        return m;
    }

    /** The share of pixels where a channel differs by more than {@code tolerance}. */
    private static double changed(int[] a, int[] b, int tolerance) {
        int n = 0;
        for (int i = 0; i < a.length; i++) {
            for (int s = 0; s <= 16; s += 8) {
                if (Math.abs((a[i] >> s & 255) - (b[i] >> s & 255)) > tolerance) {
                    n++;
                    break;
                }
            }
        }
        return n / (double) a.length;
    }
}
