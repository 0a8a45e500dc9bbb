package org.jecosys.jme;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import java.lang.management.ManagementFactory;
import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

/** jME's cameras as JEcoSys cameras: the same eye, view direction and clip-space projection. */
class JmeCameraTest {
    private static final float EPS = 1e-4f;

    private static Camera perspective() {
        Camera cam = new Camera(640, 360);
        cam.setFrustumPerspective(55, 640 / 360f, 0.05f, 300f);
        cam.setLocation(new Vector3f(3, 2.6f, -4));
        cam.lookAt(new Vector3f(1, 0.2f, -8), Vector3f.UNIT_Y);
        return cam;
    }

    @Test
    void aPerspectiveCameraHasTheEngineEyeDirectionAndProjection() {
        Camera cam = perspective();
        JmeCamera c = new JmeCamera().update(cam);
        assertEquals(3, c.x(), EPS);
        assertEquals(2.6, c.y(), EPS);
        assertEquals(-4, c.z(), EPS);
        org.joml.Vector3f f = c.forward(new org.joml.Vector3f());
        Vector3f d = cam.getDirection();
        assertEquals(d.x, f.x, EPS);
        assertEquals(d.y, f.y, EPS);
        assertEquals(d.z, f.z, EPS);
        assertEquals(2 * Math.tan(Math.toRadians(55) / 2), c.viewHeightPerMetre(), 1e-5);
        // a world point lands on the same pixel through jME's getScreenCoordinates and JEcoSys's viewProjection
        Matrix4f vp = c.viewProjection(new Matrix4f());
        for (float[] p : new float[][] {{1, 0.2f, -8}, {2.5f, 0, -6}, {0, 1, -12}}) {
            Vector4f clip = vp.transform(new Vector4f(p[0], p[1], p[2], 1));
            Vector3f s = cam.getScreenCoordinates(new Vector3f(p[0], p[1], p[2]));
            assertEquals(s.x, (clip.x / clip.w + 1) / 2 * 640, 1e-2);
            assertEquals(s.y, (clip.y / clip.w + 1) / 2 * 360, 1e-2);
            assertEquals(s.z, (clip.z / clip.w + 1) / 2, 1e-5);
        }
    }

    @Test
    void aParallelProjectionHasNoPerspectiveFootprint() {
        Camera cam = new Camera(400, 200);
        cam.setParallelProjection(true);
        cam.setFrustum(0.1f, 100f, -10, 10, 5, -5);
        cam.setLocation(new Vector3f(0, 30, 0));
        cam.lookAt(new Vector3f(0, 0, 0), Vector3f.UNIT_Z.negate());
        JmeCamera c = new JmeCamera().update(cam);
        assertEquals(0, c.viewHeightPerMetre());
        assertEquals(10, c.viewHeightAtEye(), 1e-4);
        assertEquals(30, c.y(), EPS);
    }

    @Test
    void updatingAllocatesNothing() {
        Camera cam = perspective();
        JmeCamera c = new JmeCamera();
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long self = Thread.currentThread().getId();
        for (int i = 0; i < 20_000; i++) { // warm up: the JIT's own first-call allocations
            c.update(cam);
        }
        // the least of five runs: an allocation per update would show in every run (16 kB or more), while
        // the JIT or the runtime may allocate now and then on this thread on their own
        long least = Long.MAX_VALUE;
        for (int run = 0; run < 5; run++) {
            long before = mx.getThreadAllocatedBytes(self);
            for (int i = 0; i < 1000; i++) {
                c.update(cam);
            }
            least = Math.min(least, mx.getThreadAllocatedBytes(self) - before);
        }
        assertEquals(0, least, "bytes allocated by 1000 updates");
    }
}
