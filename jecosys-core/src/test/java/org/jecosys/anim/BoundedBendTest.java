package org.jecosys.anim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.field.DragLaw;
import org.junit.jupiter.api.Test;

/**
 * The bend is bounded physically (see "Bounded bend" in {@link SpringKinds}): the spring's rest
 * point is F/PC up to half the bend limit {@code length sin(maxBend)}, then stiffens smoothly toward
 * it, so no wind reaches the last pose, a stronger wind still bends further, and a component
 * released from a storm is back within a few tau.
 */
class BoundedBendTest {
    static final double PC = 0.2;
    static final double TAU = 0.3;
    static final double DRAG_AREA = 0.002;
    static final double LENGTH = 0.5;
    static final double MAX_BEND = 1.2;
    static final double H = 1.0 / 60;

    static SpringModelTest.One blade() {
        SpringKinds.Builder b = new SpringKinds.Builder();
        b.add(PC, TAU, 0.0004, DRAG_AREA, LENGTH, 0.02, MAX_BEND, 16, 0xFF);
        SpringModelTest.One o = new SpringModelTest.One(b.build(), DRAG_AREA, 4);
        return o;
    }

    static double limit() {
        return LENGTH * Math.sin(MAX_BEND);
    }

    static double speedFor(double deviation) {
        return Math.sqrt(deviation * PC / (0.5 * DragLaw.AIR_DENSITY * DRAG_AREA));
    }

    static double settle(SpringModelTest.One o, double speed, double seconds) {
        o.wx[0] = (float) speed;
        o.wz[0] = 0;
        for (int i = 0; i < Math.round(seconds / H); i++) {
            o.step(H);
        }
        return Math.hypot(o.s.deviationX(0), o.s.deviationZ(0));
    }

    @Test
    void belowTheKneeTheEquilibriumIsFOverPcAndAboveItStaysBelowTheLimit() {
        double knee = SpringKinds.KNEE * limit();
        assertEquals(limit(), blade().s.kinds().bendLimit(0), 1e-6);
        for (double f : new double[] {0.05, 0.3, 0.6, 0.9, 1.0}) {
            double want = f * knee;
            double d = settle(blade(), speedFor(want), 20 * TAU);
            assertEquals(want, d, 0.01 * want, "F/PC = " + f + " of the knee");
        }
        double prev = knee;
        for (double f : new double[] {1.2, 2, 5, 50, 5000}) {
            double d = settle(blade(), speedFor(f * knee), 20 * TAU);
            assertTrue(d > prev && d < limit(), "F/PC = " + f + " knees: " + d + " after " + prev + ", limit " + limit());
            prev = d;
        }
    }

    @Test
    void noOvershootOnAStepOrARelease() {
        for (double f : new double[] {0.5, 3, 300}) {
            SpringModelTest.One o = blade();
            o.s.settle(0, 1, o.step); // in no wind
            double speed = speedFor(f * SpringKinds.KNEE * limit());
            double top = 0;
            for (int i = 0; i < Math.round(20 * TAU / H); i++) {
                top = Math.max(top, settle(o, speed, H));
            }
            double end = Math.hypot(o.s.deviationX(0), o.s.deviationZ(0));
            assertTrue(top <= 1.01 * end, "step to " + f + " knees overshoots: " + top + " > " + end);
            double low = 0;
            for (int i = 0; i < Math.round(20 * TAU / H); i++) {
                settle(o, 0, H);
                low = Math.min(low, o.s.deviationX(0));
            }
            assertTrue(-low <= 0.01 * end, "release from " + f + " knees swings through: " + low);
        }
    }

    @Test
    void aStormNeverReachesTheLastPoseStillShowsGustsAndIsOverWithinAFewTau() {
        SpringModelTest.One o = blade();
        o.s.settle(0, 1, o.step);
        double maxPose = o.s.kinds().poseMax(0);
        float lowest = Float.MAX_VALUE;
        float highest = 0;
        for (int i = 0; i < Math.round(2 / H); i++) {
            double speed = 200 + 100 * Math.sin(2 * Math.PI * i * H); // a 200 m/s storm gusting by 100 m/s
            settle(o, speed, H);
            float pose = o.s.poseCoordinate(0);
            assertTrue(pose < maxPose, "never at the last pose: " + pose);
            assertTrue(Math.hypot(o.s.deviationX(0), o.s.deviationZ(0)) < limit());
            if (i * H > 1) {
                lowest = Math.min(lowest, o.s.bend(0));
                highest = Math.max(highest, o.s.bend(0));
            }
        }
        assertTrue(highest - lowest > 1e-3, "the gusts still show: bend " + lowest + " .. " + highest);
        float storm = o.s.bend(0);
        settle(o, 0, 5 * TAU);
        assertTrue(o.s.bend(0) < 0.1 * storm, "5 tau after the storm: " + o.s.bend(0) + " of " + storm);
        settle(o, 0, 3 * TAU);
        assertTrue(o.s.bend(0) < 0.02 * storm, "8 tau after the storm: " + o.s.bend(0) + " of " + storm);
    }

    @Test
    void theBendKeepsTheLength() {
        SpringModelTest.One o = blade();
        double d = 0.6 * limit();
        settle(o, speedFor(d), 20 * TAU);
        double got = Math.hypot(o.s.deviationX(0), o.s.deviationZ(0));
        // the deviation runs along the rest lean (heading 0.3 rad, wind along +X): the extra tip offset is
        // |L + D| - l, and its sine over the length is the bend
        double lx = 0.02 * Math.cos(0.3) + o.s.deviationX(0);
        double lz = 0.02 * Math.sin(0.3) + o.s.deviationZ(0);
        double extra = Math.hypot(lx, lz) - 0.02;
        assertEquals(Math.asin(extra / LENGTH), o.s.bend(0), 2e-3, "deviation " + got);
    }
}
