package org.jecosys.anim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.plant.PoseMapping;
import org.junit.jupiter.api.Test;

/** Deviation to pose coordinate and azimuth; rest heading; level-of-detail and visibility filters. */
class BendTest {
    static AnimationState plants(int lodMask, float heading, float lean) {
        SpringKinds.Builder b = new SpringKinds.Builder();
        b.add(0.2, 0.3, 0.0004, 0.002, 0.4, lean, 1.2, 16, lodMask);
        return new AnimationState(b.build(), new double[][] {{10, 15}}, new int[1], new int[] {0, 1}, new float[1],
                new float[1], new float[1], new int[1], new float[] {heading});
    }

    @Test
    void atRestAComponentShowsPoseZeroAtItsRestHeading() {
        for (float h : new float[] {0f, 1f, 2.5f, -2f, 3.1f}) {
            AnimationState s = plants(0xFF, h, 0.05f);
            assertEquals(0, s.poseCoordinate(0));
            assertEquals(Math.atan2(Math.sin(h), Math.cos(h)), s.azimuth(0), 2e-5);
            s.kinds().prepare(1.0 / 60, 4);
            for (int i = 0; i < 100; i++) {
                s.animate(0, 1, AnimationStep.of(AnimationMode.CONSTRAINT, new float[1], new float[1],
                        new boolean[] {true}));
            }
            assertEquals(0, s.poseCoordinate(0), "no wind, no bend");
            assertEquals(Math.atan2(Math.sin(h), Math.cos(h)), s.azimuth(0), 2e-5, "no flip at zero wind");
        }
    }

    @Test
    void windAlongTheLeanBendsFurtherAndKeepsTheHeading() {
        AnimationState s = plants(0xFF, 0.5f, 0.05f);
        s.kinds().prepare(1.0 / 60, 4);
        float[] wx = {(float) (6 * Math.cos(0.5))};
        float[] wz = {(float) (6 * Math.sin(0.5))};
        for (int i = 0; i < 300; i++) {
            s.animate(0, 1, AnimationStep.of(AnimationMode.CONSTRAINT, wx, wz, new boolean[] {true}));
        }
        double d = Math.hypot(s.deviationX(0), s.deviationZ(0));
        assertEquals(PoseMapping.poseCoordinate(d, 0.4, 1.2, 16), s.poseCoordinate(0), 1e-3);
        assertTrue(s.poseCoordinate(0) > 1);
        assertEquals(0.5, s.azimuth(0), 1e-4);
    }

    @Test
    void windAcrossTheLeanTurnsTheComponent() {
        AnimationState s = plants(0xFF, 0f, 0.05f);
        s.kinds().prepare(1.0 / 60, 4);
        for (int i = 0; i < 300; i++) {
            s.animate(0, 1, AnimationStep.of(AnimationMode.CONSTRAINT, new float[1], new float[] {6},
                    new boolean[] {true}));
        }
        double expected = Math.atan2(s.deviationZ(0), 0.05 + s.deviationX(0));
        assertEquals(expected, s.azimuth(0), 2e-5);
        assertTrue(s.azimuth(0) > 0.3);
    }

    @Test
    void invisiblePlantsAndComponentsNotDrawnAtTheirLevelKeepTheirState() {
        AnimationState s = plants(0b011, 0f, 0.05f);
        s.kinds().prepare(1.0 / 60, 4);
        float[] w = {5};
        assertEquals(0, s.animate(0, 1, AnimationStep.of(AnimationMode.CONSTRAINT, w, w, new boolean[] {false})));
        assertEquals(0, s.deviationX(0));
        s.resetToRest(0, 1); // at rest, and following the wind from there on
        // 20 m away: level 2, where this kind is not drawn
        AnimationStep step = AnimationStep.of(AnimationMode.CONSTRAINT, w, w, new boolean[] {true});
        assertEquals(0, s.animate(0, 1, step.eye(20, 0, 0)));
        assertEquals(2, s.level(0));
        assertEquals(0, s.deviationX(0));
        assertEquals(1, s.animate(0, 1, step.eye(12, 0, 0)));
        assertEquals(1, s.level(0));
        assertTrue(s.deviationX(0) > 0);
        s.setLodScale(2); // level edges 20 and 30: 20 m is now level 1
        assertEquals(1, s.animate(0, 1, step.eye(20, 0, 0)));
    }

    @Test
    void trigMatchesTheJdkWithinTheDocumentedError() {
        for (int i = -2000; i <= 2000; i++) {
            float y = (float) Math.sin(i * 0.0031);
            float x = (float) Math.cos(i * 0.0031) * (i % 3 + 0.5f);
            assertEquals(Math.atan2(y, x), Trig.atan2(y, x), 1e-5);
            float t = i * 0.01f;
            if (t >= 0) {
                assertEquals(Math.atan(t), Trig.atanPositive(t), 1e-5);
            }
        }
        assertEquals(0, Trig.atan2(0, 0));
        assertEquals(Math.PI / 2, Trig.atanPositive(Float.POSITIVE_INFINITY), 1e-6);
    }
}
