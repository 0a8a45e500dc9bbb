package org.jecosys.render;

import org.jecosys.render.gl.SoftwareGl;

/**
 * {@link SceneRenderer}'s GPU pass timing ({@link SceneRenderer#setPassTiming}): the timer queries of
 * a {@link GpuPassTimer} while it is on, the mark at the start of each pass, and the timer's renewal in
 * a new context (the old queries died with the old one: forgotten, not deleted). Render thread; turning
 * it on allocates the queries, a timed frame allocates nothing.
 */
final class PassTiming implements AutoCloseable {
    private final GlContext gl;
    /** The timer queries; null while off. */
    private GpuPassTimer timer;

    PassTiming(GlContext gl) {
        this.gl = gl;
    }

    /** Turns timing on (making the queries, on a software rasteriser the clock) or off (deleting them). */
    void set(boolean on) {
        if (on && timer == null) {
            timer = new GpuPassTimer(SoftwareGl.is(gl.describe()));
        } else if (!on && timer != null) {
            timer.close();
            timer = null;
        }
    }

    /** {@return whether the passes are timed} */
    boolean on() {
        return timer != null;
    }

    /** {@return the passes' GPU times so far, or null while timing is off} */
    PassTimes times() {
        return timer == null ? null : timer.times();
    }

    /** Starts a timed frame; timing is on. */
    void begin() {
        timer.begin();
    }

    /** Ends a timed frame; timing is on. */
    void end() {
        timer.end();
    }

    /** Starts timing {@code pass} when timing is on. */
    void mark(PassTimes.Pass pass) {
        if (timer != null) {
            timer.next(pass);
        }
    }

    /**
     * The context is gone: forgets the timer without a GL call.
     *
     * @return whether timing was on
     */
    boolean forget() {
        boolean timed = timer != null;
        timer = null;
        return timed;
    }

    /** Deletes the queries (timing is off after). */
    @Override
    public void close() {
        if (timer != null) {
            timer.close();
        }
        timer = null;
    }
}
