package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.render.GlContext.DebugOutput;
import com.sun.management.ThreadMXBean;
import java.lang.management.ManagementFactory;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.overlay.FieldOverlay;

/**
 * Scene C1, headless: a renderer whose construction fails part way releases the GL objects it had
 * already made (every possible failure point, counted with {@link GlTracker}), and rendering
 * allocates nothing on the render thread after warm-up.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class RenderResourcesTest {
    private static final int W = 160;
    private static final int H = 100;
    /** Frames before the allocation is measured: the first ones make the shadow map and its programs. */
    private static final int WARM_UP_FRAMES = 20;
    /** Frames per measured window. */
    private static final int WINDOW_FRAMES = 50;
    /** Cached once: ManagementFactory.getThreadMXBean() itself allocates. */
    private static final ThreadMXBean THREADS = (ThreadMXBean) ManagementFactory.getThreadMXBean();

    private World world;
    private ViewCamera camera;
    private GlContext gl;
    private GlFramebuffer fb;

    @BeforeAll
    void setUp() {
        SceneDef def = RenderScenes.load("c1.xml");
        world = RenderScenes.build(def);
        camera = RenderScenes.camera(def, world, W, H);
        gl = GlContext.headless(DebugOutput.ON);
        fb = new GlFramebuffer(gl.tracker(), W, H);
    }

    @AfterEach
    void noGlErrors() {
        gl.debug().check("the test");
    }

    @AfterAll
    void tearDown() {
        if (fb != null) {
            fb.close();
        }
        if (gl != null) {
            assertEquals(0, gl.tracker().live(), "every GL object released");
            gl.close();
        }
    }

    @Test
    void aConstructorFailingPartWayReleasesWhatItMade() {
        int before = gl.tracker().live();
        long created = gl.tracker().createdTotal();
        try (SceneRenderer r = new SceneRenderer(gl, world, RenderSettings.standalone())) {
            assertTrue(r.triangles() >= 0);
        }
        int objects = (int) (gl.tracker().createdTotal() - created);
        assertTrue(objects > 10, "a scene renderer makes " + objects + " GL objects");
        for (int n = 0; n < objects; n++) {
            gl.tracker().failAfter(n);
            int failAt = n;
            IllegalStateException e = assertThrows(IllegalStateException.class,
                    () -> new SceneRenderer(gl, world, RenderSettings.standalone()), "failure at object " + n);
            assertTrue(e.getMessage().contains("injected"), e.getMessage());
            assertEquals(before, gl.tracker().live(), "GL objects left after a failure at object " + failAt);
        }
        gl.tracker().failAfter(-1);
        for (int n = 0; n < 3; n++) {
            gl.tracker().failAfter(n);
            assertThrows(IllegalStateException.class, () -> new GlFramebuffer(gl.tracker(), 8, 8));
            assertEquals(before, gl.tracker().live(), "framebuffer failing at object " + n);
        }
        gl.tracker().failAfter(-1);
    }

    @Test
    void everyGlObjectTheRendererMakesIsTrackedAndReleased() {
        for (ResolvePath path : ResolvePath.values()) {
            if (path.supported(gl.capabilities())) {
                everyGlObjectIsTrackedAndReleased(path);
            }
        }
    }

    private void everyGlObjectIsTrackedAndReleased(ResolvePath path) {
        // the driver's own count of live objects, whoever made them, against GlTracker's
        GlCensus before = GlCensus.take();
        int tracked = gl.tracker().live();
        GlCensus during;
        // with the shadow map drawn: its depth texture, framebuffer and programs are tracked too
        RenderSettings mapped = RenderSettings.standalone();
        mapped.setShadows(0.6f);
        mapped.setShadowPath(ShadowPath.MAP);
        try (SceneRenderer r = new SceneRenderer(gl, world, mapped, path);
             FieldOverlay overlay = new FieldOverlay(gl, world.terrain().heightfield())) {
            fb.bind();
            r.render(TestFrames.wind(world, 0.5, camera), camera, W, H);
            during = GlCensus.take().minus(before);
            assertTrue(during.total() > 10, "objects: " + during);
            assertEquals(path, r.plants().path());
            assertEquals(gl.tracker().live() - tracked, during.total(),
                    path + ": every object made is a tracked Gl* wrapper (no stray shader or buffer): " + during);
            assertEquals(0, during.shaders(), "shaders are deleted once linked");
        }
        assertEquals(tracked, gl.tracker().live());
        assertEquals(before, GlCensus.take(), path + ": closing released every object the driver knows of (there were "
                + during + ")");
    }

    @Test
    void renderingAllocatesNothingAfterWarmUp() {
        Frame[] frames = new Frame[4];
        for (int i = 0; i < frames.length; i++) {
            frames[i] = TestFrames.wind(world, 0.25 * i, camera);
        }
        long thread = Thread.currentThread().getId();
        // with ground cover: its blades (tiles, bend map) are drawn every frame too
        RenderSettings covered = RenderSettings.standalone();
        covered.setGroundCover(new org.jecosys.scene.RenderDef.GroundCover(
                1, 0.06, 800, 6, 1.5, new org.jecosys.math.Rgb(0.3f, 0.5f, 0.16f), new org.jecosys.math.Rgb(0.6f, 0.55f, 0.3f)));
        // and the sun's shadow map, drawn every frame
        covered.setShadows(0.6f);
        covered.setShadowPath(ShadowPath.MAP);
        try (SceneRenderer r = new SceneRenderer(gl, world, covered)) {
            fb.bind();
            for (int i = 0; i < WARM_UP_FRAMES; i++) {
                r.render(frames[i % frames.length], camera, W, H);
            }
            assertTrue(r.cover().blades() > 0, "the ground cover's blades are drawn");
            THREADS.getThreadAllocatedBytes(thread); // prime the counter's own first-call allocation
            // The frame allocates nothing in interpreted or C1-compiled code too (with -XX:TieredStopAtLevel=1
            // every window is 0 bytes from the first), so nothing here waits for C2's escape analysis. A few
            // hundred bytes can still appear on this thread in bursts while C2 compiles and deoptimises the
            // frame (JFR shows JVM-made Strings at call sites being relinked, in no fixed frame), hence two
            // consecutive zero windows among up to 40; they come after about 5. A per-frame allocation of
            // even one byte would never give a zero window.
            long[] windows = new long[40];
            int zeroRun = 0;
            int w = 0;
            for (; w < windows.length && zeroRun < 2; w++) {
                long start = THREADS.getThreadAllocatedBytes(thread);
                for (int i = 0; i < WINDOW_FRAMES; i++) {
                    r.render(frames[i % frames.length], camera, W, H);
                }
                windows[w] = THREADS.getThreadAllocatedBytes(thread) - start;
                zeroRun = windows[w] == 0 ? zeroRun + 1 : 0;
            }
            assertEquals(2, zeroRun, "two consecutive windows of " + WINDOW_FRAMES + " frames with ground cover and"
                    + " the shadow map allocating 0 bytes on the render thread; bytes per window: "
                    + java.util.Arrays.toString(java.util.Arrays.copyOf(windows, w)));
        }
    }
}
