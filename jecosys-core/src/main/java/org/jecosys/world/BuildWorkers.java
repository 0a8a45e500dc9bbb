package org.jecosys.world;

import java.util.concurrent.Callable;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Future;
import java.util.concurrent.FutureTask;
import java.util.concurrent.atomic.AtomicIntegerArray;
import java.util.concurrent.locks.LockSupport;

/**
 * The tile workers of a {@link TileStreamer}: daemon threads that run the builds it hands in, in the
 * order handed in. Unlike a JDK thread pool, the stepping thread and the workers share no lock: the
 * queue is lock-free, and a hand-in unparks a worker only if one is parked. With a pool's locked queue
 * the stepping thread could block on the lock a worker held and be woken by it; a thread woken by
 * another may be placed on the waker's core, so the stepping thread then moved onto the tile worker's
 * core and shared the next step's cores with it (a step then runs as on one core). Hand-in: any
 * thread; allocates the task. Package-private: the streamer's only.
 */
final class BuildWorkers {
    private final ConcurrentLinkedQueue<FutureTask<?>> queue = new ConcurrentLinkedQueue<>();
    private final Thread[] threads;
    /** Per worker: 1 while it is parked until unparked (a hand-in must wake it), else 0. */
    private final AtomicIntegerArray parked;
    private volatile boolean stopped;

    /**
     * Starts {@code count} daemon threads named {@code name}.
     *
     * @param name  the threads' name
     * @param count how many, at least 1
     */
    BuildWorkers(String name, int count) {
        threads = new Thread[count];
        parked = new AtomicIntegerArray(count);
        for (int i = 0; i < count; i++) {
            int w = i;
            Thread t = new Thread(() -> loop(w), name);
            t.setDaemon(true);
            threads[i] = t;
        }
        for (Thread t : threads) {
            t.start();
        }
    }

    /**
     * Hands in a build; an idle worker starts it at once. Any thread; allocates the task.
     *
     * @throws IllegalStateException after {@link #shutdownNow()}
     */
    <T> Future<T> submit(Callable<T> build) {
        if (stopped) {
            throw new IllegalStateException("the tile workers are stopped");
        }
        FutureTask<T> task = new FutureTask<>(build);
        queue.add(task);
        // read after the add: a worker that set its flag afterwards sees the task before it parks
        for (int i = 0; i < threads.length; i++) {
            if (parked.compareAndSet(i, 1, 0)) { // one worker per task, each woken once
                LockSupport.unpark(threads[i]);
                break;
            }
        }
        return task;
    }

    /** Stops the workers: a build running finishes, the builds not started are cancelled. Idempotent. */
    void shutdownNow() {
        stopped = true;
        for (Thread t : threads) {
            t.interrupt();
            LockSupport.unpark(t);
        }
        cancelQueued();
    }

    /** Cancels the builds handed in and not started (a stop). */
    private void cancelQueued() {
        for (FutureTask<?> f = queue.poll(); f != null; f = queue.poll()) {
            f.cancel(false);
        }
    }

    private void loop(int w) {
        while (!stopped) {
            FutureTask<?> task = queue.poll();
            if (task != null) {
                task.run();
                continue;
            }
            parked.set(w, 1);
            if (queue.isEmpty() && !stopped) { // read after the flag: a hand-in sees it, or we see the task
                LockSupport.park(this);
            }
            parked.set(w, 0);
        }
        cancelQueued(); // a hand-in that raced the stop
    }
}
