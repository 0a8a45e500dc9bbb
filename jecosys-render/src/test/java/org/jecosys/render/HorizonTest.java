package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * Issue 25, "Done when": the world does not end in the air. From 60 m above the meadow and from 5 m
 * above the rose (the highest the viewer lets the eye go over its 4 m square is 4 m above its top), and
 * from above c1, every pixel whose ray points below the horizon (by more than 0.2 degrees) shows ground:
 * the depth of the render without plants is not the far plane's there. The ground beyond the terrain is
 * the renderer's horizon skirt, hazed like the rest.
 */
class HorizonTest {
    private static final int W = 320;
    private static final int H = 180;
    /** Rays this far below the horizon must meet the ground, radians (0.2 degrees). */
    private static final double BELOW = Math.toRadians(0.2);

    @Test
    void fromHighAboveTheMeadowTheGroundReachesTheHorizon() {
        checkFromAbove("meadow.xml", 60);
    }

    @Test
    void fromAboveTheRoseTheGroundReachesTheHorizon() {
        checkFromAbove("rose.xml", 5);
    }

    @Test
    void fromAbovePaperSceneTheGroundReachesTheHorizon() {
        checkFromAbove("c1.xml", 30);
    }

    /** Eye {@code height} metres above the terrain's middle, looking 15 and 40 degrees down, four ways. */
    private static void checkFromAbove(String scene, double height) {
        SceneDef def = RenderScenes.load(scene);
        World world = RenderScenes.build(def);
        var hf = world.terrain().heightfield();
        double cx = hf.minX() + 0.5 * (hf.resolution() - 1) * hf.cellX();
        double cz = hf.minZ() + 0.5 * (hf.resolution() - 1) * hf.cellZ();
        double eyeY = hf.height(cx, cz) + height;
        int sky = 0;
        int below = 0;
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            for (double pitchDeg : new double[] {-15, -40}) {
                for (int k = 0; k < 4; k++) {
                    ViewCamera cam = new ViewCamera();
                    cam.setPosition(cx, eyeY, cz);
                    cam.setOrientation(k * Math.PI / 2 + 0.3, Math.toRadians(pitchDeg));
                    cam.setLens(def.camera().fovY(), W / (double) H, 0.05, 400);
                    double[] dist = s.groundDistance(TestFrames.rest(world, cam), cam);
                    Matrix4f inv = cam.viewProjection(new Matrix4f()).invert();
                    Vector3f near = new Vector3f();
                    Vector3f far = new Vector3f();
                    for (int y = 0; y < H; y++) {
                        for (int x = 0; x < W; x++) {
                            float nx = (float) (2 * (x + 0.5) / W - 1);
                            float ny = (float) (2 * (y + 0.5) / H - 1);
                            inv.transformProject(nx, ny, -1, near);
                            inv.transformProject(nx, ny, 1, far);
                            far.sub(near).normalize();
                            if (far.y < -Math.sin(BELOW)) {
                                below++;
                                if (Double.isInfinite(dist[y * W + x])) {
                                    sky++;
                                }
                            }
                        }
                    }
                }
            }
        }
        System.out.printf("[look] %s from %.0f m above: %d of %d pixels below the horizon show sky (0)%n", scene,
                height, sky, below);
        assertTrue(below > 0, "some of the view is below the horizon");
        assertTrue(sky == 0, sky + " of " + below + " pixels below the horizon show the sky, from " + height
                + " m above " + scene);
    }
}
