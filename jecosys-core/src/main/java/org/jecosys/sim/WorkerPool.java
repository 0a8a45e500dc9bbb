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
    /**
     * The JVM's per-thread allocation counter, looked up once: {@code ManagementFactory.getThreadMXBean()}
     * itself allocates on every call, which would pollute the very measurement. Null when unsupported.
     */
    private static final com.sun.management.ThreadMXBean THREADS = threadBean();

    private final Thread[] threads;
    private final long[] ids;
    private final ChunkTask task;
    private final int chunks;
    private final AtomicInteger next = new AtomicInteger();
    private final AtomicInteger pending = new AtomicInteger();
    /** System.nanoTime() at which the step's first chunk started and its last chunk ended, any thread. */
    private final AtomicLong firstChunk = new AtomicLong();
    private final AtomicLong lastChunk = new AtomicLong();
    private volatile int generation;
    private volatile boolean stopped;
    private volatile Thread owner;
    private volatile Throwable failure;

    WorkerPool(String name, int workers, int chunks, ChunkTask task) {
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

    /** Releases the workers on a new step. Owner thread. No allocation. */
    void start() {
        if (stopped) {
            throw new IllegalStateException("the worker pool is closed");
        }
        owner = Thread.currentThread();
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
            } else {
                LockSupport.park(this);
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
        while (true) {
            int spins = 0;
            while (generation == seen && !stopped) {
                if (spins < SPINS) {
                    spins++;
                    Thread.onSpinWait();
                } else {
                    LockSupport.park(this);
                }
            }
            if (generation == seen) {
                return; // stopped, and no step is waiting for this thread
            }
            seen = generation;
            if (!stopped) {
                try {
                    runChunks(worker);
                } catch (Throwable t) {
                    failure = t;
                    next.set(chunks);
                }
            }
            // always signalled, also when stopped: the owner's await() runs the chunks left itself
            if (pending.decrementAndGet() == 0) {
                LockSupport.unpark(owner);
            }
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
