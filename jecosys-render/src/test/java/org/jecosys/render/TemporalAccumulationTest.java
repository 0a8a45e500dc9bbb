package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import org.jecosys.math.Camera;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;

/**
 * The framebuffer's temporal accumulation ({@link GlFramebuffer#setAccumulation}) on the paper's scene C1,
 * close to its plants, at a small size (the meadow's figures are {@link SharpnessTest}'s): what it refuses, the jitter it gives a camera, that a view held still gathers detail, that a camera
 * which moves leaves no ghost of the old view and that the history forgets it, that resolving allocates
 * nothing per frame, and that its GL objects go when it is turned off.
 */
class TemporalAccumulationTest {
    private static final int W = 320;
    private static final int H = 180;
    /** The paper's scene C1 (grass leaves, quick to draw). */
    private static final String SCENE = "c1.xml";

    private static double meanAbsDiff(Img a, Img b) {
        return ImageMetrics.meanAbsDiff(a, b, all(a));
    }

    /** {@code frames} frames of a still view (nothing moving) with accumulation on, without resetting the history. */
    private static Img hold(Shots s, Frame frame, Camera camera, int frames) {
        Img last = null;
        for (int i = 0; i < frames; i++) {
            last = s.render(frame, s.fb.jittered(camera, true), true, true);
        }
        return last;
    }

    @Test
    void refusesWhatItCannotDoAndGivesBackItsObjects() {
        SceneDef def = RenderScenes.load(SCENE);
        World world = RenderScenes.build(def);
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H);
             GlFramebuffer single = new GlFramebuffer(s.gl.tracker(), 8, 8)) {
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> single.setAccumulation(16));
            assertTrue(e.getMessage().contains("multisampled"), e.getMessage());
            assertEquals(0, single.accumulation());
            for (int bad : new int[] {-1, 1, 65}) {
                IllegalArgumentException b = assertThrows(IllegalArgumentException.class,
                        () -> s.fb.setAccumulation(bad));
                assertTrue(b.getMessage().contains("[2, 64]"), b.getMessage());
            }
            assertThrows(IllegalArgumentException.class, () -> s.fb.jittered(null));
            ViewCamera cam = RenderScenes.camera(def, world, W, H);
            assertSame(cam, s.fb.jittered(cam), "off, the camera is drawn as it is");
            int before = s.gl.tracker().live();
            s.fb.setAccumulation(16);
            assertEquals(16, s.fb.accumulation());
            assertEquals(before + 8, s.gl.tracker().live(), "accumulation makes its eight GL objects");
            s.fb.setAccumulation(0);
            assertEquals(before, s.gl.tracker().live(), "turned off, its objects are deleted");
            assertEquals(0, s.fb.accumulation());
        }
    }

    @Test
    void theJitterMovesOnlyTheProjectionWithinHalfAPixel() {
        SceneDef def = RenderScenes.load(SCENE);
        World world = RenderScenes.build(def);
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            ViewCamera cam = RenderScenes.camera(def, world, W, H);
            s.fb.setAccumulation(16);
            Matrix4f view = cam.view(new Matrix4f());
            Matrix4f projection = cam.projection(new Matrix4f());
            double sx = 0;
            double sy = 0;
            java.util.Set<String> offsets = new java.util.HashSet<>();
            for (int i = 0; i < 16; i++) {
                Camera j = s.fb.jittered(cam);
                assertTrue(j.view(new Matrix4f()).equals(view, 1e-6f), "the view is unchanged");
                assertEquals(cam.x(), j.x(), 1e-4);
                assertEquals(cam.z(), j.z(), 1e-4);
                // the projection moved in clip space: translation(dx, dy, 0) * projection
                Matrix4f p = j.projection(new Matrix4f());
                double dx = (p.m20() - projection.m20()) / -1.0 * W / 2; // column 2 row 0 carries dx * m23 (= -1)
                double dy = (p.m21() - projection.m21()) / -1.0 * H / 2;
                assertTrue(p.m00() == projection.m00() && p.m11() == projection.m11(), "the lens is unchanged");
                assertTrue(Math.abs(dx) <= 0.5 && Math.abs(dy) <= 0.5, "within half a pixel: " + dx + ", " + dy);
                sx += dx;
                sy += dy;
                offsets.add(Math.round(dx * 1000) + "," + Math.round(dy * 1000));
                s.fb.bind();
                s.fb.resolve();
            }
            assertEquals(16, offsets.size(), "16 different offsets");
            assertTrue(Math.abs(sx / 16) < 0.05 && Math.abs(sy / 16) < 0.05, "centred: " + sx / 16 + ", " + sy / 16);
            s.fb.setAccumulation(0);
        }
    }

    @Test
    void aStillViewSharpensAndAMovedCameraLeavesNoGhost() {
        SceneDef def = RenderScenes.load(SCENE);
        World world = RenderScenes.build(def);
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            ViewCamera a = close(world);
            ViewCamera b = close(world);
            b.setOrientation(a.yaw() + Math.toRadians(6), a.pitch());
            Frame fa = TestFrames.rest(world, a);
            Frame frameB = TestFrames.rest(world, b);
            Shots.View view = s.view(fa, a);
            Img plainA = view.full();
            boolean[] veg = view.vegetation();
            s.fb.setAccumulation(16);
            Img firstA = hold(s, fa, a, 1);
            Img stillA = hold(s, fa, a, 16);
            s.fb.resetHistory();
            Img stillB = hold(s, frameB, b, 16);
            s.fb.resetHistory();
            hold(s, fa, a, 16);
            Img movedB = hold(s, frameB, b, 1);
            Img settledB = hold(s, frameB, b, 16);
            // what a viewer copies into its window (one more still frame, resolved into it) is the running mean
            try (GlFramebuffer window = new GlFramebuffer(s.gl.tracker(), W, H)) {
                s.fb.bind();
                s.renderer.render(frameB, s.fb.jittered(b, true), W, H);
                s.fb.resolveTo(window.id());
                java.nio.ByteBuffer px = org.lwjgl.system.MemoryUtil.memAlloc(4 * W * H);
                try {
                    org.jecosys.render.gl.Pixels.read(W, H, px);
                    double copied = meanAbsDiff(settledB, Img.of(px, W, H));
                    assertTrue(copied <= 0.25, "resolveTo copies the running mean: " + copied);
                } finally {
                    org.lwjgl.system.MemoryUtil.memFree((java.nio.Buffer) px);
                }
            }
            // the camera still, the plants in the wind: 0.5 s at the render command's 30 frames a second
            Frame end = TestFrames.wind(world, 1.5, a);
            s.fb.resetHistory();
            Img windStill = hold(s, end, a, 16);
            s.fb.resetHistory();
            Img running = null;
            for (int i = 0; i <= 15; i++) {
                running = s.render(TestFrames.wind(world, 1.0 + i / 30.0, a), s.fb.jittered(a, false), true, true);
            }
            s.fb.setAccumulation(0);
            double sharpPlain = ImageMetrics.meanAbsLaplacian(plainA, veg);
            double sharpStill = ImageMetrics.meanAbsLaplacian(stillA, veg);
            double first = ImageMetrics.meanAbsDiff(firstA, plainA, veg);
            double views = meanAbsDiff(stillA, stillB);
            double ghost = meanAbsDiff(movedB, stillB);
            double settled = meanAbsDiff(settledB, stillB);
            System.out.printf("[look] temporal accumulation at %dx%d: detail over the plants %.2f one frame, %.2f held still; first "
                    + "frame against the plain resolve %.2f/255; camera turned 6 degrees: views differ by %.2f/255, "
                    + "the first frame after the turn by %.2f/255 from the view accumulated there, 16 frames later "
                    + "%.2f/255; held still %.2f/255%n", W, H, sharpPlain, sharpStill, first, views,
                    ghost, settled, ImageMetrics.meanAbsDiff(stillA, plainA, veg));
            assertTrue(sharpStill >= 1.3 * sharpPlain, "held still, the view gathers detail: " + sharpStill
                    + " against " + sharpPlain);
            double gathered = ImageMetrics.meanAbsDiff(stillA, plainA, veg);
            assertTrue(first <= 0.5 * gathered, "the first frame shows the one-frame resolve: " + first
                    + " from it, against " + gathered + " when held still");
            assertTrue(ghost <= 0.35 * views, "after the turn the old view does not linger: " + ghost + " against "
                    + views);
            assertTrue(settled <= 1.0, "the history forgets the old view: " + settled);
            Img windPlain = s.render(end, a, true, true);
            double trail = ImageMetrics.meanAbsDiff(running, windStill, veg);
            double plainOff = ImageMetrics.meanAbsDiff(windPlain, windStill, veg);
            System.out.printf("[look] temporal accumulation, plants in the wind for 0.5 s at 30 frames a second: the last "
                    + "frame %.2f/255 over the plants from the same moment held still, the one-frame resolve %.2f/255%n",
                    trail, plainOff);
            assertTrue(trail <= plainOff, "while the plants move, accumulation is no further from the still view than "
                    + "the one-frame resolve: " + trail + " against " + plainOff);
        }
    }

    /** 0.8 m above the ground, 2 m from the plant with the most neighbours within 1.5 m, looking at it. */
    private static ViewCamera close(World world) {
        int best = 0;
        int most = -1;
        for (int p = 0; p < world.plantCount(); p++) {
            int n = 0;
            for (int q = 0; q < world.plantCount(); q++) {
                n += Math.hypot(world.plantX(p) - world.plantX(q), world.plantZ(p) - world.plantZ(q)) < 1.5 ? 1 : 0;
            }
            if (n > most) {
                most = n;
                best = p;
            }
        }
        double x = world.plantX(best);
        double y = world.plantY(best);
        double z = world.plantZ(best);
        return Shots.lookAt(x, y + 0.8, z + 2, x, y + 0.1, z, Math.toRadians(50), W / (double) H, 0.05, 200);
    }

    private static boolean[] all(Img img) {
        boolean[] m = new boolean[img.width() * img.height()];
        java.util.Arrays.fill(m, true);
        return m;
    }

    @Test
    void resolvingAllocatesNothingPerFrame() {
        SceneDef def = RenderScenes.load(SCENE);
        World world = RenderScenes.build(def);
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            ViewCamera cam = RenderScenes.camera(def, world, W, H);
            Frame frame = TestFrames.rest(world, cam);
            s.fb.setAccumulation(16);
            long allocated = 0;
            for (int i = 0; i < 40; i++) {
                long a0 = threads.getCurrentThreadAllocatedBytes();
                Camera j = s.fb.jittered(cam);
                long a1 = threads.getCurrentThreadAllocatedBytes();
                s.fb.bind();
                s.renderer.render(frame, j, W, H);
                long a2 = threads.getCurrentThreadAllocatedBytes();
                s.fb.resolve();
                long a3 = threads.getCurrentThreadAllocatedBytes();
                if (i >= 20) {
                    allocated += (a1 - a0) + (a3 - a2);
                }
            }
            s.gl.debug().check("temporal accumulation");
            s.fb.setAccumulation(0);
            assertEquals(0, allocated, "bytes allocated by 20 frames' jitter and resolve after warm-up");
        }
    }
}
