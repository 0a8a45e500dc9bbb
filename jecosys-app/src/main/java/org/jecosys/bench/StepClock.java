package org.jecosys.bench;

import java.lang.management.ManagementFactory;
import java.util.Arrays;

/**
 * Two clocks beside a step's wall time, to tell the library's spread from the machine's:
 * <ul>
 * <li>{@link #cpuNanos()}: the CPU time of the stepping thread and of the animation pool's threads
 * (found once by name), summed. It leaves out the time a thread waited to run (a virtual CPU parked by
 * its host, a thread woken late), which a wall clock counts, and a collector's pause; what it spreads
 * by is the step's own work (its content, tile arrivals) and its workers' spinning at the barrier.</li>
 * <li>{@link #floor}: a fixed arithmetic kernel of about a step's length, paced like the walk (one
 * period of the rate, the thread parked in between). Its 99th percentile over its median is the
 * machine's own for any step of that length: there is nothing in the kernel to spread.</li>
 * <li>{@link TwoThreadKernel}: the same kernel on two threads at once, between the steps.</li>
 * </ul>
 * Bench only; {@link #cpuNanos()} allocates nothing, the constructor and {@link #floor} allocate.
 */
final class StepClock {
    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
    private final long[] ids;
    /** Keeps the kernel's result alive so that it is computed. */
    private static volatile double sink;

    /**
     * The calling thread and the live threads whose names start with {@code poolPrefix}.
     *
     * @param poolPrefix the animation pool's thread-name prefix
     * @throws IllegalStateException when no such thread is alive: the clock would count the caller only
     */
    StepClock(String poolPrefix) {
        long[] found = new long[64];
        int n = 0;
        found[n++] = Thread.currentThread().getId();
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.getName().startsWith(poolPrefix) && n < found.length) {
                found[n++] = t.getId();
            }
        }
        if (n == 1) {
            throw new IllegalStateException("no live thread is named " + poolPrefix + "...: its CPU time would be left out");
        }
        ids = Arrays.copyOf(found, n);
    }

    /** CPU nanoseconds used so far by the counted threads (a thread that ended counts 0). */
    long cpuNanos() {
        long sum = 0;
        for (long id : ids) {
            sum += Math.max(0, THREADS.getThreadCpuTime(id));
        }
        return sum;
    }

    /**
     * The machine's spread for a step of about {@code stepMs}: a fixed kernel run {@code steps} times at
     * {@code rate} per second, the thread parked between runs; {median, 99th percentile} of its wall
     * time, ms.
     */
    static double[] floor(double stepMs, double rate, int steps) {
        long n = size(stepMs);
        double[] ms = new double[steps];
        long period = (long) (1e9 / rate);
        long deadline = System.nanoTime();
        for (int s = 0; s < steps; s++) {
            deadline += period;
            sleepUntil(deadline);
            long t0 = System.nanoTime();
            sink = kernel(n);
            ms[s] = (System.nanoTime() - t0) / 1e6;
        }
        return new double[] {Stats.median(ms), Stats.percentile(ms, 0.99)};
    }

    /**
     * The kernel's length for about {@code stepMs}: warmed up (compiled), then the fastest of three runs,
     * doubling until a quarter step, scaled.
     */
    static long size(double stepMs) {
        long n = 1 << 14;
        for (int w = 0; w < 2000; w++) {
            sink = kernel(n);
        }
        while (true) {
            double ms = Double.POSITIVE_INFINITY;
            for (int k = 0; k < 3; k++) {
                long t0 = System.nanoTime();
                sink = kernel(n);
                ms = Math.min(ms, (System.nanoTime() - t0) / 1e6);
            }
            if (ms >= stepMs / 4 || n > (1L << 40)) {
                return Math.max(1, (long) (n * stepMs / Math.max(1e-3, ms)));
            }
            n *= 2;
        }
    }

    /** A loop-carried chain of multiplies and adds: no memory, no allocation, the same work every time. */
    static double kernel(long n) {
        double a = 1.000000001;
        double s = 0;
        for (long i = 0; i < n; i++) {
            s = s * a + 1e-9;
        }
        return s;
    }

    /**
     * Parks the calling thread until {@code System.nanoTime()} reaches {@code deadline}, parking again
     * after an early return (a park may return early: a spurious wake-up, a permit left by an unpark).
     * No allocation.
     */
    static void sleepUntil(long deadline) {
        for (long wait = deadline - System.nanoTime(); wait > 0; wait = deadline - System.nanoTime()) {
            java.util.concurrent.locks.LockSupport.parkNanos(wait);
        }
    }

    /**
     * A real-time loop's pacing: parks until {@code deadline} and returns it, or returns now when the
     * deadline has passed (a late frame starts the next period from now). No allocation.
     */
    static long pace(long deadline) {
        if (deadline - System.nanoTime() > 0) {
            sleepUntil(deadline);
            return deadline;
        }
        return System.nanoTime();
    }
}
