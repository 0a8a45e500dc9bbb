package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import org.jecosys.anim.AnimationMode;
import org.jecosys.math.ViewCamera;
import org.junit.jupiter.api.Test;

/**
 * Steps allocate nothing after warm-up, on the stepping thread and on every worker (ThreadMXBean).
 * After warm-up the steps are measured in windows of 250; the test passes when two consecutive
 * windows allocate 0 bytes on every stepping thread. A per-step allocation of even one byte could
 * never give a zero window; what the windows tolerate is the JVM's own allocation of a few hundred
 * bytes, once, while code moves between the interpreter and the C1/C2 compilers (seen with JFR as
 * String and byte[] pairs at lines with no string code, never steady).
 */
class SimulationAllocationTest {
    static final com.sun.management.ThreadMXBean MX =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
    static final int WINDOW = 250;
    static final int MAX_WINDOWS = 12;

    static long total(long self, long[] workers) {
        long sum = MX.getThreadAllocatedBytes(self);
        for (long id : workers) {
            sum += MX.getThreadAllocatedBytes(id);
        }
        return sum;
    }

    @Test
    void noStepAllocatesAfterWarmUp() throws Exception {
        assertTrue(MX.isThreadAllocatedMemorySupported());
        MX.setThreadAllocatedMemoryEnabled(true);
        for (int run = 0; run <= AnimationMode.values().length; run++) {
            // every mode on C1, then CONSTRAINT in a turbulent wind with plants varying in response
            boolean turbulent = run == AnimationMode.values().length;
            AnimationMode mode = turbulent ? AnimationMode.CONSTRAINT : AnimationMode.values()[run];
            try (Simulation sim = turbulent ? SimFixtures.turbulent(2) : SimFixtures.c1(2)) {
                sim.setMode(mode);
                if (turbulent) {
                    sim.setThinning(3, 10, 0.3); // the draw decision's distance thinning allocates nothing either
                }
                ViewCamera cam = SimFixtures.camera();
                double yaw = cam.yaw();
                long self = Thread.currentThread().getId();
                long[] workers = sim.inspect().workerThreadIds();
                int i = 0;
                for (; i < 1500; i++) {
                    cam.setOrientation(yaw + 0.6 * Math.sin(2 * Math.PI * i / 500), cam.pitch());
                    sim.step(1.0 / 60 + 1e-9, cam);
                }
                total(self, workers); // prime the counter's own first-call allocation
                long[] windows = new long[MAX_WINDOWS];
                int zeroRun = 0;
                int w = 0;
                for (; w < MAX_WINDOWS && zeroRun < 2; w++) {
                    long before = total(self, workers);
                    for (int k = 0; k < WINDOW; k++, i++) {
                        cam.setOrientation(yaw + 0.6 * Math.sin(2 * Math.PI * i / 500), cam.pitch());
                        sim.step(1.0 / 60 + 1e-9, cam);
                    }
                    // the second reading's own work happens before it reads, like the first's: they cancel
                    windows[w] = total(self, workers) - before;
                    zeroRun = windows[w] == 0 ? zeroRun + 1 : 0;
                }
                assertEquals(2, zeroRun, mode + ": two consecutive windows of " + WINDOW + " steps allocating 0 bytes on"
                        + " the stepping thread and every worker; bytes per window: "
                        + java.util.Arrays.toString(java.util.Arrays.copyOf(windows, w)));
                assertTrue(sim.inspect().allocatedBytes() >= 0);
            }
        }
    }
}
