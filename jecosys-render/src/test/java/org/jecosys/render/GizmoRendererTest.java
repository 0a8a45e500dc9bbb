package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.GL_BLEND;
import static org.lwjgl.opengl.GL11C.GL_CULL_FACE;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_GREATER;
import static org.lwjgl.opengl.GL11C.GL_LESS;
import static org.lwjgl.opengl.GL11C.GL_ONE;
import static org.lwjgl.opengl.GL11C.GL_ZERO;
import static org.lwjgl.opengl.GL11C.glBlendFunc;
import static org.lwjgl.opengl.GL11C.glDepthFunc;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glViewport;

import org.jecosys.render.GlContext.DebugOutput;
import java.nio.ByteBuffer;
import java.util.Map;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.World;
import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.render.overlay.GizmoKind;
import org.jecosys.render.overlay.GizmoRenderer;
import org.jecosys.render.overlay.Gizmos;

/**
 * The gizmos over a headless render of C1: every kind's handle is drawn in its colour where its
 * centre projects, rings lie on the terrain at their radius, the GL state is put back, every GL
 * object is released, and drawing allocates nothing after warm-up.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class GizmoRendererTest {
    private static final int W = 320;
    private static final int H = 200;
    /** Largest difference per channel (0-255) between a drawn pixel and the gizmo's colour. */
    private static final int TOLERANCE = 16;

    private World world;
    private GlContext gl;
    private GlFramebuffer fb;
    private ByteBuffer px;

    @BeforeAll
    void setUp() {
        world = RenderScenes.build(RenderScenes.load("c1.xml"));
        gl = GlContext.headless(DebugOutput.ON);
        fb = new GlFramebuffer(gl.tracker(), W, H);
        px = MemoryUtil.memAlloc(4 * W * H);
    }

    @AfterEach
    void noGlErrors() {
        gl.debug().check("the gizmo test");
    }

    @AfterAll
    void tearDown() {
        MemoryUtil.memFree((java.nio.Buffer) px);
        if (fb != null) {
            fb.close();
        }
        if (gl != null) {
            assertEquals(0, gl.tracker().live(), "every GL object released");
            gl.close();
        }
    }

    private static ViewCamera camera() {
        ViewCamera c = new ViewCamera();
        c.setPosition(0, 22, 4);
        c.setOrientation(0, -1.25);
        c.setLens(Math.toRadians(50), W / (double) H, 0.05, 200);
        return c;
    }

    /** Nine gizmos, one per kind, on a 3 x 3 grid 4.5 m by 5.5 m apart, each with a 1.2 m influence ring. */
    private static Gizmos grid() {
        Gizmos g = new Gizmos();
        GizmoKind[] kinds = GizmoKind.values();
        for (int k = 0; k < kinds.length; k++) {
            int i = g.add(kinds[k], -4.5 + 4.5 * (k % 3), -8 + 5.5 * (k / 3), 1.2, 0.3);
            g.direction(i, 0.5);
            g.spin(i, 1);
        }
        return g;
    }

    /** Pixel (column, row from the bottom) where world point (x, y, z) projects. */
    private static int[] project(ViewCamera cam, double x, double y, double z) {
        Vector4f p = cam.viewProjection(new Matrix4f()).transform(new Vector4f((float) x, (float) y, (float) z, 1));
        return new int[] {(int) Math.floor((p.x / p.w * 0.5 + 0.5) * W), (int) Math.floor((p.y / p.w * 0.5 + 0.5) * H)};
    }

    private boolean near(int x, int y, GizmoKind kind, int radius) {
        for (int dy = -radius; dy <= radius; dy++) {
            for (int dx = -radius; dx <= radius; dx++) {
                int cx = x + dx;
                int cy = y + dy;
                if (cx >= 0 && cy >= 0 && cx < W && cy < H
                        && Math.abs(Pixels.red(px, W, cx, cy) - Math.round(kind.red() * 255)) <= TOLERANCE
                        && Math.abs(Pixels.green(px, W, cx, cy) - Math.round(kind.green() * 255)) <= TOLERANCE
                        && Math.abs(Pixels.blue(px, W, cx, cy) - Math.round(kind.blue() * 255)) <= TOLERANCE) {
                    return true;
                }
            }
        }
        return false;
    }

    private String at(int x, int y) {
        return "(" + Pixels.red(px, W, x, y) + "," + Pixels.green(px, W, x, y) + "," + Pixels.blue(px, W, x, y) + ")";
    }

    @Test
    void eachKindIsDrawnInItsColourWhereItsCentreProjectsAndItsRingLiesOnTheTerrain() {
        ViewCamera cam = camera();
        Gizmos gizmos = grid();
        try (SceneRenderer scene = new SceneRenderer(gl, world, RenderSettings.standalone());
             GizmoRenderer renderer = new GizmoRenderer(gl, world.terrain().heightfield())) {
            fb.bind();
            scene.render(TestFrames.rest(world, cam), cam, W, H);
            Pixels.read(W, H, px);
            for (int i = 0; i < gizmos.size(); i++) {
                int[] c = project(cam, gizmos.x(i), world.terrain().heightfield().height(gizmos.x(i), gizmos.z(i)),
                        gizmos.z(i));
                assertTrue(!near(c[0], c[1], gizmos.kind(i), 0), "without gizmos " + gizmos.kind(i)
                        + "'s colour is not already at its centre " + at(c[0], c[1]));
            }
            glViewport(0, 0, W, H);
            renderer.render(gizmos, null, 1, cam);
            Pixels.read(W, H, px);
            for (int i = 0; i < gizmos.size(); i++) {
                double x = gizmos.x(i);
                double z = gizmos.z(i);
                int[] c = project(cam, x, world.terrain().heightfield().height(x, z), z);
                assertTrue(c[0] > 4 && c[1] > 4 && c[0] < W - 4 && c[1] < H - 4, "centre in view: " + c[0] + "," + c[1]);
                assertTrue(near(c[0], c[1], gizmos.kind(i), 0), gizmos.kind(i) + " at its centre " + c[0] + ","
                        + c[1] + ": " + at(c[0], c[1]));
            }
            // the rings, on the terrain without plants in front: left and right of the centre
            scene.drawPlants = false;
            scene.render(TestFrames.rest(world, cam), cam, W, H);
            renderer.render(gizmos, null, 1, cam);
            Pixels.read(W, H, px);
            for (int i = 0; i < gizmos.size(); i++) {
                for (int side = -1; side <= 1; side += 2) {
                    double x = gizmos.x(i) + side * gizmos.influenceRadius(i);
                    double z = gizmos.z(i);
                    int[] c = project(cam, x, world.terrain().heightfield().height(x, z), z);
                    assertTrue(near(c[0], c[1], gizmos.kind(i), 1), gizmos.kind(i) + "'s ring at " + c[0] + ","
                            + c[1] + ": " + at(c[0], c[1]));
                }
            }
            assertTrue(renderer.triangles() > 9 * 50, "triangles: " + renderer.triangles());
        }
    }

    @Test
    void windArrowsAreDrawnFromTheFieldAndColouredBySpeed() {
        float[] rgb = new float[3];
        GizmoRenderer.windColour(0, 5, rgb);
        assertTrue(rgb[2] > 0.9f && rgb[0] < 0.3f, "0 m/s is blue");
        GizmoRenderer.windColour(5, 5, rgb);
        assertTrue(rgb[0] > 0.9f && rgb[2] < 0.2f, "the scale's top is red");
        GizmoRenderer.windColour(50, 5, rgb);
        assertTrue(rgb[0] > 0.9f && rgb[2] < 0.2f, "above the scale stays red");
        assertThrows(IllegalArgumentException.class, () -> GizmoRenderer.windColour(1, 0, rgb));
        float[] rgba = new float[4];
        GizmoRenderer.shade(GizmoKind.VORTEX, true, 1, rgba);
        assertEquals(GizmoKind.VORTEX.red(), rgba[0], 1e-6f);
        assertEquals(1f, rgba[3], 1e-6f);
        GizmoRenderer.shade(GizmoKind.VORTEX, true, 0, rgba);
        assertTrue(rgba[3] < 0.5f && Math.abs(rgba[0] - 0.5f) < Math.abs(GizmoKind.VORTEX.red() - 0.5f),
                "an inactive flow is fainter and greyer");
        GizmoRenderer.shade(GizmoKind.VORTEX, false, 1, rgba);
        assertTrue(rgba[0] == rgba[1] && rgba[1] == rgba[2], "a switched-off flow is grey");
    }

    @Test
    void everyGlStateItTouchesIsTheSameAfterRender() {
        try (GizmoRenderer renderer = new GizmoRenderer(gl, world.terrain().heightfield())) {
            fb.bind();
            glViewport(20, 10, 200, 150);
            glEnable(GL_CULL_FACE);
            glDisable(GL_DEPTH_TEST);
            glDepthFunc(GL_GREATER);
            glDepthMask(true);
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ONE);
            Map<String, String> before = HostCompositionTest.census();
            renderer.render(grid(), null, 1, camera());
            assertEquals(before, HostCompositionTest.census());
            assertTrue(renderer.triangles() > 0);
            glDisable(GL_CULL_FACE);
            glDepthFunc(GL_LESS);
            glDisable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ZERO);
            glViewport(0, 0, W, H);
        }
    }

    @Test
    void closingReleasesEveryGlObjectAndAFailingConstructorLeavesNone() {
        GlCensus before = GlCensus.take();
        int tracked = gl.tracker().live();
        long created = gl.tracker().createdTotal();
        try (GizmoRenderer renderer = new GizmoRenderer(gl, world.terrain().heightfield())) {
            fb.bind();
            renderer.render(grid(), null, 1, camera());
            assertEquals(gl.tracker().live() - tracked, GlCensus.take().minus(before).total(),
                    "every object is a tracked Gl* wrapper");
        }
        assertEquals(before, GlCensus.take(), "closing released every object the driver knows of");
        int objects = (int) (gl.tracker().createdTotal() - created);
        assertTrue(objects >= 3, "program, vertex array, buffer: " + objects);
        for (int n = 0; n < objects; n++) {
            gl.tracker().failAfter(n);
            assertThrows(IllegalStateException.class, () -> new GizmoRenderer(gl, world.terrain().heightfield()));
            assertEquals(tracked, gl.tracker().live(), "objects left after a failure at object " + n);
        }
        gl.tracker().failAfter(-1);
        assertEquals(before, GlCensus.take());
    }

    @Test
    void drawingAllocatesNothingAfterWarmUp() {
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        Gizmos gizmos = grid();
        ViewCamera cam = camera();
        long thread = Thread.currentThread().getId();
        try (GizmoRenderer renderer = new GizmoRenderer(gl, world.terrain().heightfield())) {
            fb.bind();
            for (int i = 0; i < 2000; i++) {
                renderer.render(gizmos, null, 1, cam);
            }
            threads.getThreadAllocatedBytes(thread);
            int zeroRun = 0;
            long[] windows = new long[16];
            int w = 0;
            for (; w < windows.length && zeroRun < 2; w++) {
                long start = threads.getThreadAllocatedBytes(thread);
                for (int i = 0; i < 200; i++) {
                    renderer.render(gizmos, null, 1, cam);
                }
                windows[w] = threads.getThreadAllocatedBytes(thread) - start;
                zeroRun = windows[w] == 0 ? zeroRun + 1 : 0;
            }
            assertEquals(2, zeroRun, "two windows of 200 gizmo frames allocating 0 bytes: "
                    + java.util.Arrays.toString(java.util.Arrays.copyOf(windows, w)));
        }
    }
}
