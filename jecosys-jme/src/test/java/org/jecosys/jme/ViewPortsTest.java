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
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Simulation;
import org.junit.jupiter.api.Test;

/**
 * The game's other viewports through {@link PlantAppState#addViewPort}: each one's camera is a view of
 * the simulation while the viewport is enabled and attached, and not once it is disabled, detached or
 * removed. jME's render manager needs no window for its viewports; the renderer draws in a headless
 * context standing in for jME's.
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
}
