package org.jecosys.sim;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import org.jecosys.math.Require;

/**
 * A fixed set of worker threads that run the chunks of one step (paper §5.1). Per step the owner
 * calls {@link #start()}, may do other work (the force-field update), then {@link #await()}.
 * Workers claim chunk indices 0 .. chunks-1 from an atomic counter and call
 * {@link ChunkTask#runChunk(int)}; which worker runs a chunk changes nothing in the result, because
 * chunks are fixed and disjoint. The owner is one of the workers: a pool of N workers has N - 1
 * threads, and {@link #await()} runs the chunks no thread has claimed yet; a step of one chunk wakes
 * no thread at all (waking costs more than such a chunk), and N = 1 runs everything on the owner.
 * Hand-off by a volatile generation counter and
 * {@link LockSupport#park()}/{@code unpark}: no task objects, lambdas or collections per step, no
 * allocation after the threads started. Owner: one thread at a time calls start/await/close.
 *
 * <p>Anticipation: a thread the owner unparks may be woken on the owner's own core and share it with
 * the owner until the scheduler moves it, so that the step runs as on one core. On a virtual machine
 * whose idle cores are halted this happened in one step in ten of a 30 Hz walk; a C program of two
 * threads showed the same (woken by another thread, the sleeper ran on the waker's core 295 times in
 * 300). A thread that wakes itself with a timer wakes on its own core. So the owner says at each
 * {@link #start(boolean)} whether another step follows right after this one (its loop of fixed
 * steps): then the pool threads spin for it (at most {@link #FOLLOW_CAP_NANOS}). After a step nothing
 * follows, they sleep until {@link #LEAD_NANOS} before the next burst of steps is due (the last
 * burst's start plus the interval between the last two bursts' starts, as a game's loop repeats its
 * frame) and spin until as long after it; only when the last two intervals differ by more than the
 * lead (no cadence to anticipate), or the burst comes outside that window, does the owner's unpark
 * wake them. The spinning costs at most twice the lead per burst of one thread's time, none while no
 * step is coming.
 */
final class WorkerPool implements AutoCloseable {
    /** The work of one chunk; implemented once, never allocated per step. */
    interface ChunkTask {
        /**
         * Runs chunk {@code chunk} on worker {@code worker}: in [0, workers() - 1), a pool thread, or
         * {@code workers() - 1}, the owner. A worker runs one chunk at a time, so per-worker scratch
         * needs no lock; the result must not depend on the worker.
         */
        void runChunk(int chunk, int worker);
    }

    private static final int SPINS = 200;
    /** How long a pool thread spins for the step the owner said follows, at most, nanoseconds. */
    static final long FOLLOW_CAP_NANOS = 2_000_000;
    /** How long before the burst it expects a pool thread wakes itself, and spins after it, nanoseconds. */
    static final long LEAD_NANOS = 1_000_000;
    /** Intervals between bursts longer than this are not anticipated: the owner's unpark wakes the threads. */
    static final long LONGEST_INTERVAL = 250_000_000;
    /** How long the owner spins for the pool's last chunks before it parks, nanoseconds. */
    private static final long DRAIN_SPIN_NANOS = 1_000_000;
    /**
     * The JVM's per-thread allocation counter, looked up once: {@code ManagementFactory.getThreadMXBean()}
     * itself allocates on every call, which would pollute the very measurement. Null when unsupported.
     */
    private static final com.sun.management.ThreadMXBean THREADS = threadBean();

    private final Thread[] threads;
    private final long[] ids;
    private final ChunkTask task;
    /** How long a pool thread spins for a step the owner said follows, at most, nanoseconds. */
    private final long followCap;
    private final int chunks;
    private final AtomicInteger next = new AtomicInteger();
    private final AtomicInteger pending = new AtomicInteger();
    /** System.nanoTime() at which the step's first chunk started and its last chunk ended, any thread. */
    private final AtomicLong firstChunk = new AtomicLong();
    private final AtomicLong lastChunk = new AtomicLong();
    /** Steps a pool thread found started while it was awake for them (spinning), summed over threads. */
    private final AtomicLong awake = new AtomicLong();
    /** Steps a pool thread was woken for by the owner's unpark, summed over threads. */
    private final AtomicLong unparked = new AtomicLong();
    private volatile int generation;
    /** Whether the owner said another step follows the current one; written before the generation. */
    private volatile boolean followed;
    /** System.nanoTime() of the last burst's first {@link #start}; 0: none yet. */
    private volatile long burstStart;
    /** The interval between the last two bursts' starts when it matched the one before; 0: no cadence. */
    private volatile long cadence;
    /** The owner's bursts of steps; owner only. */
    private final Bursts bursts = new Bursts();
    private volatile boolean stopped;
    private volatile Thread owner;
    /**
     * Whether the owner is parked (or about to) waiting for the pool: only then does the last worker
     * unpark it, so that no permit is left behind for the owner's own next park (a game's frame pacing).
     */
    private volatile boolean ownerParked;
    private volatile Throwable failure;

    WorkerPool(String name, int workers, int chunks, ChunkTask task) {
        this(name, workers, chunks, task, FOLLOW_CAP_NANOS);
    }

    /**
     * As {@link #WorkerPool(String, int, int, ChunkTask)}, the pool's threads spinning at most
     * {@code followCap} ns for a step the owner said follows (tests: a cap no machine's load reaches).
     */
    WorkerPool(String name, int workers, int chunks, ChunkTask task, long followCap) {
        if (followCap < 0) {
            throw new IllegalArgumentException("followCap must be at least 0 ns, got " + followCap);
        }
        this.followCap = followCap;
        Require.range("workers", workers, 1, 256);
        this.chunks = Require.range("chunks", chunks, 0, Integer.MAX_VALUE);
        this.task = Require.nonNull("task", task);
        threads = new Thread[workers - 1]; // the owner is the last worker: it helps in await()
        for (int i = 0; i < threads.length; i++) {
            int worker = i;
            Thread t = new Thread(() -> loop(worker), name + "-" + i);
            t.setDaemon(true);
            threads[i] = t;
        }
        ids = new long[threads.length];
        for (int i = 0; i < threads.length; i++) {
            ids[i] = threads[i].getId();
        }
        for (Thread t : threads) {
            t.start();
        }
    }

    private static com.sun.management.ThreadMXBean threadBean() {
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        return mx instanceof com.sun.management.ThreadMXBean smx && smx.isThreadAllocatedMemorySupported() ? smx
                : null;
    }

    /** Threads that animate: the pool's threads and the owner, which helps in {@link #await()}. */
    int workers() {
        return threads.length + 1;
    }

    /**
     * {@return how often a pool thread found a step started while it was awake for it} Summed over the
     * pool's threads since they started: steps the owner said would follow, and steps of a steady
     * cadence that came inside the anticipated window. Any thread; no allocation.
     */
    long awakeSteps() {
        return awake.get();
    }

    /** {@return how often a pool thread had to be woken by the owner for a step, summed over threads} Any thread. */
    long unparkedSteps() {
        return unparked.get();
    }

    /** The worker threads' ids (allocates). */
    long[] threadIds() {
        return ids.clone();
    }

    /**
     * Bytes allocated so far by the worker threads and by thread {@code other} (the owner; -1: none),
     * from {@code com.sun.management.ThreadMXBean#getThreadAllocatedBytes}; -1 when the JVM cannot
     * tell. Any thread; no allocation.
     */
    long allocatedBytes(long other) {
        com.sun.management.ThreadMXBean mx = THREADS;
        if (mx == null) {
            return -1;
        }
        long sum = other >= 0 ? Math.max(0, mx.getThreadAllocatedBytes(other)) : 0;
        for (long id : ids) {
            sum += Math.max(0, mx.getThreadAllocatedBytes(id));
        }
        return sum;
    }

    /**
     * Releases the workers on a new step. Owner thread. No allocation.
     *
     * @param followed whether the owner starts another step right after this one's {@link #await()}
     *                 (the pool threads then spin for it instead of sleeping)
     */
    void start(boolean followed) {
        if (stopped) {
            throw new IllegalStateException("the worker pool is closed");
        }
        owner = Thread.currentThread();
        if (bursts.step(followed, System.nanoTime())) { // the first step of a burst: the owner's cadence
            cadence = cadence(bursts.interval(), bursts.lastInterval());
            burstStart = bursts.start();
        }
        this.followed = followed;
        firstChunk.set(Long.MAX_VALUE);
        lastChunk.set(Long.MIN_VALUE);
        next.set(0);
        if (chunks <= 1 || threads.length == 0) {
            // one chunk (waking a worker costs more) or no pool threads: the owner runs them in await()
            pending.set(0);
            return;
        }
        pending.set(threads.length);
        generation++;
        for (Thread t : threads) {
            LockSupport.unpark(t);
        }
    }

    /**
     * The cadence to anticipate after a burst started {@code interval} after the one before, which came
     * {@code lastInterval} after its own predecessor (ns; 0: none): the interval when the two match
     * within {@link #LEAD_NANOS} and it is at most {@link #LONGEST_INTERVAL}, else 0 (no cadence: the
     * threads park until unparked). Pure.
     */
    static long cadence(long interval, long lastInterval) {
        boolean steady = interval > 0 && interval <= LONGEST_INTERVAL
                && Math.abs(interval - lastInterval) <= LEAD_NANOS;
        return steady ? interval : 0;
    }

    /**
     * Runs the chunks no worker has claimed yet on the calling thread, then waits until every worker
     * finished the step started last. Owner thread. No allocation.
     */
    void await() {
        // the caller helps: it runs every chunk no worker has claimed yet (each chunk is claimed once,
        // whoever runs it, so results do not depend on which thread did the work)
        Throwable own = null;
        try {
            runChunks(threads.length);
        } catch (RuntimeException | Error t) {
            own = t;
            next.set(chunks); // no thread claims another chunk of this step
        }
        // always wait for the pool threads, also after a failure: a step they still run would
        // otherwise overlap the next one (its counters reset under them) and park the owner for ever
        drain();
        if (own != null) {
            failure = null; // the owner's own exception goes out as it is
            if (own instanceof RuntimeException r) {
                throw r;
            }
            throw (Error) own;
        }
        Throwable f = failure;
        if (f != null) {
            failure = null;
            throw new IllegalStateException("an animation worker failed: " + f, f);
        }
    }

    private void drain() {
        int spins = 0;
        long spinUntil = 0;
        while (pending.get() != 0) {
            if (stopped) {
                // closed during the step: every chunk was claimed (the loop above ran the rest), and a
                // pool thread only ends after finishing the chunk it holds, so joining them finishes the step
                joinThreads();
                break;
            }
            if (spins < SPINS) {
                spins++;
                Thread.onSpinWait();
            } else if (spinUntil == 0) {
                spinUntil = System.nanoTime() + DRAIN_SPIN_NANOS;
            } else if (System.nanoTime() - spinUntil < 0) {
                Thread.onSpinWait();
            } else {
                ownerParked = true;
                if (pending.get() != 0) { // read after the flag: the last worker sees the flag, or we see 0
                    LockSupport.park(this);
                }
                ownerParked = false;
            }
        }
    }

    /** Runs unclaimed chunks until none is left, recording when this thread's first started and last ended. */
    private void runChunks(int worker) {
        int c = next.getAndIncrement();
        if (c >= chunks) {
            return;
        }
        firstChunk.accumulateAndGet(System.nanoTime(), Math::min);
        for (; c < chunks; c = next.getAndIncrement()) {
            task.runChunk(c, worker);
        }
        lastChunk.accumulateAndGet(System.nanoTime(), Math::max);
    }

    /**
     * The animation's own time in the step that {@link #await()} finished: from the start of its
     * first chunk to the end of its last, on whichever threads ran them, nanoseconds (0 when no chunk
     * ran). With one thread it excludes the owner's work before {@link #await()} (the force field);
     * with several it is the animation's wall time beside it. Owner thread, after await; no allocation.
     */
    long animationNanos() {
        long first = firstChunk.get();
        long last = lastChunk.get();
        return last >= first ? last - first : 0;
    }

    private void loop(int worker) {
        int seen = 0;
        boolean follow = false;
        long expected = 0;
        while (true) {
            boolean spinning = awaitNext(seen, follow, expected);
            while (generation == seen && !stopped) {
                spinning = false;
                LockSupport.park(this);
            }
            if (generation == seen) {
                return; // stopped, and no step is waiting for this thread
            }
            seen = generation;
            (spinning ? awake : unparked).incrementAndGet();
            // what the owner said of this step, read before it can start the next one
            follow = followed;
            long interval = cadence;
            expected = interval == 0 ? 0 : burstStart + interval;
            if (!stopped) {
                try {
                    runChunks(worker);
                } catch (Throwable t) {
                    failure = t;
                    next.set(chunks);
                }
            }
            // always signalled, also when stopped: the owner's await() runs the chunks left itself
            if (pending.decrementAndGet() == 0 && ownerParked) {
                LockSupport.unpark(owner);
            }
        }
    }

    /**
     * A pool thread's wait after step {@code seen}: spins for the step the owner said follows
     * ({@code follow}), or sleeps until shortly before the next burst is due ({@code expected},
     * System.nanoTime(); 0: no cadence) and spins over it; returns when the next step came, the pool
     * stopped or the window passed (the caller then parks until unparked). No allocation.
     *
     * @return whether the thread was awake, spinning, until it returned
     */
    private boolean awaitNext(int seen, boolean follow, long expected) {
        if (seen == 0) {
            return false; // no step yet
        }
        long now = System.nanoTime();
        if (follow) {
            long until = now + followCap;
            while (generation == seen && !stopped && now - until < 0) {
                Thread.onSpinWait();
                now = System.nanoTime();
            }
            return true;
        }
        if (expected == 0) {
            return false;
        }
        long wake = expected - LEAD_NANOS;
        while (generation == seen && !stopped && wake - now > 0) {
            LockSupport.parkNanos(this, wake - now); // returns early on the owner's unpark
            now = System.nanoTime();
        }
        if (generation != seen) {
            return false; // the step came before the window: the owner's unpark woke the thread
        }
        long until = expected + LEAD_NANOS;
        while (generation == seen && !stopped && now - until < 0) {
            Thread.onSpinWait();
            now = System.nanoTime();
        }
        return true;
    }

    /**
     * Stops and joins the workers; idempotent; any thread. A step in progress still completes: the
     * workers finish the chunks they hold and the owner's {@link #await()} runs the rest, so it
     * returns instead of waiting for threads that are gone.
     */
    @Override
    public void close() {
        if (stopped) {
            return;
        }
        stopped = true;
        for (Thread t : threads) {
            LockSupport.unpark(t);
        }
        Thread o = owner;
        if (o != null) {
            LockSupport.unpark(o);
        }
        joinThreads();
    }

    private void joinThreads() {
        boolean interrupted = false;
        for (Thread t : threads) {
            while (t.isAlive()) {
                try {
                    t.join();
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }
}
