package org.jecosys.jme;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.app.LegacyApplication;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import com.jme3.renderer.RenderManager;
import com.jme3.renderer.ViewPort;
import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Simulation;
import org.junit.jupiter.api.Test;

/**
 * The game's other viewports through {@link PlantAppState#addViewPort}: each one's camera is a view of
 * the simulation while the viewport is enabled and attached, and not once it is disabled, detached or
 * removed; three viewports (the main one and two added) each show moving plants, and a removed one
 * stops costing animation. jME's render manager needs no window for its viewports; the renderer draws
 * in a headless context standing in for jME's.
 */
class ViewPortsTest {
    /** An application whose render manager and main viewport exist without a window. */
    static final class Headless extends LegacyApplication {
        Headless() {
            renderManager = new RenderManager(null);
            cam = camera();
            viewPort = renderManager.createMainView("main", cam);
        }
    }

    static Camera camera() {
        Camera c = new Camera(320, 180);
        c.setFrustumPerspective(50, 320 / 180f, 0.05f, 200f);
        c.setLocation(new Vector3f(0, 2, 8));
        c.lookAt(new Vector3f(0, 0, 0), Vector3f.UNIT_Y);
        return c;
    }

    @Test
    void addedViewPortsAreViewsWhileTheyDraw() throws Exception {
        Scene scene = SceneFiles.read(Path.of("jecosys-jme/src/test/resources/org/jecosys/jme/tiny/tiny.xml"));
        Simulation sim = Scenes.simulation(scene, 1, Progress.NONE);
        try (GlContext owner = GlContext.headless(DebugOutput.ON)) {
            Headless app = new Headless();
            PlantAppState state = new PlantAppState(sim, RenderSettings.of(scene.def()));
            assertThrows(IllegalStateException.class, () -> state.addViewPort(app.getViewPort()));
            state.initialize(app);
            try {
                RenderManager rm = app.getRenderManager();
                ViewPort mini = rm.createMainView("minimap", camera());
                ViewPort mirror = rm.createPostView("mirror", camera());
                state.addViewPort(mini);
                state.addViewPort(mirror);
                assertThrows(IllegalArgumentException.class, () -> state.addViewPort(mini));
                assertThrows(IllegalArgumentException.class, () -> state.addViewPort(app.getViewPort()));
                assertEquals(2, state.viewedViewPorts());
                assertEquals(2, sim.inspect().viewCount());
                state.update(1 / 30f);
                assertEquals(2, sim.inspect().viewCount());
                mini.setEnabled(false); // a disabled viewport stops costing animation
                state.update(1 / 30f);
                assertEquals(1, state.viewedViewPorts());
                assertEquals(1, sim.inspect().viewCount());
                mini.setEnabled(true);
                state.update(1 / 30f);
                assertEquals(2, sim.inspect().viewCount());
                rm.removePostView(mirror); // detached from the render manager
                state.update(1 / 30f);
                assertEquals(1, sim.inspect().viewCount());
                assertTrue(state.removeViewPort(mini));
                assertFalse(state.removeViewPort(mini));
                assertEquals(0, sim.inspect().viewCount());
                assertEquals(0, state.viewedViewPorts());
            } finally {
                state.cleanup(app);
            }
        }
    }

    /**
     * Issue 38: three viewports (the main one and two added with {@link PlantAppState#addViewPort}, no
     * {@code Simulation.addView} call), the scene C1 seen from its middle in three directions 120
     * degrees apart, drawn side by side: each viewport's picture changes between frames (what each
     * camera sees animates). Once the third is removed, fewer plants are animated (it stops costing
     * animation) and the other two keep changing.
     */
    @Test
    void threeViewPortsAnimateAndARemovedOneStopsCosting() throws Exception {
        int w = 320;
        int h = 180;
        Scene scene = SceneFiles.read(Path.of("scenes/c1.xml"));
        Simulation sim = Scenes.simulation(scene, 0, Progress.NONE);
        try (GlContext owner = GlContext.headless(DebugOutput.ON)) {
            GlFramebuffer target = new GlFramebuffer(GlContexts.tracker(owner), 3 * w, h);
            java.nio.ByteBuffer earlier = org.lwjgl.system.MemoryUtil.memAlloc(4 * 3 * w * h);
            java.nio.ByteBuffer later = org.lwjgl.system.MemoryUtil.memAlloc(earlier.capacity());
            Headless app = new Headless();
            PlantAppState state = new PlantAppState(sim, RenderSettings.of(scene.def()));
            state.initialize(app);
            try {
                float y = (float) sim.world().terrain().heightfield().height(0, 0) + 1.6f;
                ViewPort[] vps = new ViewPort[3];
                for (int c = 0; c < vps.length; c++) {
                    double a = Math.toRadians(120 * c);
                    Camera cam = c == 0 ? app.getCamera() : new Camera(w, h);
                    cam.resize(w, h, true);
                    cam.setFrustumPerspective(50, w / (float) h, 0.05f, 100f);
                    cam.setLocation(new Vector3f(0, y, 0));
                    cam.lookAt(new Vector3f((float) (4 * Math.sin(a)), y - 1.6f, (float) (-4 * Math.cos(a))),
                            Vector3f.UNIT_Y);
                    cam.update();
                    vps[c] = c == 0 ? app.getViewPort() : app.getRenderManager().createMainView("view " + c, cam);
                    if (c > 0) {
                        state.addViewPort(vps[c]);
                    }
                }
                target.bind();
                int[] changed = frames(state, vps, w, h, earlier, later);
                int animated = animatedPlants(sim);
                System.out.println("[look] jME, three viewports (main and two addViewPort): pixels changed over 6"
                        + " frames " + java.util.Arrays.toString(changed) + ", " + animated + " plants animated");
                for (int c = 0; c < vps.length; c++) {
                    assertTrue(changed[c] >= 100, "viewport " + c + " animates: " + changed[c] + " pixels changed");
                }
                assertTrue(state.removeViewPort(vps[2]));
                int[] two = frames(state, vps, w, h, earlier, later);
                int fewer = animatedPlants(sim);
                System.out.println("[look] jME, the third viewport removed: " + fewer + " plants animated (" + animated
                        + " with it), the other two change " + java.util.Arrays.toString(two));
                assertEquals(1, sim.inspect().viewCount(), "registered views");
                assertTrue(fewer < animated, "plants animated without the third viewport " + fewer + ", with it "
                        + animated);
                assertTrue(two[0] >= 100 && two[1] >= 100, "the other viewports animate: " + java.util.Arrays.toString(two));
                assertEquals(0, two[2], "the removed viewport is not drawn");
            } finally {
                state.cleanup(app);
                org.lwjgl.system.MemoryUtil.memFree(earlier);
                org.lwjgl.system.MemoryUtil.memFree(later);
                target.close();
            }
            GlContexts.debug(owner).check("the three viewports test");
        }
    }

    /**
     * Ten frames: the state steps, then each viewport draws through its processors (as jME's render
     * manager calls them after the viewport's scene) in its own third of the target. {@return per
     * viewport, the pixels that differ between the fourth frame and the tenth}
     */
    private static int[] frames(PlantAppState state, ViewPort[] vps, int w, int h, java.nio.ByteBuffer earlier,
                                java.nio.ByteBuffer later) {
        for (int i = 0; i < 10; i++) {
            state.update(1 / 30f);
            org.lwjgl.opengl.GL11C.glViewport(0, 0, vps.length * w, h);
            org.lwjgl.opengl.GL11C.glClearColor(0.6f, 0.75f, 0.9f, 1f);
            org.lwjgl.opengl.GL11C.glClear(org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT
                    | org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT);
            for (int c = 0; c < vps.length; c++) {
                org.lwjgl.opengl.GL11C.glViewport(c * w, 0, w, h);
                for (com.jme3.post.SceneProcessor p : vps[c].getProcessors()) {
                    p.postFrame(null);
                }
            }
            if (i == 3 || i == 9) {
                org.jecosys.render.gl.Pixels.read(vps.length * w, h, i == 3 ? earlier : later);
            }
        }
        int[] changed = new int[vps.length];
        for (int p = 0; p < earlier.capacity(); p += 4) {
            if (earlier.getInt(p) != later.getInt(p)) {
                changed[p / 4 % (vps.length * w) / w]++;
            }
        }
        return changed;
    }

    /** {@return the plants the simulation animates now (visible to one of its views)} */
    private static int animatedPlants(Simulation sim) {
        int n = 0;
        for (int p = 0; p < sim.world().plantCount(); p++) {
            n += sim.inspect().plantVisible(p) ? 1 : 0;
        }
        return n;
    }
}
