package org.jecosys.render.gl;


/**
 * Counts the live GL objects created through the {@code Gl*} wrappers of one {@code GlContext}, so a
 * test (or a leak check at shutdown) can prove that closing the renderers released every one.
 *
 * <p>Objects belong to a context generation ({@link #generation()}). When the context they were made
 * in is gone (destroyed, or replaced by the host), {@link #abandon()} starts a new generation: closing
 * an object of an older one then forgets its name without any GL call (the names died with their
 * context, and deleting them in the new one would delete or fail on that context's names), and counts
 * it as {@link #abandoned()}; it still leaves {@link #live()}.
 *
 * <p>Render thread only. No allocation.
 */
public final class GlTracker {
    private int live;
    private long created;
    private long failAt = -1;
    private int generation;
    private long abandoned;

    public GlTracker() {
    }

    public void created() {
        live++;
        created++;
    }

    /**
     * Test hook: the {@code n}-th GL object created from now on (0 = the next) fails as if the driver
     * had refused it, so a test can check that a constructor failing part way releases what it made;
     * negative turns it off.
     */
    public void failAfter(int n) {
        failAt = n < 0 ? -1 : created + n;
    }

    /** Whether the object about to be counted must fail ({@link #failAfter}). */
    public boolean mustFail() {
        if (failAt >= 0 && created == failAt) {
            failAt = -1;
            return true;
        }
        return false;
    }

    public void deleted() {
        live--;
    }

    /** Counts an object of an older generation closed without a GL call ({@link #abandon()}); it also leaves {@link #live()}. */
    public void forgotten() {
        live--;
        abandoned++;
    }

    /**
     * The context the objects were made in is gone: every object made so far belongs to a dead
     * generation, and its {@code close()} only forgets its name. Render thread; no allocation.
     */
    public void abandon() {
        generation++;
    }

    /** {@return the current context generation: 0 at first, one more after each {@link #abandon()}} */
    public int generation() {
        return generation;
    }

    /** {@return how many objects were closed after their context was gone, without a GL call} */
    public long abandoned() {
        return abandoned;
    }

    /** {@return the number of GL objects created and not yet closed} */
    public int live() {
        return live;
    }

    /** {@return the number of GL objects created since the context was made} */
    public long createdTotal() {
        return created;
    }
}
