package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.ViewCamera;
import org.junit.jupiter.api.Test;
import org.joml.Matrix4f;
import org.joml.Vector4f;

/**
 * The draw decision culls a plant exactly when its bounding sphere (centred on its base) lies outside
 * one of the camera's frustum planes, measured in metres: the planes must be normalised for the
 * sphere test (a plant whose base is below the picture but whose flower is in it was culled when
 * they were not). Checked for every plant of C1 against planes computed here, from cameras looking
 * down at several pitches and headings.
 */
class DrawDecisionCullingTest {
    @Test
    void aPlantIsCulledOnlyWhenItsSphereIsOutside() throws Exception {
        World world = SimFixtures.world();
        DrawDecision decision = DrawDecision.of(world);
        Frame frame = new Frame(world.plantCount(), world.bendGeometry());
        Matrix4f vp = new Matrix4f();
        Vector4f plane = new Vector4f();
        int culled = 0;
        int drawn = 0;
        int nearEdge = 0;
        for (double pitch : new double[] {-0.2, -0.5, -0.9}) {
            for (double yaw = 0; yaw < 2 * Math.PI; yaw += Math.PI / 3) {
                ViewCamera cam = new ViewCamera();
                cam.setPosition(1, 2, 1);
                cam.setOrientation(yaw, pitch);
                cam.setLens(Math.toRadians(50), 16 / 9.0, 0.05, 200);
                decision.decideAll(cam, frame);
                cam.viewProjection(vp);
                for (int p = 0; p < world.plantCount(); p++) {
                    float r = DrawDecision.boundingRadius(world.plants().species().get(world.plantSpecies(p)));
                    double worst = Double.POSITIVE_INFINITY;
                    for (int i = 0; i < 6; i++) {
                        vp.frustumPlane(i, plane);
                        double n = Math.sqrt(plane.x * plane.x + plane.y * plane.y + plane.z * plane.z);
                        double d = (plane.x * world.plantX(p) + plane.y * world.plantY(p) + plane.z * world.plantZ(p)
                                + plane.w) / n;
                        worst = Math.min(worst, d);
                    }
                    if (Math.abs(worst + r) < 1e-3) {
                        continue; // on the sphere's edge: either answer is right
                    }
                    boolean inside = worst > -r;
                    nearEdge += worst < 0 && inside ? 1 : 0;
                    assertEquals(inside, frame.drawLevel(p) >= 0, "plant " + p + ": nearest plane " + worst
                            + " m from its base, radius " + r + " m");
                    culled += inside ? 0 : 1;
                    drawn += inside ? 1 : 0;
                }
            }
        }
        assertTrue(culled > 100 && drawn > 100 && nearEdge > 10, "culled " + culled + ", drawn " + drawn
                + ", drawn with the base outside the picture " + nearEdge);
    }

    /**
     * The step skips the sphere test for a chunk whose box of plant bases the frustum holds whole: then
     * every sphere of the chunk passes it. Checked on C1's plants cut into ranges of 7, for cameras
     * that hold some ranges whole and cut others.
     */
    @Test
    void aRangeInsideTheFrustumHasEverySphereInside() throws Exception {
        World world = SimFixtures.world();
        DrawDecision decision = DrawDecision.of(world);
        int plants = world.plantCount();
        int[] first = new int[(plants + 6) / 7 + 1];
        for (int i = 0; i < first.length; i++) {
            first[i] = Math.min(plants, 7 * i);
        }
        float[] box = decision.baseBoxes(first);
        org.joml.FrustumIntersection frustum = new org.joml.FrustumIntersection();
        Matrix4f vp = new Matrix4f();
        int inside = 0;
        int cut = 0;
        for (double pitch : new double[] {-0.3, -0.7, -1.2, -1.5}) {
            for (double yaw = 0; yaw < 2 * Math.PI; yaw += Math.PI / 4) {
                ViewCamera cam = new ViewCamera();
                cam.setPosition(0, pitch < -1 ? 12 : 3, 0);
                cam.setOrientation(yaw, pitch);
                cam.setLens(Math.toRadians(60), 16 / 9.0, 0.05, 200);
                frustum.set(cam.viewProjection(vp), true);
                for (int i = 0; i + 1 < first.length; i++) {
                    int o = 6 * i;
                    if (frustum.intersectAab(box[o], box[o + 1], box[o + 2], box[o + 3], box[o + 4], box[o + 5])
                            != org.joml.FrustumIntersection.INSIDE) {
                        cut++;
                        continue;
                    }
                    inside++;
                    for (int p = first[i]; p < first[i + 1]; p++) {
                        assertTrue(world.plantX(p) >= box[o] && world.plantX(p) <= box[o + 3]
                                && world.plantZ(p) >= box[o + 2] && world.plantZ(p) <= box[o + 5], "plant " + p);
                        float r = decision.radius(world.plantSpecies(p));
                        assertTrue(frustum.testSphere(world.plantX(p), world.plantY(p), world.plantZ(p), r),
                                "plant " + p + " of a range held whole");
                    }
                }
            }
        }
        assertTrue(inside > 50 && cut > 50, "ranges held whole " + inside + ", others " + cut);
    }
}
