package org.jecosys.sim;

import java.util.concurrent.atomic.AtomicInteger;

/**
 * Triple buffering of {@link Frame}s between one writer (the simulation) and one reader (the
 * renderer, or a game thread). The writer fills its back frame and {@link #publish()}es it; the
 * reader's {@link #latest()} takes the newest published frame if there is one. Neither ever waits
 * or sees a frame being written; frame numbers seen by the reader never go back. One packed atomic
 * integer holds which buffer is "ready" and whether it is new, so exchanging is lock-free (see
 * docs/ARCHITECTURE.md, "Threads"). No allocation after construction.
 */
public final class FrameExchange {
    private static final int FRESH = 4;
    private final Frame[] frames = new Frame[3];
    /** The ready buffer's index (bits 0-1) and the FRESH flag (bit 2). */
    private final AtomicInteger ready = new AtomicInteger(1);
    private int back;
    private int front = 2;
    /** The buffer the writer published last (initially the ready one): it keeps its content until the next publish. */
    private int published = 1;

    /**
     * Three empty frames sized for a world. Allocates.
     *
     * @param plants     plants of the world, &gt;= 0
     * @param components components of all plants, &gt;= 0
     */
    public FrameExchange(int plants, int components) {
        for (int i = 0; i < 3; i++) {
            frames[i] = new Frame(plants, components);
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

    /**
     * The frame the writer published last (before the first publish: the initial ready frame). The
     * reader may hold it but never writes it, and the writer gets it back only at the next
     * {@link #publish}, so the writer may read it while filling {@link #back()}. Writer thread only.
     */
    Frame lastPublished() {
        return frames[published];
    }

    /** Index (0-2) of {@link #back()}, for bookkeeping per buffer. Writer thread only. */
    int backIndex() {
        return back;
    }

    /** Publishes the back frame and gives the writer another to fill. Writer thread only. */
    public void publish() {
        published = back;
        int old = ready.getAndSet(back | FRESH);
        back = old & 3;
    }

    /**
     * The newest complete frame: a newly published one if any, else the one this reader already
     * had. It stays unchanged until this reader calls again. Reader thread only.
     *
     * @return the newest complete frame (number 0 before the first publish)
     */
    public Frame latest() {
        if ((ready.get() & FRESH) != 0) {
            int old = ready.getAndSet(front);
            front = old & 3;
        }
        return frames[front];
    }
}
