package org.jecosys.bench;

import java.lang.management.ManagementFactory;

/**
 * The CPU time of this whole process, every thread counted (the JVM's and native ones: a software
 * rasteriser's, whose work is the "GPU" work of a frame there). Unlike the wall clock it does not count
 * time the host gave to others; it still follows the host's speed (on the 2-core development machine it
 * spread from run to run as much as the wall clock did). On a GPU it counts only the driver's CPU side.
 * Linux HotSpot reads it in steps of 10 ms. Any thread; allocates nothing after the first call.
 */
final class ProcessCpu {
    private static final com.sun.management.OperatingSystemMXBean OS = bean();

    private ProcessCpu() {
    }

    private static com.sun.management.OperatingSystemMXBean bean() {
        return ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean b
                ? b : null;
    }

    /** {@return the process's CPU time so far, nanoseconds, or -1 where the JVM does not tell} */
    static long nanos() {
        return OS == null ? -1 : OS.getProcessCpuTime();
    }
}
