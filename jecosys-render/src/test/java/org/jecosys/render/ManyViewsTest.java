package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.render.GlContext.DebugOutput;
import java.nio.ByteBuffer;
import org.jecosys.math.Camera;
import org.jecosys.math.MatrixCamera;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.ViewDecision;
import org.jecosys.sim.World;
import org.joml.Matrix4f;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;

/**
 * Any number of views from one frame: two cameras looking opposite ways both draw their plants, each
 * within 5% of what it draws as the only camera; a 180-degree camera cut draws at least 90% of its
 * steady plant pixels on its first frame; an orthographic top view and a perspective view that show
 * a plant at the same size pick the same level of detail; drawing two views a frame allocates nothing.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class ManyViewsTest {
    private static final int W = 256;
    private static final int H = 160;
    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();

    private GlContext gl;
    private GlFramebuffer fb;
    private SceneDef scene;
    private World world;
    private SceneRenderer renderer;
    private ByteBuffer px;

    @BeforeAll
    void setUp() {
        gl = GlContext.headless(DebugOutput.ON);
        fb = new GlFramebuffer(gl.tracker(), W, H);
        scene = RenderScenes.load("c1.xml");
        world = RenderScenes.build(scene);
        renderer = new SceneRenderer(gl, world, new RenderSettings());
        px = MemoryUtil.memAlloc(4 * W * H);
    }

    @AfterAll
    void tearDown() {
        MemoryUtil.memFree((java.nio.Buffer) px);
        renderer.close();
        fb.close();
        gl.debug().check("the many-views test");
        gl.close();
    }

    /** A camera 1.7 m high, 9 m from the middle, looking across it along +Z (north) or -Z. */
    private static ViewCamera looking(boolean north) {
        ViewCamera c = new ViewCamera();
        c.setPosition(0, 1.7, north ? -9 : 9);
        c.setOrientation(north ? Math.PI : 0, -0.18);
        c.setLens(Math.toRadians(50), W / (double) H, 0.05, 200);
        return c;
    }

    private Simulation simulation() {
        return Simulation.of(world, scene.simulationDef(), 2);
    }

    /** Plant pixels: the frame drawn over an empty magenta target, plants only. */
    private int plantPixels(Frame frame, Camera camera) {
        fb.bind();
        GL11C.glViewport(0, 0, W, H);
        GL11C.glClearColor(1f, 0f, 1f, 1f);
        GL11C.glClear(GL11C.GL_COLOR_BUFFER_BIT | GL11C.GL_DEPTH_BUFFER_BIT);
        renderer.render(frame, camera);
        fb.resolve();
        Pixels.read(W, H, px);
        int n = 0;
        for (int i = 0; i < W * H; i++) {
            boolean magenta = (px.get(4 * i) & 0xff) == 255 && (px.get(4 * i + 1) & 0xff) == 0
                    && (px.get(4 * i + 2) & 0xff) == 255;
            n += magenta ? 0 : 1;
        }
        return n;
    }

    @Test
    void twoCamerasLookingOppositeWaysFromOneFrameEachDrawWhatTheyDrawAlone() {
        ViewCamera south = looking(false);
        ViewCamera north = looking(true);
        int both1;
        int both2;
        try (Simulation sim = simulation()) {
            sim.addView(north);
            for (int i = 0; i < 30; i++) {
                sim.stepFixed(south);
            }
            Frame f = sim.latestFrame();
            both1 = plantPixels(f, south);
            both2 = plantPixels(f, north);
        }
        int alone1 = alone(south);
        int alone2 = alone(north);
        System.out.printf("[views] plant pixels, one frame for both views: %d and %d; each view alone: %d and %d%n",
                both1, both2, alone1, alone2);
        assertTrue(alone1 > 1000 && alone2 > 1000, "both views see plants: " + alone1 + ", " + alone2);
        assertEquals(alone1, both1, 0.05 * alone1, "the step's own camera");
        assertEquals(alone2, both2, 0.05 * alone2, "the other camera, drawn from the same frame");
    }

    private int alone(ViewCamera camera) {
        try (Simulation sim = simulation()) {
            for (int i = 0; i < 30; i++) {
                sim.stepFixed(camera);
            }
            return plantPixels(sim.latestFrame(), camera);
        }
    }

    @Test
    void aCameraCutIsDrawnCompleteOnItsFirstFrame() {
        ViewCamera south = looking(false);
        ViewCamera north = looking(true);
        try (Simulation sim = simulation()) {
            for (int i = 0; i < 60; i++) {
                sim.stepFixed(south);
            }
            sim.stepFixed(north); // the cut: this step still follows the camera of the step before
            int first = plantPixels(sim.latestFrame(), north);
            for (int i = 0; i < 60; i++) {
                sim.stepFixed(north);
            }
            int steady = plantPixels(sim.latestFrame(), north);
            System.out.printf("[views] 180-degree cut: %d plant pixels on its first frame, %d steady%n", first, steady);
            assertTrue(steady > 1000, "steady: " + steady);
            assertTrue(first >= 0.9 * steady, "first frame after the cut: " + first + " of " + steady);
        }
    }

    @Test
    void anOrthographicTopViewAndAPerspectiveViewShowingAPlantAtTheSameSizePickTheSameLevel() {
        double fov = Math.toRadians(50); // c1's LOD lens (<field lodFovY="50">)
        int checked = 0;
        int[] seen = new int[3];
        for (int p = 0; p < world.plantCount(); p += 7) {
            float x = world.plantX(p);
            float y = world.plantY(p);
            float z = world.plantZ(p);
            for (double d : new double[] {4, 9, 12, 14, 20, 40}) {
                // perspective: the plant at distance d straight ahead, from above
                Matrix4f view = new Matrix4f().setLookAt(x, (float) (y + d), z, x, y, z, 0, 0, -1);
                Matrix4f persp = new Matrix4f().setPerspective((float) fov, W / (float) H, 0.05f, 500f);
                // orthographic: the same size on screen, a view height of 2 d tan(fov / 2)
                float half = (float) (d * Math.tan(fov / 2));
                Matrix4f ortho = new Matrix4f().setOrtho(-half * W / H, half * W / H, -half, half, 0.05f, 500f);
                int lp = levelOf(p, new MatrixCamera(view, persp));
                int lo = levelOf(p, new MatrixCamera(view, ortho));
                assertEquals(lp, lo, "plant " + p + " at " + d + " m: perspective and orthographic levels");
                // and the eye's distance does not matter for the orthographic view
                Matrix4f far = new Matrix4f().setLookAt(x, (float) (y + 3 * d), z, x, y, z, 0, 0, -1);
                assertEquals(lo, levelOf(p, new MatrixCamera(far, ortho)), "orthographic, eye 3 times as high");
                if (lp >= 0) {
                    seen[lp]++;
                }
                checked++;
            }
        }
        assertTrue(checked > 50 && seen[0] > 0 && seen[1] > 0 && seen[2] > 0,
                "every level met: " + java.util.Arrays.toString(seen));
        // the animation, too, updates a plant seen orthographically at the level of its size on screen
        try (Simulation sim = simulation()) {
            int p = 0;
            float x = world.plantX(p);
            float y = world.plantY(p);
            float z = world.plantZ(p);
            double d = 12.5; // the middle level of c1 (10 to 15 m)
            float half = (float) (d * Math.tan(fov / 2));
            Matrix4f ortho = new Matrix4f().setOrtho(-half * W / H, half * W / H, -half, half, 0.05f, 500f);
            MatrixCamera top = new MatrixCamera(new Matrix4f().setLookAt(x, y + 2f, z, x, y, z, 0, 0, -1), ortho);
            for (int i = 0; i < 3; i++) {
                sim.stepFixed(top);
            }
            assertEquals(1, sim.latestFrame().plantLevel(p), "the animation's level of a plant seen from 2 m, "
                    + "orthographically at the size of 12.5 m");
        }
    }

    private Frame decided;
    private ViewDecision decision;

    private int levelOf(int p, Camera camera) {
        if (decided == null) {
            // a frame recorded by a simulation of C1: its LOD edges and lens (<field lodFovY="50">)
            try (Simulation sim = simulation()) {
                sim.stepFixed(looking(false));
                decided = new Frame(world.plantCount(), world.bendGeometry());
                sim.copyLatestFrame(decided);
            }
            decision = new ViewDecision(world);
        }
        decision.decide(decided, camera);
        return decision.levels()[p];
    }

    @Test
    void drawingTwoViewsAFrameAllocatesNothingAfterWarmUp() {
        ViewCamera south = looking(false);
        ViewCamera north = looking(true);
        try (Simulation sim = simulation()) {
            sim.addView(north);
            long thread = Thread.currentThread().getId();
            fb.bind();
            for (int i = 0; i < 200; i++) {
                sim.stepFixed(south);
                Frame f = sim.latestFrame();
                renderer.render(f, south, W, H);
                renderer.render(f, north, W, H);
            }
            THREADS.getThreadAllocatedBytes(thread);
            int zeroRun = 0;
            long[] windows = new long[12];
            int w = 0;
            for (; w < windows.length && zeroRun < 2; w++) {
                long start = THREADS.getThreadAllocatedBytes(thread);
                for (int i = 0; i < 100; i++) {
                    sim.stepFixed(south);
                    Frame f = sim.latestFrame();
                    renderer.render(f, south, W, H);
                    renderer.render(f, north, W, H);
                }
                windows[w] = THREADS.getThreadAllocatedBytes(thread) - start;
                zeroRun = windows[w] == 0 ? zeroRun + 1 : 0;
            }
            assertEquals(2, zeroRun, "bytes allocated per 100 frames of two views (step and both renders), window "
                    + "by window: " + java.util.Arrays.toString(java.util.Arrays.copyOf(windows, w)));
        }
    }
}
