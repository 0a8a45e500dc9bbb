package org.jecosys.sim;

import java.lang.invoke.VarHandle;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Triple buffering of {@link Frame}s between one writer (the simulation) and one reader (the
 * renderer, or a game thread). The writer fills its back frame and {@link #publish()}es it; the
 * reader's {@link #latest()} takes the newest published frame if there is one. Neither ever waits
 * or sees a frame being written; frame numbers seen by the reader never go back. One packed atomic
 * integer holds which buffer is "ready" and whether it is new, so exchanging is lock-free (see
 * docs/ARCHITECTURE.md, "Threads"). No allocation after construction.
 *
 * <p>The reader is one thread: the first that calls {@link #latest()}; another thread calling it
 * while that one is alive gets an {@link IllegalStateException} (triple buffering cannot keep a
 * frame unchanged for two readers). Any number of other threads may take copies with
 * {@link #copyLatest(Frame)}: each buffer carries a write sequence (odd while the writer fills it),
 * and a copy whose buffer was written meanwhile is taken again, so a copy is never torn either.
 */
public final class FrameExchange {
    private static final int FRESH = 4;
    private final Frame[] frames = new Frame[3];
    /** The ready buffer's index (bits 0-1) and the FRESH flag (bit 2). */
    private final AtomicInteger ready = new AtomicInteger(1);
    private int back;
    private int front = 2;
    /** The newest published buffer, for copies by any thread. */
    private volatile int newest = 1;
    /** Per buffer, its write sequence: odd while the writer fills it. */
    private final AtomicLongArray writes = new AtomicLongArray(3);
    /** The thread {@link #latest()} serves, or null before its first call. */
    private final AtomicReference<Thread> reader = new AtomicReference<>();

    /**
     * Three empty frames sized for a world. Allocates.
     *
     * @param plants   plants of the world, &gt;= 0
     * @param geometry the bend geometry of its components ({@link Frame#Frame(int, org.jecosys.anim.BendGeometry)})
     */
    public FrameExchange(int plants, org.jecosys.anim.BendGeometry geometry) {
        for (int i = 0; i < 3; i++) {
            frames[i] = new Frame(plants, geometry);
        }
    }

    /** Frame i of the three (0-2), for initialising all of them before the first publish. Writer thread, before any reader. */
    Frame frame(int i) {
        return frames[i];
    }

    /** {@return the writer's frame to fill} Writer thread only. */
    public Frame back() {
        return frames[back];
    }

    /** Index (0-2) of {@link #back()}, for bookkeeping per buffer. Writer thread only. */
    int backIndex() {
        return back;
    }

    /**
     * Marks the back frame as being written, before the writer (or its workers) change it, so that
     * {@link #copyLatest} never returns a copy taken meanwhile. Writer thread only; no allocation.
     */
    void beginWrite() {
        if ((writes.get(back) & 1) == 0) {
            writes.incrementAndGet(back);
        }
    }

    /** Publishes the back frame and gives the writer another to fill. Writer thread only. */
    public void publish() {
        if ((writes.get(back) & 1) != 0) {
            writes.incrementAndGet(back);
        }
        newest = back;
        int old = ready.getAndSet(back | FRESH);
        back = old & 3;
    }

    /**
     * The newest complete frame: a newly published one if any, else the one this reader already
     * had. It stays unchanged until this reader calls again. Reader thread only.
     *
     * @return the newest complete frame (number 0 before the first publish)
     * @throws IllegalStateException when another thread, still alive, is the reader (use
     *                               {@link #copyLatest(Frame)} from every thread but one)
     */
    public Frame latest() {
        Thread t = Thread.currentThread();
        if (reader.get() != t) {
            claimReader(t);
        }
        if ((ready.get() & FRESH) != 0) {
            int old = ready.getAndSet(front);
            front = old & 3;
        }
        return frames[front];
    }

    private void claimReader(Thread t) {
        for (Thread owner = reader.get(); owner != t; owner = reader.get()) {
            if (owner != null && owner.isAlive()) {
                throw new IllegalStateException("latestFrame() has one reader thread, '" + owner.getName()
                        + "', and is called from '" + t.getName() + "': a frame it returns stays unchanged only "
                        + "for that one thread; read from other threads with copyLatestFrame(Frame)");
            }
            reader.compareAndSet(owner, t); // the first reader, or the previous one has ended
        }
    }

    /**
     * Copies the newest complete frame into {@code dest}, from any thread and any number of threads
     * at once, concurrently with the writer and the reader of {@link #latest()}: a copy whose buffer
     * the writer started to refill meanwhile is taken again (a copy takes microseconds, a step
     * milliseconds), so the copy is never torn. Never blocks the writer. No allocation.
     *
     * @param dest a frame of the same sizes, owned by the caller
     * @return {@code dest}
     * @throws IllegalArgumentException when {@code dest} is null, has other sizes or is one of this
     *                                  exchange's own frames
     */
    public Frame copyLatest(Frame dest) {
        if (dest == null || dest.componentCount() != frames[0].componentCount()
                || dest.plantCount() != frames[0].plantCount()) {
            throw new IllegalArgumentException("dest must be a frame of " + frames[0].plantCount() + " plants and "
                    + frames[0].componentCount() + " components, got " + (dest == null ? "null"
                    : dest.plantCount() + " plants and " + dest.componentCount() + " components"));
        }
        if (dest == frames[0] || dest == frames[1] || dest == frames[2]) {
            throw new IllegalArgumentException("dest must be the caller's own frame, not one of the exchange's");
        }
        while (true) {
            int i = newest;
            long seq = writes.get(i);
            if ((seq & 1) != 0) {
                Thread.onSpinWait(); // lapped: the writer refills what was the newest; a newer one is coming
                continue;
            }
            dest.copyFrom(frames[i]);
            VarHandle.acquireFence(); // the copy's reads happen before the check below
            if (writes.get(i) == seq) {
                return dest;
            }
        }
    }
}
