package org.jecosys.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * The open-world section's reading of its slow steps: those over 1.5 times the median wall time, and
 * among them those whose CPU time was the usual one (they waited for a core).
 */
class SlowStepsTest {
    @Test
    void slowStepsWithTheUsualWorkAreToldFromSlowStepsWithMoreWork() {
        // ten steps of 4 ms on two threads (8 ms of CPU); two of 9 and 10 ms with the usual work (8 ms: one
        // core), one of 9 ms with twice the work (16 ms), one of 5 ms (not slow)
        double[] wall = {4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 9, 10, 9, 5};
        double[] cpu = {8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 16, 8};
        double[] r = SlowSteps.count(wall, cpu);
        assertEquals(3, r[0], "steps over 1.5 times the median");
        assertEquals(2, r[1], "of those, with CPU time within 1.3 times its median");
        assertEquals(8.0 / 9, r[2], 1e-12, "CPU over wall in the slow steps (median, nearest rank)");
        assertEquals(2.0, r[3], 1e-12, "CPU over wall in all steps");
        double[] none = SlowSteps.count(new double[] {4, 4, 4}, new double[] {8, 8, 8});
        assertEquals(0, none[0]);
        assertEquals(Double.NaN, none[2]);
    }
}
