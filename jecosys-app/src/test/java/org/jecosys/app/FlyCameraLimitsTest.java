package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jecosys.math.CameraDef;
import org.jecosys.math.ViewCamera;
import org.jecosys.math.Waypoint;
import org.jecosys.terrain.Heightfield;
import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

/**
 * The walking camera stays over the terrain and above the ground, walks at a speed scaled to the
 * terrain (slower with Ctrl, faster with Shift), and "frame the scene" shows the whole terrain.
 */
class FlyCameraLimitsTest {
    /** A hilly terrain of side {@code size} metres. */
    private static Heightfield hills(double size) {
        int res = 17;
        float[] h = new float[res * res];
        for (int j = 0; j < res; j++) {
            for (int i = 0; i < res; i++) {
                h[j * res + i] = (float) (0.08 * size * (0.5 + 0.5 * Math.sin(0.9 * i) * Math.cos(0.7 * j)));
            }
        }
        return Heightfield.of(size, size, res, h);
    }

    private static FlyCamera camera(Heightfield ground) {
        CameraDef def = new CameraDef(0, 0.5, 0.3 * ground.sizeZ(), 0, -0.17, Math.toRadians(60), 0.02, 300,
                List.of(), 1.4, false);
        ViewCamera cam = ViewCamera.of(def, ground.height(def.x(), def.z()), 16 / 9.0);
        return new FlyCamera(cam, def, ground);
    }

    @Test
    void walkingForAnyTimeStaysOverTheTerrainAndAboveTheGround() {
        Heightfield rose = hills(4);
        FlyCamera fly = camera(rose);
        ViewCamera c = fly.camera();
        // the issue: 1.5 s of W on rose.xml's 4 x 4 m terrain left the world; here 10 s, with Shift, then down
        for (int i = 0; i < 600; i++) {
            fly.move(1 / 60.0, 1, 0.3, 0, FlyCamera.FAST);
            assertTrue(rose.contains(c.x(), c.z()), "over the terrain at step " + i + ": " + c.x() + ", " + c.z());
        }
        for (int i = 0; i < 600; i++) {
            fly.move(1 / 60.0, 0, 0, -1, FlyCamera.FAST);
            assertTrue(c.y() >= rose.height(c.x(), c.z()) + fly.clearance() - 1e-9, "above the ground");
        }
        assertEquals(rose.height(c.x(), c.z()) + fly.clearance(), c.y(), 1e-9, "down to the clearance, not through");
        for (int i = 0; i < 6000; i++) {
            fly.move(1 / 60.0, 0, 0, 1, FlyCamera.FAST);
        }
        assertTrue(c.y() <= rose.maxHeight() + 4 + 1e-9, "not into the sky forever: " + c.y());
    }

    @Test
    void theWalkingSpeedScalesWithTheTerrainAndCtrlAndShift() {
        assertEquals(FlyCamera.MIN_WALK, FlyCamera.walkSpeed(hills(4)), 1e-12, "the 4 m rose");
        assertEquals(3.2, FlyCamera.walkSpeed(hills(80)), 1e-12, "the 80 m meadow");
        assertEquals(FlyCamera.MAX_WALK, FlyCamera.walkSpeed(hills(400)), 1e-12, "the 400 m large scene");
        Heightfield meadow = hills(80);
        double[] moved = new double[3];
        double[] factors = {FlyCamera.SLOW, 1, FlyCamera.FAST};
        for (int k = 0; k < 3; k++) {
            FlyCamera fly = camera(meadow);
            double z = fly.camera().z();
            fly.move(0.5, 1, 0, 0, factors[k]);
            moved[k] = z - fly.camera().z();
        }
        assertEquals(3.2 * 0.5, moved[1], 1e-9);
        assertEquals(moved[1] / 4, moved[0], 1e-9, "Ctrl: four times slower");
        assertEquals(moved[1] * 4, moved[2], 1e-9, "Shift: four times faster");
        FlyCamera fly = camera(meadow);
        fly.scaleSpeed(2);
        assertEquals(3.2 * 1.5625, fly.speed(), 1e-9, "two wheel steps: 1.25 squared");
    }

    @Test
    void framingTheSceneShowsTheWholeTerrainFromInsideItsBounds() {
        for (double size : new double[] {4, 24, 80, 400}) {
            Heightfield ground = hills(size);
            FlyCamera fly = camera(ground);
            fly.togglePath();
            fly.frameScene();
            assertFalse(fly.playing());
            ViewCamera c = fly.camera();
            assertTrue(ground.contains(c.x(), c.z()), "inside the bounds");
            assertTrue(c.y() > ground.maxHeight(), "above every hill");
            Matrix4f vp = c.viewProjection(new Matrix4f());
            double[][] points = {{0, 0}, {ground.minX(), ground.minZ()}, {ground.maxX(), ground.minZ()},
                {0, ground.minZ()}, {0, 0.6 * ground.maxZ()}};
            for (double[] p : points) {
                Vector4f v = vp.transform(new Vector4f((float) p[0], (float) ground.height(p[0], p[1]), (float) p[1], 1));
                assertTrue(v.w > 0 && Math.abs(v.x / v.w) <= 1 && Math.abs(v.y / v.w) <= 1,
                        size + " m terrain: (" + p[0] + ", " + p[1] + ") in view, ndc " + v.x / v.w + ", " + v.y / v.w);
            }
        }
    }
}
