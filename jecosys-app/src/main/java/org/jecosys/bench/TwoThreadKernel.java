package org.jecosys.bench;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

/**
 * The machine's own spread for a step that needs both cores at once: a fixed arithmetic kernel
 * ({@link StepClock#kernel}) run on the calling thread and on a helper thread side by side, the run
 * ending when both are done, as the open world's step runs on its stepping thread and the animation
 * pool's thread. Nothing in the two kernels can vary, so its 99th percentile over its median is what
 * the machine gives any two-thread step of that length. The bench runs it between the world's steps, in
 * the same seconds, so that the two are measured under the same host.
 *
 * <p>The caller {@link #arm}s a run at a time ahead, then {@link #run}s it: both threads park until the
 * start; the helper wakes {@link #LEAD_NS} early and spins to it, as the animation pool's thread polls
 * before a step it expects, so a late wake-up the pool avoids is not counted. One calling thread; the
 * constructor starts the helper thread, {@link #close} ends it. {@link #arm} and {@link #run} allocate
 * nothing.
 */
final class TwoThreadKernel implements AutoCloseable {
    /** How early the helper wakes before a run's start and spins, ns. */
    static final long LEAD_NS = 1_000_000;
    private final long n;
    private final Thread helper;
    private final AtomicInteger armed = new AtomicInteger();
    private final AtomicInteger done = new AtomicInteger();
    private volatile long start;
    private volatile boolean closed;
    private volatile double helperSink;
    private volatile double sink;

    /**
     * A kernel of about {@code ms} on each thread (sized on the calling thread); starts the helper.
     *
     * @param ms the kernel's length, milliseconds, greater than 0
     */
    TwoThreadKernel(double ms) {
        if (!(ms > 0)) {
            throw new IllegalArgumentException("the kernel's length must be over 0 ms, got " + ms);
        }
        n = StepClock.size(ms);
        helper = new Thread(this::serve, "jecosys-floor-helper");
        helper.setDaemon(true);
        helper.start();
    }

    /** The next run starts at {@code at} ({@link System#nanoTime()}); arm it ahead of its start. */
    void arm(long at) {
        start = at;
        armed.incrementAndGet();
        LockSupport.unpark(helper);
    }

    /**
     * Parks until the armed run's start, runs the kernel, waits for the helper's.
     *
     * @return the run's wall time from its start to both kernels' end, ns
     */
    long run() {
        int k = armed.get();
        StepClock.sleepUntil(start);
        long t0 = System.nanoTime();
        sink = StepClock.kernel(n);
        while (done.get() < k && helper.isAlive()) {
            Thread.onSpinWait();
        }
        return System.nanoTime() - t0;
    }

    /** {@return how many runs the helper has finished} */
    int helperRuns() {
        return done.get();
    }

    private void serve() {
        int seen = 0;
        while (!closed) {
            int k = armed.get();
            if (k == seen) {
                LockSupport.park(this);
                continue;
            }
            seen = k;
            long at = start;
            StepClock.sleepUntil(at - LEAD_NS);
            while (System.nanoTime() - at < 0) {
                Thread.onSpinWait();
            }
            helperSink = StepClock.kernel(n);
            done.set(seen);
        }
    }

    /** Ends the helper thread and waits for it. */
    @Override
    public void close() throws InterruptedException {
        closed = true;
        LockSupport.unpark(helper);
        helper.join();
    }
}
