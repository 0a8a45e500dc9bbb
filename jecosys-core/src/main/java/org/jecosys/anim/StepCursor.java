package org.jecosys.anim;

/**
 * The bookkeeping of one {@link AnimationState#animate(int, int, AnimationStep)} call, kept in its
 * {@link AnimationStep} so that the call allocates nothing (see "Update order" in
 * {@link AnimationState}). It holds two pending batches, both in component order:
 * <ul>
 * <li>the <em>spring segment</em>: runs {@code segRun .. segRunEnd - 1}, contiguous and of one
 * spring class, advanced together ({@link AnimationState#spring}) when the next queued run does not
 * continue it, before outputs are computed, and at the end;</li>
 * <li>the <em>output range</em>: the components {@code [outStart, outEnd)} whose outputs are
 * computed together; ranges closer than {@link #MERGE_GAP} components are merged (recomputing the
 * gap is idempotent), farther ones written separately.</li>
 * </ul>
 * Plants below {@code done} have up-to-date outputs. One call at a time; no allocation.
 */
final class StepCursor {
    /** Output ranges closer than this many components are merged (recomputing the gap is idempotent). */
    static final int MERGE_GAP = 256;

    private int segRun; // pending spring segment, or segRun < 0 for none
    private int segRunEnd;
    private int segClass;
    private int outStart; // pending output range [outStart, outEnd) of components, or outStart < 0 for none
    private int outEnd;
    private int outStartPlant; // the plant whose first component is outStart
    private int done; // outputs up to date below this plant

    /** Starts a call over the plants from {@code first}: nothing pending, no output written. */
    void begin(int first) {
        segRun = -1;
        segRunEnd = -1;
        segClass = -1;
        outStart = -1;
        outEnd = -1;
        outStartPlant = -1;
        done = first;
    }

    /**
     * Queues spring run {@code r} of coefficient row {@code cls} ({@link SpringKinds#row}): it extends
     * the pending segment if it continues it (same row, next component), otherwise the pending segment
     * is advanced and r starts a new one.
     *
     * @param runStart per run its first component (length runs + 1)
     */
    void queueRun(AnimationState state, int r, int cls, int[] runStart) {
        if (segRun >= 0 && cls == segClass && runStart[r] == runStart[segRunEnd]) {
            segRunEnd = r + 1;
        } else {
            advanceSegment(state);
            segRun = r;
            segRunEnd = r + 1;
            segClass = cls;
        }
    }

    /** Advances the pending spring segment, if any, and leaves none pending. */
    void advanceSegment(AnimationState state) {
        if (segRun >= 0) {
            state.spring(segRun, segRunEnd, segClass);
            segRun = -1;
        }
    }

    /**
     * Adds the components {@code [c0, c1)} of plant {@code p} (after those queued so far) to the
     * pending output range. If they start more than {@link #MERGE_GAP} components after it, the
     * pending range is written first (after advancing the pending segment: the outputs read D) and
     * p starts a new one.
     */
    void queueOutputs(AnimationState state, AnimationStep step, int p, int c0, int c1) {
        if (outStart < 0) {
            outStart = c0;
            outStartPlant = p;
        } else if (c0 - outEnd > MERGE_GAP) {
            advanceSegment(state);
            done = state.writeOutputs(done, outStartPlant, outEnd, step);
            outStart = c0;
            outStartPlant = p;
        }
        outEnd = c1;
    }

    /**
     * Ends the call's outputs: writes the pending output range, then brings the stale outputs of the
     * plants after it, up to {@code end}, up to date from before. The pending segment must have
     * been advanced.
     */
    void finishOutputs(AnimationState state, AnimationStep step, int end) {
        if (outStart >= 0) {
            done = state.writeOutputs(done, outStartPlant, outEnd, step);
        }
        state.copyStale(done, end, step);
    }
}
