package org.jecosys.anim;

/**
 * The bookkeeping of one {@link AnimationState#animate(int, int, AnimationStep)} call, kept in its
 * {@link AnimationStep} so that the call allocates nothing (see "Update order" in
 * {@link AnimationState}): the pending <em>output range</em>, the components {@code [outStart,
 * outEnd)} whose outputs are computed together; ranges closer than {@link #MERGE_GAP} components are
 * merged (recomputing the gap is idempotent), farther ones written separately. Plants below
 * {@code done} have up-to-date outputs. One call at a time; no allocation.
 */
final class StepCursor {
    /** Output ranges closer than this many components are merged (recomputing the gap is idempotent). */
    static final int MERGE_GAP = 256;

    private int outStart; // pending output range [outStart, outEnd) of components, or outStart < 0 for none
    private int outEnd;
    private int outStartPlant; // the plant whose first component is outStart
    private int done; // outputs up to date below this plant

    /** Starts a call over the plants from {@code first}: nothing pending, no output written. */
    void begin(int first) {
        outStart = -1;
        outEnd = -1;
        outStartPlant = -1;
        done = first;
    }

    /**
     * Adds the components {@code [c0, c1)} of plant {@code p} (after those queued so far) to the
     * pending output range. If they start more than {@link #MERGE_GAP} components after it, the
     * pending range is written first and p starts a new one.
     */
    void queueOutputs(AnimationState state, AnimationStep step, int p, int c0, int c1) {
        if (outStart < 0) {
            outStart = c0;
            outStartPlant = p;
        } else if (c0 - outEnd > MERGE_GAP) {
            done = state.writeOutputs(done, outStartPlant, outEnd, step);
            outStart = c0;
            outStartPlant = p;
        }
        outEnd = c1;
    }

    /**
     * Ends the call's outputs: writes the pending output range, then brings the stale outputs of the
     * plants after it, up to {@code end}, up to date from before.
     */
    void finishOutputs(AnimationState state, AnimationStep step, int end) {
        if (outStart >= 0) {
            done = state.writeOutputs(done, outStartPlant, outEnd, step);
        }
        state.copyStale(done, end, step);
    }
}
