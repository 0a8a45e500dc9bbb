package org.jecosys.render.gl;

import java.util.List;

/**
 * Closing many GL objects at once, every one even when one fails (libGDX's {@code Disposable}
 * discipline): the renderers' constructors on failure and their {@code close()}. Render thread.
 */
public final class Closing {
    private Closing() {
    }

    /** Closes {@code resources} last to first, like {@link #closeAll} (every one, even past a failure). */
    public static void closeReverse(List<AutoCloseable> resources) {
        AutoCloseable[] reversed = new AutoCloseable[resources.size()];
        for (int i = 0; i < reversed.length; i++) {
            reversed[i] = resources.get(reversed.length - 1 - i);
        }
        closeAll(reversed);
    }

    /**
     * Closes every non-null resource, in order, even when one fails: the first failure is thrown
     * afterwards (wrapped when checked) with the later ones added as suppressed exceptions, so one
     * broken close never leaks the objects after it. Render thread; allocates only on failure.
     */
    public static void closeAll(AutoCloseable... resources) {
        RuntimeException first = null;
        for (AutoCloseable r : resources) {
            if (r == null) {
                continue;
            }
            try {
                r.close();
            } catch (Exception e) {
                RuntimeException wrapped = e instanceof RuntimeException re ? re
                        : new IllegalStateException("closing " + r, e);
                if (first == null) {
                    first = wrapped;
                } else {
                    first.addSuppressed(wrapped);
                }
            }
        }
        if (first != null) {
            throw first;
        }
    }
}
