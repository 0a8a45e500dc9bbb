package org.jecosys.render.ground;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.ViewCamera;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

/**
 * Where the sun's shadow map lies ({@link ShadowFit}): it holds the view's frustum out to its reach
 * whichever way the camera looks, a texel stays on the same patch of ground while the camera moves and
 * turns (the shadows cannot swim), the size does not change as the camera turns, and points toward
 * the sun are nearer in the map's depth.
 */
class ShadowFitTest {
    private static final float LX = (float) (Math.cos(Math.toRadians(30)) * Math.cos(Math.toRadians(40)));
    private static final float LY = (float) Math.sin(Math.toRadians(30));
    private static final float LZ = (float) (Math.cos(Math.toRadians(30)) * Math.sin(Math.toRadians(40)));

    private static ViewCamera camera(double x, double z, double yaw) {
        ViewCamera camera = new ViewCamera();
        camera.setPosition(x, 1.7, z);
        camera.setOrientation(yaw, -0.2);
        camera.setLens(Math.toRadians(60), 16 / 9.0, 0.1, 500);
        return camera;
    }

    private static Vector3f map(ShadowFit fit, double x, double y, double z) {
        Vector4f v = fit.shadowMatrix(new Matrix4f()).transform(new Vector4f((float) x, (float) y, (float) z, 1f));
        return new Vector3f(v.x / v.w, v.y / v.w, v.z / v.w);
    }

    @Test
    void theFrustumOutToTheReachIsInsideTheMapWhereverTheCameraLooks() {
        try (ShadowFit fit = new ShadowFit(2048)) {
            for (double yaw = 0; yaw < 2 * Math.PI; yaw += 0.4) {
                ViewCamera cam = camera(3, -2, yaw);
                fit.fit(cam, LX, LY, LZ, 20);
                Matrix4f inverse = cam.viewProjection(new Matrix4f()).invert();
                // the frustum's corners at the eye and 20 m along its axis
                Vector3f fwd = cam.forward(new Vector3f());
                for (int corner = 0; corner < 4; corner++) {
                    Vector4f ndc = new Vector4f(corner % 2 == 0 ? -1 : 1, corner < 2 ? -1 : 1, 1, 1);
                    Vector4f far = inverse.transform(ndc);
                    Vector3f dir = new Vector3f(far.x / far.w, far.y / far.w, far.z / far.w)
                            .sub((float) cam.x(), (float) cam.y(), (float) cam.z());
                    dir.mul(20f / dir.dot(fwd));
                    Vector3f p = map(fit, cam.x() + dir.x, cam.y() + dir.y, cam.z() + dir.z);
                    assertTrue(p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1 && p.z >= 0 && p.z <= 1,
                            "yaw " + yaw + ": corner " + corner + " 20 m out maps to " + p);
                }
                Vector3f eye = map(fit, cam.x(), cam.y(), cam.z());
                assertTrue(eye.x >= 0 && eye.x <= 1 && eye.y >= 0 && eye.y <= 1, "the eye maps to " + eye);
            }
        }
    }

    @Test
    void aTexelStaysOnTheSamePatchOfGroundWhileTheCameraMovesAndTurns() {
        try (ShadowFit fit = new ShadowFit(2048)) {
            fit.fit(camera(0, 0, 0), LX, LY, LZ, 20);
            double texel = fit.texelMetres();
            double radius = fit.radius();
            Vector3f a = map(fit, 1.234, 0.05, -3.21);
            for (int i = 1; i <= 40; i++) {
                fit.fit(camera(0.013 * i, -0.031 * i, 0.07 * i), LX, LY, LZ, 20);
                assertEquals(texel, fit.texelMetres(), 1e-12, "texel size as the camera turns");
                assertEquals(radius, fit.radius(), 1e-12, "radius as the camera turns");
                Vector3f b = map(fit, 1.234, 0.05, -3.21);
                // the map moved by whole texels: the point's position within its texel is the same
                double fx = (a.x - b.x) * fit.size();
                double fy = (a.y - b.y) * fit.size();
                assertEquals(Math.rint(fx), fx, 2e-2, "step " + i + ": moved by " + fx + " texels in x");
                assertEquals(Math.rint(fy), fy, 2e-2, "step " + i + ": moved by " + fy + " texels in y");
            }
        }
    }

    @Test
    void towardTheSunIsNearerAndAHighSunStillFits() {
        try (ShadowFit fit = new ShadowFit(1024)) {
            fit.fit(camera(0, 0, 0), LX, LY, LZ, 20);
            Vector3f ground = map(fit, 0, 0, -5);
            Vector3f above = map(fit, LX, LY, -5 + LZ);
            assertTrue(above.z < ground.z, "a point 1 m toward the sun is nearer: " + above.z + " vs " + ground.z);
            assertEquals(ground.x, above.x, 1e-4, "and on the same texel");
            assertTrue(fit.bias() > 0 && fit.bias() < 1e-3, "bias " + fit.bias());
            fit.fit(camera(0, 0, 0), 0, 1, 0, 20);
            Vector3f under = map(fit, 0.3, 0, -4);
            assertTrue(under.x > 0 && under.x < 1 && under.y > 0 && under.y < 1, "overhead sun: " + under);
        }
        assertThrows(IllegalArgumentException.class, () -> new ShadowFit(8));
    }
}
