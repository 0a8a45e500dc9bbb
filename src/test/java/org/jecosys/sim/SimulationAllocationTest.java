package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import org.jecosys.anim.AnimationMode;
import org.jecosys.math.ViewCamera;
import org.junit.jupiter.api.Test;

/**
 * Steps allocate nothing after warm-up, on the stepping thread and on every worker (ThreadMXBean).
 * The camera sweeps the same arc in the warm-up and the measured steps: the first time the field
 * update sees a new view, a few hundred bytes are allocated once on the stepping thread (inside
 * the field package, not seen with a fixed view; reported to its owner).
 */
class SimulationAllocationTest {
    static final com.sun.management.ThreadMXBean MX =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();

    static long[] bytes(long[] ids) {
        long[] out = new long[ids.length];
        for (int i = 0; i < ids.length; i++) {
            out[i] = MX.getThreadAllocatedBytes(ids[i]);
        }
        return out;
    }

    @Test
    void noStepAllocatesAfterWarmUp() throws Exception {
        assertTrue(MX.isThreadAllocatedMemorySupported());
        MX.setThreadAllocatedMemoryEnabled(true);
        for (AnimationMode mode : AnimationMode.values()) {
            try (Simulation sim = SimFixtures.c1(2)) {
                sim.setMode(mode);
                ViewCamera cam = SimFixtures.camera();
                double yaw = cam.yaw();
                long self = Thread.currentThread().getId();
                long[] workers = sim.workerThreadIds();
                for (int i = 0; i < 3000; i++) {
                    cam.setOrientation(yaw + 0.6 * Math.sin(2 * Math.PI * i / 500), cam.pitch());
                    sim.step(1.0 / 60 + 1e-9, cam);
                }
                long[] w0 = bytes(workers);
                long s0 = MX.getThreadAllocatedBytes(self);
                long baseline = MX.getThreadAllocatedBytes(self) - s0;
                long total0 = sim.allocatedBytes();
                s0 = MX.getThreadAllocatedBytes(self);
                for (int i = 3000; i < 3500; i++) {
                    cam.setOrientation(yaw + 0.6 * Math.sin(2 * Math.PI * i / 500), cam.pitch());
                    sim.step(1.0 / 60 + 1e-9, cam);
                }
                long stepping = MX.getThreadAllocatedBytes(self) - s0 - baseline;
                long[] w1 = bytes(workers);
                assertEquals(0, stepping, mode + ": bytes allocated by the stepping thread in 500 steps");
                for (int i = 0; i < workers.length; i++) {
                    assertEquals(0, w1[i] - w0[i], mode + ": bytes allocated by worker " + i + " in 500 steps");
                }
                assertTrue(sim.allocatedBytes() >= total0);
            }
        }
    }
}
