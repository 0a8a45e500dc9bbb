package org.jecosys.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

class ViewCameraTest {
    private static final float EPS = 1e-5f;

    @Test
    void yawZeroLooksAlongMinusZ() {
        ViewCamera c = new ViewCamera();
        Vector3f f = c.forward(new Vector3f());
        assertEquals(0, f.x, EPS);
        assertEquals(0, f.y, EPS);
        assertEquals(-1, f.z, EPS);
    }

    @Test
    void positiveYawTurnsTowardPlusXAndPitchLooksUp() {
        ViewCamera c = new ViewCamera();
        c.setOrientation(Math.PI / 2, 0);
        Vector3f f = c.forward(new Vector3f());
        assertEquals(1, f.x, EPS);
        assertEquals(0, f.z, EPS);
        c.setOrientation(0, 0.3);
        assertEquals(Math.sin(0.3), c.forward(new Vector3f()).y, EPS);
    }

    @Test
    void viewMatrixMapsForwardToMinusZAndEyeToOrigin() {
        ViewCamera c = new ViewCamera();
        c.setPosition(3, 2, -5);
        c.setOrientation(0.7, -0.4);
        Matrix4f view = c.view(new Matrix4f());
        Vector3f f = c.forward(new Vector3f());
        Vector3f eye = view.transformPosition(new Vector3f(3, 2, -5));
        assertEquals(0, eye.length(), 1e-4f);
        Vector3f p = view.transformPosition(new Vector3f(3 + f.x * 10, 2 + f.y * 10, -5 + f.z * 10));
        assertEquals(0, p.x, 1e-4f);
        assertEquals(0, p.y, 1e-4f);
        assertEquals(-10, p.z, 1e-4f);
    }

    @Test
    void viewProjectionEqualsProjectionTimesView() {
        ViewCamera c = new ViewCamera();
        c.setPosition(1, 2, 3);
        c.setOrientation(-1.1, 0.2);
        c.setLens(1.0, 1.5, 0.2, 300);
        Matrix4f vp = c.viewProjection(new Matrix4f());
        Matrix4f ref = c.projection(new Matrix4f()).mul(c.view(new Matrix4f()));
        Vector4f a = vp.transform(new Vector4f(7, 1, -9, 1));
        Vector4f b = ref.transform(new Vector4f(7, 1, -9, 1));
        assertEquals(0, a.sub(b).length(), 1e-3f);
    }

    @Test
    void ofPlacesEyeAboveGround() {
        ViewCamera c = ViewCamera.of(CameraDef.defaults(), 4.0, 2.0);
        assertEquals(5.7, c.y(), 1e-9);
        assertEquals(2.0, c.aspect(), 0);
        assertTrue(c.far() > c.near());
    }

    @Test
    void rejectsBadLens() {
        ViewCamera c = new ViewCamera();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> c.setLens(1, 1, 5, 1));
        assertTrue(e.getMessage().contains("far"));
        assertThrows(IllegalArgumentException.class, () -> c.setOrientation(0, 2));
    }

    @org.junit.jupiter.api.Test
    void matricesEqualJomlsOwnChainForManyPoses() {
        Rng rng = new Rng(11);
        org.joml.Matrix4f mine = new org.joml.Matrix4f();
        org.joml.Matrix4f joml = new org.joml.Matrix4f();
        for (int i = 0; i < 200; i++) {
            ViewCamera c = new ViewCamera();
            c.setPosition(rng.nextDouble(-50, 50), rng.nextDouble(0, 10), rng.nextDouble(-50, 50));
            c.setOrientation(rng.nextDouble(-7, 7), rng.nextDouble(-1.5, 1.5));
            c.setLens(rng.nextDouble(0.3, 2.5), rng.nextDouble(0.5, 3), rng.nextDouble(0.01, 1), rng.nextDouble(10, 1000));
            float p = (float) -c.pitch();
            float y = (float) c.yaw();
            joml.setPerspective((float) c.fovY(), (float) c.aspect(), (float) c.near(), (float) c.far())
                    .rotateX(p).rotateY(y).translate((float) -c.x(), (float) -c.y(), (float) -c.z());
            org.junit.jupiter.api.Assertions.assertTrue(c.viewProjection(mine).equals(joml, 1e-3f), "pose " + i);
            joml.rotationX(p).rotateY(y).translate((float) -c.x(), (float) -c.y(), (float) -c.z());
            org.junit.jupiter.api.Assertions.assertTrue(c.view(mine).equals(joml, 1e-3f), "view " + i);
            joml.setPerspective((float) c.fovY(), (float) c.aspect(), (float) c.near(), (float) c.far());
            org.junit.jupiter.api.Assertions.assertTrue(c.projection(mine).equals(joml, 1e-4f), "projection " + i);
        }
    }
}
