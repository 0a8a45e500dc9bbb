package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.anim.AnimationView;
import org.jecosys.math.ViewCamera;
import org.junit.jupiter.api.Test;

/**
 * A game that stops at a breakpoint, or is suspended for a day, calls {@code step} with a huge dt:
 * the simulation runs maxSubSteps fixed steps, counts the rest as dropped and carries on normally.
 */
class LongPauseTest {
    @Test
    void aLongPauseRunsMaxSubStepsAndDropsTheRest() throws Exception {
        try (Simulation sim = SimFixtures.c1(2)) {
            ViewCamera cam = SimFixtures.camera();
            int max = sim.def().animation().maxSubSteps();
            double h = sim.inspect().fixedStep();
            assertEquals(1, sim.step(h * 1.5, cam));
            long stepsBefore = sim.inspect().steps();
            double timeBefore = sim.inspect().time();
            long droppedBefore = sim.inspect().droppedSteps();

            assertEquals(max, sim.step(1e6, cam));

            assertEquals(stepsBefore + max, sim.inspect().steps());
            assertEquals(timeBefore + max * h, sim.inspect().time(), 1e-9);
            long dropped = sim.inspect().droppedSteps() - droppedBefore;
            long expected = (long) ((1e6 + 0.5 * h) / h) - max;
            assertTrue(Math.abs(dropped - expected) <= 1, "dropped " + dropped + ", expected about " + expected);
            assertFinite(sim.inspect().state());
            assertEquals(sim.inspect().steps(), sim.latestFrame().number());

            // the backlog is gone: the next frames step normally
            assertEquals(0, sim.step(0, cam));
            assertEquals(1, sim.step(h, cam));
            assertEquals(stepsBefore + max + 1, sim.inspect().steps());
            assertFinite(sim.inspect().state());
        }
    }

    @Test
    void anAbsurdPauseSaturatesTheCounterAndNothingElse() throws Exception {
        try (Simulation sim = SimFixtures.c1(1)) {
            ViewCamera cam = SimFixtures.camera();
            int max = sim.def().animation().maxSubSteps();
            assertEquals(max, sim.step(Double.MAX_VALUE, cam));
            assertTrue(sim.inspect().droppedSteps() > 0);
            assertEquals(max, sim.step(Double.MAX_VALUE, cam));
            assertEquals(Long.MAX_VALUE, sim.inspect().droppedSteps(), "saturates, never wraps to negative");
            assertEquals(1, sim.step(sim.inspect().fixedStep(), cam), "no backlog is kept");
            assertEquals(2L * max + 1, sim.inspect().steps());
            assertFinite(sim.inspect().state());
        }
    }

    @Test
    void negativeNaNAndInfiniteTimesAreRejected() throws Exception {
        try (Simulation sim = SimFixtures.c1(1)) {
            ViewCamera cam = SimFixtures.camera();
            for (double dt : new double[] {-1e-9, -1, Double.NaN, Double.POSITIVE_INFINITY,
                                           Double.NEGATIVE_INFINITY}) {
                IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> sim.step(dt, cam));
                assertTrue(e.getMessage().contains("dt"), e.getMessage());
            }
            assertEquals(0, sim.inspect().steps());
            assertEquals(0, sim.inspect().droppedSteps());
        }
    }

    private static void assertFinite(AnimationView s) {
        for (int c = 0; c < s.componentCount(); c++) {
            assertTrue(Float.isFinite(s.deviationX(c)) && Float.isFinite(s.deviationZ(c))
                    && Float.isFinite(s.velocityX(c)) && Float.isFinite(s.velocityZ(c))
                    && Float.isFinite(s.poseCoordinate(c)) && Float.isFinite(s.azimuth(c)), "component " + c);
        }
    }
}
