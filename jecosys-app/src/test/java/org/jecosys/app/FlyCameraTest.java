package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jecosys.math.CameraDef;
import org.jecosys.math.ViewCamera;
import org.jecosys.math.Waypoint;
import org.jecosys.sim.CameraWalk;
import org.jecosys.terrain.Heightfield;
import org.junit.jupiter.api.Test;

/** P in the viewer walks the scene's path exactly as {@link CameraWalk} (simulate, benchmarks) does. */
class FlyCameraTest {
    private static Heightfield slope() {
        int res = 33;
        float[] h = new float[res * res];
        for (int j = 0; j < res; j++) {
            for (int i = 0; i < res; i++) {
                h[j * res + i] = 0.1f * i + 0.05f * j;
            }
        }
        return Heightfield.of(40, 40, res, h);
    }

    @Test
    void playingThePathFollowsCameraWalk() {
        Heightfield ground = slope();
        CameraDef def = new CameraDef(0, 1.7, 10, 0, -0.1, Math.toRadians(60), 0.05, 300,
                List.of(new Waypoint(0, 0, 10), new Waypoint(0, 2.5, -10), new Waypoint(-8, 0, -2)), 1.4, true);
        ViewCamera cam = ViewCamera.of(def, ground.height(0, 10), 16 / 9.0);
        FlyCamera fly = new FlyCamera(cam, def, ground);
        CameraWalk walk = new CameraWalk(def, ground, 16 / 9.0);
        fly.togglePath();
        assertTrue(fly.playing());
        double t = 0;
        for (int i = 0; i < 2000; i++) {
            double dt = 0.01 + 0.02 * (i % 3);
            t += dt;
            fly.move(dt, 1, 0, 0, false); // keys are ignored while the path plays
            ViewCamera w = walk.at(t);
            assertEquals(w.x(), cam.x(), 1e-9, "x at " + t);
            assertEquals(w.y(), cam.y(), 1e-9, "y at " + t);
            assertEquals(w.z(), cam.z(), 1e-9, "z at " + t);
            assertEquals(w.yaw(), cam.yaw(), 1e-12, "yaw at " + t);
            assertEquals(w.pitch(), cam.pitch(), 1e-12, "pitch at " + t);
        }
        fly.togglePath();
        assertFalse(fly.playing());
        double x = cam.x();
        fly.move(0.5, 0, 1, 0, false);
        assertTrue(Math.abs(cam.x() - x) > 0.5, "WASD moves again once the path is stopped");
    }
}
