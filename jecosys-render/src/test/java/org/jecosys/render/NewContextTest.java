package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.Pixels;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.opengl.GL15C;
import org.lwjgl.system.MemoryUtil;

/**
 * A host replaces its context under a renderer (what jMonkeyEngine's {@code app.restart()} does):
 * the library wraps a host's headless context, draws, the host destroys that context and makes a new
 * one current on the same thread, and the next {@code render} notices, forgets the old objects without
 * a GL call (a name the host made in the new context survives) and draws the same pixels in the new
 * context, with no GL error and no name left over.
 */
class NewContextTest {
    private static final int W = 200;
    private static final int H = 120;

    private static ViewCamera camera() {
        ViewCamera c = new ViewCamera();
        c.setPosition(0, 1.6, 9);
        c.setOrientation(0, -0.2);
        c.setLens(Math.toRadians(50), W / (double) H, 0.05, 200);
        return c;
    }

    /** The host's frame: its own framebuffer cleared to magenta, the plants drawn over it. */
    private static void hostFrame(SceneRenderer renderer, Frame frame, ByteBuffer out) {
        try (GlFramebuffer fb = new GlFramebuffer(new GlTracker(), W, H)) {
            fb.bind();
            GL11C.glViewport(0, 0, W, H);
            GL11C.glClearColor(1, 0, 1, 1);
            GL11C.glClear(GL11C.GL_COLOR_BUFFER_BIT | GL11C.GL_DEPTH_BUFFER_BIT);
            renderer.render(frame, camera());
            Pixels.read(W, H, out);
            org.lwjgl.opengl.GL30C.glBindFramebuffer(org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER, 0);
        }
    }

    private static int plantPixels(ByteBuffer p) {
        int n = 0;
        for (int i = 0; i < W * H; i++) {
            boolean magenta = (p.get(4 * i) & 0xff) == 255 && (p.get(4 * i + 1) & 0xff) == 0
                    && (p.get(4 * i + 2) & 0xff) == 255;
            n += magenta ? 0 : 1;
        }
        return n;
    }

    @Test
    void aReplacedContextIsNoticedAndTheRendererDrawsTheSameInTheNewOne() {
        World world = RenderScenes.build(RenderScenes.load("c1.xml"));
        ByteBuffer before = MemoryUtil.memAlloc(4 * W * H);
        ByteBuffer after = MemoryUtil.memAlloc(4 * W * H);
        GlContext host = GlContext.headless(DebugOutput.ON);
        GlContext gl = null;
        try {
            gl = GlContext.current(DebugOutput.ON);
            GlTracker tracker = GlContexts.tracker(gl);
            RenderSettings settings = RenderSettings.standalone();
            settings.setClear(false);
            settings.setTerrain(false);
            SceneRenderer renderer = new SceneRenderer(gl, world, settings);
            Frame frame = TestFrames.wind(world, 0.4, camera());
            hostFrame(renderer, frame, before);
            GlContexts.debug(gl).check("the first context");
            int objects = tracker.live();
            assertTrue(objects > 10, "GL objects of the renderer: " + objects);
            assertEquals(0, gl.generation());

            // the host destroys its context and makes a new one current on this thread
            host.close();
            host = GlContext.headless(DebugOutput.ON);
            int hostBuffer = GL15C.glGenBuffers(); // a name the host made in the new context
            GL15C.glBindBuffer(GL15C.GL_ARRAY_BUFFER, hostBuffer);
            GL15C.glBindBuffer(GL15C.GL_ARRAY_BUFFER, 0);

            hostFrame(renderer, frame, after);
            assertEquals(1, gl.generation(), "the replaced context was noticed");
            assertTrue(GL15C.glIsBuffer(hostBuffer), "the host's buffer survives: no old name was deleted");
            GlContexts.debug(gl).check("the new context");
            assertEquals(objects, tracker.live(), "objects live after the rebuild: the new ones only");
            assertEquals(objects, tracker.abandoned(), "old objects forgotten without a GL call");

            int plants = plantPixels(before);
            assertTrue(plants > 500, "plant pixels before: " + plants);
            int differing = 0;
            long diff = 0;
            for (int i = 0; i < 4 * W * H; i++) {
                int d = Math.abs((before.get(i) & 0xff) - (after.get(i) & 0xff));
                diff += d;
                differing += d > 0 && i % 4 == 0 ? 1 : 0;
            }
            System.out.printf("[new-context] plant pixels %d before, %d after; channel values differing by %d in total, "
                    + "%d pixels' red differs; %d objects made again, %d forgotten%n", plants, plantPixels(after),
                    diff, differing, tracker.live(), tracker.abandoned());
            assertEquals(plants, plantPixels(after), "plant pixels after the new context");
            assertTrue(diff <= W * H / 100, "summed channel difference " + diff);

            // a second frame in the new context makes nothing again
            hostFrame(renderer, frame, after);
            assertEquals(1, gl.generation());
            assertEquals(objects, tracker.live());
            renderer.close();
            assertEquals(0, tracker.live(), "GL objects left after close");
            GlContexts.debug(gl).check("close in the new context");
            GL15C.glDeleteBuffers(hostBuffer);
        } finally {
            if (gl != null) {
                gl.close();
            }
            host.close();
            MemoryUtil.memFree((java.nio.Buffer) before);
            MemoryUtil.memFree((java.nio.Buffer) after);
        }
    }

    @Test
    void closingARendererAfterItsContextIsGoneMakesNoGlCallAndOwnedContextsAreNeverReplaced() {
        World world = RenderScenes.build(RenderScenes.load("c1.xml"));
        GlContext gl = GlContext.headless(DebugOutput.ON);
        GlTracker tracker = GlContexts.tracker(gl);
        SceneRenderer renderer;
        try {
            assertThrows(IllegalStateException.class, gl::contextReplaced);
            renderer = new SceneRenderer(gl, world, RenderSettings.standalone());
            assertNotEquals(0, tracker.live());
        } finally {
            gl.close();
        }
        assertEquals(1, gl.generation(), "closing a context the library made ends its generation");
        // no context is current any more: a GL call here would crash or fail
        renderer.close();
        assertEquals(0, tracker.live());
    }
}
