package org.jecosys.render.gl;

/**
 * Base of every {@code Gl*} wrapper: one GL object name, owned by one renderer, created and deleted on
 * the render thread. {@link #close()} is idempotent; there is no finalizer: GL objects are freed
 * explicitly on the render thread, never by the garbage collector.
 */
public abstract class GlResource implements AutoCloseable {
    private final GlTracker tracker;
    private final int generation;
    private int id;

    public GlResource(GlTracker tracker, int id) {
        if (id == 0) {
            throw new IllegalStateException(getClass().getSimpleName() + ": the GL driver returned no object name");
        }
        if (tracker.mustFail()) {
            delete(id);
            throw new IllegalStateException(getClass().getSimpleName() + ": injected failure (GlTracker.failAfter)");
        }
        this.tracker = tracker;
        this.id = id;
        this.generation = tracker.generation();
        tracker.created();
    }

    /**
     * The GL object name; fails after {@link #close()}.
     *
     * @return the name, never 0
     * @throws IllegalStateException when the object is closed
     */
    public final int id() {
        if (id == 0) {
            throw new IllegalStateException(getClass().getSimpleName() + " is closed");
        }
        return id;
    }

    /** {@return whether {@link #close()} was called} */
    public final boolean closed() {
        return id == 0;
    }

    /**
     * Deletes the GL object; when its context is gone ({@link GlTracker#abandon()}) only forgets the
     * name, without a GL call. Render thread; idempotent; no allocation.
     */
    @Override
    public final void close() {
        if (id != 0) {
            if (generation == tracker.generation()) {
                delete(id);
                id = 0;
                tracker.deleted();
            } else {
                id = 0;
                tracker.forgotten();
            }
        }
    }

    public abstract void delete(int name);
}
