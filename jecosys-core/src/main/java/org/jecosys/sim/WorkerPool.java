package org.jecosys.sim;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicIntegerArray;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;
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
 * <p>Waking without moving: a thread woken by another may be placed on the waker's core, and one
 * that wakes by its own timer wakes on the core it slept on; on a virtual machine whose idle cores are
 * halted the scheduler kept a woken thread on the waker's core even with the other core idle (a C
 * program of two threads: 295 times in 300), and the two then shared one core, the step running as on
 * one, until the balancer moved one of them several milliseconds later. So the owner and the pool
 * threads wake one another as little as they can:
 * <ul>
 *   <li>the owner says at each {@link #start(boolean)} whether another step follows at once (its loop of
 *       fixed steps): then the pool threads spin for it (at most {@link #FOLLOW_CAP_NANOS});</li>
 *   <li>after a burst they sleep by their own timer until {@link #LEAD_NANOS} before the window in which
 *       the owner's rhythm ({@link Bursts}) expects the next burst, spin until as long after it, and then
 *       still look every {@link #POLL_SLICE_NANOS} for {@link #POLL_SPAN_NANOS} (a late frame);</li>
 *   <li>each thread says by when it will look at the generation by itself ({@link #comesBy}); the owner
 *       unparks only a thread that would come later than {@link #GRACE_NANOS} (parked: no rhythm, or
 *       a burst far outside its window);</li>
 *   <li>once every chunk of a step is claimed, the owner closes the step to the pool threads that have
 *       not entered it yet ({@link #ticket}): a thread that comes late does not hold the step;</li>
 *   <li>the owner waits for the pool's last chunks spinning, then in short timed sleeps: the pool never
 *       unparks it.</li>
 * </ul>
 * The spinning costs at most the window plus twice the lead per burst of one thread's time, none while
 * no step is coming.
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
    /** How long the owner spins for the pool's last chunks before it sleeps in short slices, nanoseconds. */
    private static final long DRAIN_SPIN_NANOS = 1_000_000;
    /** The owner's sleep slice while it waits for the pool's last chunks, nanoseconds. */
    private static final long DRAIN_SLICE_NANOS = 100_000;
    /** A pool thread's sleep slice while a late burst may still come, nanoseconds. */
    static final long POLL_SLICE_NANOS = 200_000;
    /** How long after its window a pool thread still polls for a late burst, nanoseconds. */
    static final long POLL_SPAN_NANOS = 4_000_000;
    /**
     * The owner does not unpark a pool thread that looks at the step by itself within this, nanoseconds:
     * a thread it wakes may be moved onto the owner's core, which costs more than coming this late.
     */
    static final long GRACE_NANOS = 2_000_000;
    /** {@link #comesBy}: the thread is parked until unparked. */
    private static final long PARKED = Long.MAX_VALUE;
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
    /** How long after its window a pool thread polls for a late burst, nanoseconds. */
    private final long pollSpan;
    private final int chunks;
    private final AtomicInteger next = new AtomicInteger();
    private final AtomicInteger pending = new AtomicInteger();
    /** System.nanoTime() at which the step's first chunk started and its last chunk ended, any thread. */
    private final AtomicLong firstChunk = new AtomicLong();
    private final AtomicLong lastChunk = new AtomicLong();
    /** Steps the pool threads saw, summed over threads. */
    private final AtomicLong seenSteps = new AtomicLong();
    /** How often the owner unparked a pool thread for a step; owner writes, any thread reads. */
    private volatile long unparks;
    /** How often the owner closed a step to a pool thread that had not entered it; owner writes. */
    private volatile long closedOut;
    private volatile int generation;
    /** Whether the owner said another step follows the current one; written before the generation. */
    private volatile boolean followed;
    /** Earliest the next burst is expected (System.nanoTime()); 0: no rhythm. Written before the generation. */
    private volatile long windowOpen;
    /** Latest the next burst is expected; written before the generation. */
    private volatile long windowClose;
    /**
     * Per pool thread: System.nanoTime() by which it looks at the generation by itself (spinning: a
     * time already past), or {@link #PARKED}. The owner unparks only threads that would come later
     * than {@link #GRACE_NANOS}.
     */
    private final AtomicLongArray comesBy;
    /**
     * Per pool thread: the last generation settled for it, entered by the thread or closed to it by the
     * owner once every chunk of that step was claimed (a thread that comes late then does not hold the
     * step: it has nothing left to run). Whoever sets it first, by compare-and-set, decides.
     */
    private final AtomicIntegerArray ticket;
    /** The owner's bursts of steps; owner only. */
    private final Bursts bursts = new Bursts();
    private volatile boolean stopped;
    private volatile Thread owner;
    private volatile Throwable failure;

    WorkerPool(String name, int workers, int chunks, ChunkTask task) {
        this(name, workers, chunks, task, FOLLOW_CAP_NANOS, POLL_SPAN_NANOS);
    }

    /**
     * As {@link #WorkerPool(String, int, int, ChunkTask)}, the pool's threads spinning at most
     * {@code followCap} ns for a step the owner said follows and polling {@code pollSpan} ns for a late
     * burst (tests: spans no machine's load reaches).
     */
    WorkerPool(String name, int workers, int chunks, ChunkTask task, long followCap, long pollSpan) {
        if (followCap < 0 || pollSpan < 0) {
            throw new IllegalArgumentException("followCap and pollSpan must be at least 0 ns, got " + followCap
                    + " and " + pollSpan);
        }
        this.followCap = followCap;
        this.pollSpan = pollSpan;
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
        comesBy = new AtomicLongArray(threads.length);
        ticket = new AtomicIntegerArray(threads.length);
        for (int i = 0; i < threads.length; i++) {
            comesBy.set(i, PARKED);
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
     * {@return how often a pool thread came to a step by itself, not unparked for it} Summed over the
     * pool's threads since they started: steps the owner said would follow, and steps of a steady
     * cadence that came inside the anticipated window. Any thread; no allocation.
     */
    long awakeSteps() {
        return seenSteps.get() - unparks;
    }

    /** {@return how often a pool thread had to be woken by the owner for a step, summed over threads} Any thread. */
    long unparkedSteps() {
        return unparks;
    }

    /**
     * {@return how often a pool thread came to a step after every chunk was claimed, and the owner went
     * on without it} Summed over threads; any thread.
     */
    long closedOutSteps() {
        return closedOut;
    }

    /** {@return whether the pool's threads anticipate the next burst (the owner keeps a rhythm)} Any thread. */
    boolean anticipating() {
        return windowOpen != 0;
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
        long now = System.nanoTime();
        if (bursts.step(followed, now)) { // the first step of a burst: the owner's rhythm
            windowOpen = bursts.earliestNext();
            windowClose = bursts.latestNext();
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
        // read after the generation's write: a thread that set itself PARKED afterwards sees the step;
        // the time read after the thread's word, as the owner may have been descheduled (or stopped for a
        // collection) meanwhile while the thread wrote a later time of its own
        for (int i = 0; i < threads.length; i++) {
            long c = comesBy.get(i);
            if (c == PARKED || c - System.nanoTime() > GRACE_NANOS) {
                unparks++;
                LockSupport.unpark(threads[i]);
            }
        }
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
        // every chunk is claimed now: a thread that has not entered the step yet has nothing to do in it
        closeToLate();
        // always wait for the pool threads that entered, also after a failure: a step they still run
        // would otherwise overlap the next one (its counters reset under them)
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

    /** Settles the step for every pool thread that has not entered it; they no longer count as pending. */
    private void closeToLate() {
        if (chunks <= 1 || threads.length == 0) {
            return; // the pool threads were not called for this step
        }
        int g = generation;
        for (int i = 0; i < threads.length; i++) {
            int cur = ticket.get(i);
            if (cur - g < 0 && ticket.compareAndSet(i, cur, g)) {
                closedOut++;
                pending.decrementAndGet();
            }
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
                // short timed sleeps, not a park the last worker would end: a thread woken by another
                // may be moved onto the waker's core, and the owner would then share the pool's next step
                LockSupport.parkNanos(this, DRAIN_SLICE_NANOS);
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
        long open = 0;
        long close = 0;
        while (true) {
            awaitNext(worker, seen, follow, open, close);
            if (generation == seen) {
                comesBy.set(worker, PARKED);
                while (generation == seen && !stopped) { // read after PARKED: the owner unparks, or we see it
                    LockSupport.park(this);
                }
            }
            // busy with this step until it looks at the next one: no unpark needed meanwhile
            comesBy.set(worker, System.nanoTime());
            if (generation == seen) {
                return; // stopped, and no step is waiting for this thread
            }
            int g = generation;
            seen = g;
            seenSteps.incrementAndGet();
            // what the owner said of this step (if it already started the next, of that one: then this
            // thread was closed out of this step and enters the next at once)
            follow = followed;
            open = windowOpen;
            close = windowClose;
            if (!enter(worker, g)) {
                continue; // came after every chunk was claimed: the owner did not wait for it
            }
            if (!stopped) {
                try {
                    runChunks(worker);
                } catch (Throwable t) {
                    failure = t;
                    next.set(chunks);
                }
            }
            // always signalled, also when stopped: the owner's await() runs the chunks left itself
            pending.decrementAndGet(); // the owner looks by itself (drain): no unpark to move it here
        }
    }

    /** Whether pool thread {@code worker} enters step {@code g}: false when the owner closed it out first. */
    private boolean enter(int worker, int g) {
        while (true) {
            int cur = ticket.get(worker);
            if (cur - g >= 0) {
                return false;
            }
            if (ticket.compareAndSet(worker, cur, g)) {
                return true;
            }
        }
    }

    /**
     * A pool thread's wait after step {@code seen}: spins for the step the owner said follows
     * ({@code follow}), or sleeps until {@link #LEAD_NANOS} before the window {@code open .. close} in
     * which the next burst is expected (System.nanoTime(); 0: no rhythm) and spins until as long after
     * it; then it still looks every {@link #POLL_SLICE_NANOS} for {@link #POLL_SPAN_NANOS} (a late
     * burst). Returns when the next step came, the pool stopped or the time passed (the caller then
     * parks until unparked). It keeps {@link #comesBy} so that the owner need not unpark it. No allocation.
     */
    private void awaitNext(int worker, int seen, boolean follow, long open, long close) {
        if (seen == 0) {
            return; // no step yet
        }
        long now = System.nanoTime();
        long spinUntil;
        if (follow) {
            spinUntil = now + followCap;
        } else if (open != 0) {
            long wake = open - LEAD_NANOS;
            comesBy.set(worker, wake);
            while (generation == seen && !stopped && wake - now > 0) {
                LockSupport.parkNanos(this, wake - now); // returns early on the owner's unpark
                now = System.nanoTime();
            }
            if (generation != seen) {
                return; // the step came before the window
            }
            spinUntil = close + LEAD_NANOS;
        } else {
            return;
        }
        comesBy.set(worker, now);
        while (generation == seen && !stopped && now - spinUntil < 0) {
            Thread.onSpinWait();
            now = System.nanoTime();
        }
        if (generation != seen || stopped) {
            return;
        }
        long pollUntil = now + pollSpan;
        while (generation == seen && !stopped && now - pollUntil < 0) {
            comesBy.set(worker, now + POLL_SLICE_NANOS);
            LockSupport.parkNanos(this, POLL_SLICE_NANOS);
            now = System.nanoTime();
        }
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
