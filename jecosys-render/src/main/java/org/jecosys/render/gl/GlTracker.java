package org.jecosys.render.gl;


/**
 * Counts the live GL objects created through the {@code Gl*} wrappers of one {@code GlContext}, so a
 * test (or a leak check at shutdown) can prove that closing the renderers released every one.
 *
 * <p>Render thread only. No allocation.
 */
public final class GlTracker {
    private int live;
    private long created;
    private long failAt = -1;

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

    /** {@return the number of GL objects created and not yet closed} */
    public int live() {
        return live;
    }

    /** {@return the number of GL objects created since the context was made} */
    public long createdTotal() {
        return created;
    }
}
