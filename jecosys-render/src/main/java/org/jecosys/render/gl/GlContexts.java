package org.jecosys.render.gl;

import org.jecosys.render.GlContext;

/**
 * Internal: the parts of a {@link GlContext} that the renderer's internal packages, the application and
 * the tests use and the API does not show (its object tracker and debug output). {@code GlContext}
 * grants the access once, when its class is initialised, so these work for any context there is.
 * Any thread the context's methods allow.
 */
public final class GlContexts {
    /** What {@link GlContext} hands over; implemented by the context itself. */
    public interface Access {
        /**
         * @param gl the context
         * @return its live-object counter
         */
        GlTracker tracker(GlContext gl);

        /**
         * @param gl the context
         * @return its debug output, or null when made without debug
         */
        GlDebug debug(GlContext gl);
    }

    private static volatile Access access;

    private GlContexts() {
    }

    /**
     * Called once by {@link GlContext}'s class initialiser.
     *
     * @param a the context's access
     * @throws IllegalStateException on a second call
     */
    public static synchronized void grant(Access a) {
        if (access != null) {
            throw new IllegalStateException("GlContext's access is granted once");
        }
        access = a;
    }

    /**
     * @param gl the context
     * @return the live-object counter shared by every GL wrapper made in the context
     */
    public static GlTracker tracker(GlContext gl) {
        return access(gl).tracker(gl);
    }

    /**
     * @param gl the context
     * @return the context's debug output, or null when made without debug
     */
    public static GlDebug debug(GlContext gl) {
        return access(gl).debug(gl);
    }

    private static Access access(GlContext gl) {
        if (gl == null) {
            throw new NullPointerException("gl");
        }
        return access;
    }
}
