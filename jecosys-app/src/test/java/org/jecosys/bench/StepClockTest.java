package org.jecosys.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class StepClockTest {
    @Test
    void theTwoThreadKernelRunsOnBothThreadsAtEveryArmedStartAndEndsItsHelper() throws Exception {
        long period = 5_000_000;
        long t = System.nanoTime();
        try (TwoThreadKernel k = new TwoThreadKernel(0.5)) {
            for (int i = 0; i < 20; i++) {
                t += period;
                k.arm(t);
                long ns = k.run();
                assertTrue(System.nanoTime() - t >= ns && ns > 0, "a run is timed from its armed start");
                assertEquals(i + 1, k.helperRuns(), "the run waited for the helper's kernel");
            }
        }
        assertFalse(Thread.getAllStackTraces().keySet().stream()
                .anyMatch(th -> th.getName().equals("jecosys-floor-helper")), "the helper thread has ended");
        assertThrows(IllegalArgumentException.class, () -> new TwoThreadKernel(0));
    }

    @Test
    void theOneThreadFloorTimesEveryRun() {
        double[] r = StepClock.floor(0.5, 200, 40);
        assertEquals(2, r.length);
        assertTrue(r[0] > 0 && r[1] >= r[0], "median " + r[0] + " ms, p99 " + r[1] + " ms");
    }
}
