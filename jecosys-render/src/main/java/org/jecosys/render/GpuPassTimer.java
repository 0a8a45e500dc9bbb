package org.jecosys.render;

import static org.lwjgl.opengl.GL15C.GL_QUERY_RESULT;
import static org.lwjgl.opengl.GL15C.GL_QUERY_RESULT_AVAILABLE;
import static org.lwjgl.opengl.GL15C.glBeginQuery;
import static org.lwjgl.opengl.GL15C.glDeleteQueries;
import static org.lwjgl.opengl.GL15C.glEndQuery;
import static org.lwjgl.opengl.GL15C.glGenQueries;
import static org.lwjgl.opengl.GL33C.GL_TIME_ELAPSED;
import static org.lwjgl.opengl.GL11C.glFlush;
import static org.lwjgl.opengl.GL33C.glGetQueryObjectui64v;

/**
 * The timer queries behind {@link PassTimes}: a ring of {@link #SLOTS} frames' queries, one
 * {@code GL_TIME_ELAPSED} query per pass (begun when the pass starts, ended when the next starts: the
 * passes tile the frame) or, every {@link #WHOLE_EVERY}th timed frame, one around the whole frame. A
 * slot's results are read when the ring comes back to it, {@link #SLOTS} - 1 frames later, and only if
 * the GL reports them available; otherwise that frame is dropped, never waited for. A timed frame is
 * submitted pass by pass ({@code glFlush} between passes, which waits for nothing), in both kinds of
 * frames alike, so that a tiling rasteriser times each pass on its own. Render thread; the
 * constructor allocates the query names; a frame allocates nothing.
 */
final class GpuPassTimer implements AutoCloseable {
    /** Frames in flight before a slot's queries are read. */
    static final int SLOTS = 4;
    /** Every this many timed frames one is measured whole. */
    static final int WHOLE_EVERY = 4;

    private final int passes = PassTimes.PASSES.length;
    /** Per slot: a query per pass, then the whole frame's. */
    private final int[][] queries = new int[SLOTS][];
    /** Per slot: which passes it began (their queries hold results), and whether it timed the whole frame. */
    private final boolean[][] used = new boolean[SLOTS][];
    private final boolean[] whole = new boolean[SLOTS];
    private final boolean[] pending = new boolean[SLOTS];
    private final long[] scratch;
    /** The answer of {@link #query}: LWJGL's returning form wraps its stack word in a new buffer (56 bytes). */
    private final long[] answer = new long[1];
    private final PassTimes times = new PassTimes();
    private long frame;
    private int slot = -1;
    private int open = -1;
    private boolean closed;
    /** Timed by the clock around {@code glFinish} instead of timer queries (a software rasteriser). */
    private final boolean wall;
    private long wallStart;
    private long frameStart;

    /**
     * Timer queries (a GPU), or the clock around {@code glFinish} at each pass's end ({@code wall}: a
     * software rasteriser, whose timer queries do not time passes: llvmpipe counts only its rasteriser
     * threads' time inside the bins a query spans, so a vertex-only pass reads 0 and a frame submitted in
     * passes reads several times its length). Wall timing waits for each pass: a diagnostic for the bench
     * and tests on software GL, where the "GPU" is the CPU and the wait is the work.
     */
    GpuPassTimer(boolean wall) {
        this.wall = wall;
        scratch = new long[passes];
        for (int s = 0; s < SLOTS; s++) {
            queries[s] = new int[passes + 1];
            if (!wall) { // the clock needs no query
                glGenQueries(queries[s]);
            }
            used[s] = new boolean[passes];
        }
    }

    /** The measurements read so far. */
    PassTimes times() {
        return times;
    }

    /** Starts a frame: reads the slot's last results if ready, then times this frame in it. */
    void begin() {
        if (wall) {
            slot = 0;
            whole[0] = frame % WHOLE_EVERY == WHOLE_EVERY - 1;
            java.util.Arrays.fill(scratch, 0);
            frame++;
            org.lwjgl.opengl.GL11C.glFinish();
            frameStart = System.nanoTime();
            wallStart = frameStart;
            open = -1;
            return;
        }
        slot = (int) (frame % SLOTS);
        collect(slot);
        whole[slot] = frame % WHOLE_EVERY == WHOLE_EVERY - 1;
        java.util.Arrays.fill(used[slot], false);
        frame++;
        if (whole[slot]) {
            glBeginQuery(GL_TIME_ELAPSED, queries[slot][passes]);
        }
        open = -1;
        pending[slot] = true;
    }

    /** Ends the pass under way (if any) and starts timing {@code pass}. */
    void next(PassTimes.Pass pass) {
        if (slot < 0) {
            return;
        }
        if (wall) {
            if (whole[0]) {
                return; // the frame as it runs, timed whole
            }
            org.lwjgl.opengl.GL11C.glFinish();
            long now = System.nanoTime();
            if (open >= 0) {
                scratch[open] += now - wallStart;
            }
            wallStart = now;
            open = pass.ordinal();
            return;
        }
        if (whole[slot]) {
            glFlush(); // the same submission as a frame timed by pass
            return;
        }
        if (open >= 0) {
            glEndQuery(GL_TIME_ELAPSED);
            // submitted pass by pass: a tiling rasteriser (llvmpipe) otherwise runs the whole frame at its
            // end, and every query overlapping it reads the whole frame's time
            glFlush();
        }
        open = pass.ordinal();
        used[slot][open] = true;
        glBeginQuery(GL_TIME_ELAPSED, queries[slot][open]);
    }

    /** Ends the frame's last query. */
    void end() {
        if (slot < 0) {
            return;
        }
        if (wall) {
            org.lwjgl.opengl.GL11C.glFinish();
            long now = System.nanoTime();
            if (whole[0]) {
                times.whole(now - frameStart);
            } else {
                if (open >= 0) {
                    scratch[open] += now - wallStart;
                }
                times.passes(scratch);
            }
            open = -1;
            slot = -1;
            return;
        }
        if (whole[slot] || open >= 0) {
            glEndQuery(GL_TIME_ELAPSED);
        }
        open = -1;
        slot = -1;
    }

    /** Reads slot {@code s}'s results when every one is available; drops the frame otherwise. */
    private void collect(int s) {
        if (!pending[s]) {
            return;
        }
        pending[s] = false;
        if (whole[s]) {
            int q = queries[s][passes];
            if (query(q, GL_QUERY_RESULT_AVAILABLE) == 0) {
                times.drop();
                return;
            }
            times.whole(query(q, GL_QUERY_RESULT));
            return;
        }
        for (int p = 0; p < passes; p++) {
            if (used[s][p] && query(queries[s][p], GL_QUERY_RESULT_AVAILABLE) == 0) {
                times.drop();
                return;
            }
        }
        for (int p = 0; p < passes; p++) {
            scratch[p] = used[s][p] ? query(queries[s][p], GL_QUERY_RESULT) : 0;
        }
        times.passes(scratch);
    }

    private long query(int id, int pname) {
        glGetQueryObjectui64v(id, pname, answer);
        return answer[0];
    }

    /** Deletes the queries. Render thread; idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            for (int[] q : wall ? new int[0][] : queries) {
                glDeleteQueries(q);
            }
        }
    }
}
