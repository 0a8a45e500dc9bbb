package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Simulation;
import org.junit.jupiter.api.Test;

/**
 * A camera the game draws with but never registered freezes what only it sees; the renderer says so
 * once in the log, naming the remedy, and says nothing for a camera registered with
 * {@link Simulation#addView}.
 */
class UnregisteredViewTest {
    private static ViewCamera looking(double yaw) {
        ViewCamera c = new ViewCamera();
        c.setPosition(0, 1.5, 0);
        c.setOrientation(yaw, -0.3);
        c.setLens(Math.toRadians(50), 16 / 9.0, 0.05, 200);
        return c;
    }

    private static List<String> run(boolean register) throws Exception {
        return run(register, true, "scenes/meadow.xml");
    }

    /** What the log says while two cameras draw {@code scene}; {@code step}: the simulation steps between frames. */
    private static List<String> run(boolean register, boolean step, String scene) throws Exception {
        List<String> said = new CopyOnWriteArrayList<>();
        Handler handler = new Handler() {
            @Override
            public void publish(LogRecord r) {
                said.add(r.getMessage());
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        Logger log = Logger.getLogger("org.jecosys.render");
        log.addHandler(handler);
        try (Simulation sim = Scenes.simulation(Path.of(scene), Progress.NONE);
             GlContext gl = GlContext.headless(DebugOutput.ON);
             GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), 320, 180);
             SceneRenderer renderer = new SceneRenderer(gl, sim.world(), new RenderSettings())) {
            ViewCamera front = looking(0);
            ViewCamera back = looking(Math.PI); // sees what the stepping camera does not
            if (register) {
                sim.addView(back);
            }
            fb.bind();
            for (int i = 0; i < 4; i++) {
                if (step) {
                    sim.stepFixed(front);
                }
                renderer.render(sim.latestFrame(), front, 320, 180);
                renderer.render(sim.latestFrame(), back, 320, 180);
            }
            assertTrue(renderer.triangles() > 0, "the back camera draws plants");
            GlContexts.debug(gl).check("the unregistered view test");
        } finally {
            log.removeHandler(handler);
        }
        return said;
    }

    @Test
    void aCameraNoViewCoversIsNamedOnceAndARegisteredOneIsNot() throws Exception {
        List<String> unregistered = run(false);
        assertEquals(1, unregistered.size(), "said once: " + unregistered);
        assertTrue(unregistered.get(0).contains("Simulation.addView"), unregistered.get(0));
        assertEquals(List.of(), run(true), "nothing said for a registered camera");
    }

    @Test
    void framesNoStepHasWrittenYetSayNothing() throws Exception {
        // the viewer's first frames, drawn before its first fixed step: every plant stands still for any view
        // (C1: 80 plants, every one drawn by the back camera, more than the 50 that would be named)
        assertEquals(List.of(), run(false, false, "scenes/c1.xml"), "nothing said before the first step");
    }
}
