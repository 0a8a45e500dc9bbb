package org.jecosys.render;

/**
 * Counts the live GL objects created through the {@code Gl*} wrappers of one {@link GlContext}, so a
 * test (or a leak check at shutdown) can prove that closing the renderers released every one.
 *
 * <p>Render thread only. No allocation.
 */
public final class GlTracker {
    private int live;
    private long created;

    GlTracker() {
    }

    void created() {
        live++;
        created++;
    }

    void deleted() {
        live--;
    }

    /** GL objects created and not yet closed. */
    public int live() {
        return live;
    }

    /** GL objects created since the context was made. */
    public long createdTotal() {
        return created;
    }
}
