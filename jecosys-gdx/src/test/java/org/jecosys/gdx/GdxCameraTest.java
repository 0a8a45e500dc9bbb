package org.jecosys.gdx;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.badlogic.gdx.graphics.OrthographicCamera;
import com.badlogic.gdx.graphics.PerspectiveCamera;
import com.badlogic.gdx.math.Vector3;
import com.badlogic.gdx.utils.GdxNativesLoader;
import java.lang.management.ManagementFactory;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** libGDX's cameras as JEcoSys cameras: the same eye, view direction and clip-space projection. */
class GdxCameraTest {
    private static final float EPS = 1e-4f;

    @BeforeAll
    static void gdxNatives() {
        GdxNativesLoader.load(); // libGDX's frustum update is native; an application loads it at start
    }

    private static PerspectiveCamera perspective() {
        PerspectiveCamera cam = new PerspectiveCamera(55, 640, 360);
        cam.near = 0.05f;
        cam.far = 300f;
        cam.position.set(3, 2.6f, -4);
        cam.lookAt(1, 0.2f, -8);
        cam.update();
        return cam;
    }

    @Test
    void aPerspectiveCameraHasTheEngineEyeDirectionAndProjection() {
        PerspectiveCamera cam = perspective();
        GdxCamera c = new GdxCamera().update(cam);
        assertEquals(3, c.x(), EPS);
        assertEquals(2.6, c.y(), EPS);
        assertEquals(-4, c.z(), EPS);
        Vector3f f = c.forward(new Vector3f());
        assertEquals(cam.direction.x, f.x, EPS);
        assertEquals(cam.direction.y, f.y, EPS);
        assertEquals(cam.direction.z, f.z, EPS);
        assertEquals(2 * Math.tan(Math.toRadians(55) / 2), c.viewHeightPerMetre(), 1e-5);
        // a world point lands on the same pixel through libGDX's project() and JEcoSys's viewProjection
        Matrix4f vp = c.viewProjection(new Matrix4f());
        for (float[] p : new float[][] {{1, 0.2f, -8}, {2.5f, 0, -6}, {0, 1, -12}}) {
            Vector4f clip = vp.transform(new Vector4f(p[0], p[1], p[2], 1));
            Vector3 s = cam.project(new Vector3(p[0], p[1], p[2]), 0, 0, 640, 360);
            assertEquals(s.x, (clip.x / clip.w + 1) / 2 * 640, 1e-2);
            assertEquals(s.y, (clip.y / clip.w + 1) / 2 * 360, 1e-2);
            assertEquals(s.z, (clip.z / clip.w + 1) / 2, 1e-5);
        }
    }

    @Test
    void anOrthographicCameraHasNoPerspectiveFootprint() {
        OrthographicCamera cam = new OrthographicCamera(20, 10);
        cam.position.set(0, 30, 0);
        cam.direction.set(0, -1, 0);
        cam.up.set(0, 0, -1);
        cam.update();
        GdxCamera c = new GdxCamera().update(cam);
        assertEquals(0, c.viewHeightPerMetre());
        assertEquals(10, c.viewHeightAtEye(), 1e-4);
        assertEquals(30, c.y(), EPS);
    }

    @Test
    void updatingAllocatesNothing() {
        PerspectiveCamera cam = perspective();
        GdxCamera c = new GdxCamera();
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long self = Thread.currentThread().getId();
        for (int i = 0; i < 20_000; i++) { // warm up: the JIT's own first-call allocations
            cam.position.x = i % 7;
            cam.update();
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
