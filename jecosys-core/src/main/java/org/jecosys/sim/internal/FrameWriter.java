package org.jecosys.sim.internal;

import org.jecosys.sim.Frame;

/**
 * Internal (not API; not exported by the module): writes a {@link Frame} the caller owns, for tools
 * and tests that build frames without the animation engine (a renderer preview, the renderer's
 * tests). A game reads frames only; the simulation writes its own. {@code Frame} grants the access
 * once, when its class is initialised. Only on a frame the caller owns (never one read through the
 * simulation's exchange); one thread; no allocation.
 */
public final class FrameWriter {
    /** What {@link Frame} hands over; implemented by the frame's class. */
    public interface Access {
        /**
         * @param f         the frame
         * @param c         component index
         * @param poseCoord pose coordinate k + w
         * @param azimuth   world heading of the bending plane, radians
         */
        void set(Frame f, int c, float poseCoord, float azimuth);

        /**
         * @param f  the frame
         * @param c  component index
         * @param dx deviation X, metres
         * @param dz deviation Z, metres
         */
        void setDeviation(Frame f, int c, float dx, float dz);

        /**
         * @param f     the frame
         * @param p     plant index
         * @param level level of detail, or -1 for not drawn
         * @param keep  packed dither windows
         */
        void setDraw(Frame f, int p, int level, int keep);

        /**
         * @param f           the frame
         * @param start       where thinning begins, metres
         * @param end         where it reaches its least share, metres
         * @param minFraction the least share, in (0, 1]
         */
        void setThinning(Frame f, double start, double end, double minFraction);
    }

    private static volatile Access access;

    private FrameWriter() {
    }

    /**
     * Called once by {@link Frame}'s class initialiser.
     *
     * @param a the frame's access
     * @throws IllegalStateException on a second call
     */
    public static synchronized void grant(Access a) {
        if (access != null) {
            throw new IllegalStateException("Frame's access is granted once");
        }
        access = a;
    }

    /**
     * Poses component c at pose coordinate {@code poseCoord} and bend azimuth {@code azimuth} (sets
     * the deviation that gives them).
     *
     * @param f         the frame, owned by the caller
     * @param c         component index
     * @param poseCoord pose coordinate k + w, in [0, poses - 1] of the component's pose table
     * @param azimuth   world heading of the bending plane, radians
     */
    public static void set(Frame f, int c, float poseCoord, float azimuth) {
        access(f).set(f, c, poseCoord, azimuth);
    }

    /**
     * Sets component c's deviation D.
     *
     * @param f  the frame, owned by the caller
     * @param c  component index
     * @param dx deviation X, metres
     * @param dz deviation Z, metres
     */
    public static void setDeviation(Frame f, int c, float dx, float dz) {
        access(f).setDeviation(f, c, dx, dz);
    }

    /**
     * Sets plant p's drawing decision ({@link Frame#drawLevel}, {@link Frame#drawKeep}).
     *
     * @param f     the frame, owned by the caller
     * @param p     plant index
     * @param level level of detail to draw it at, or -1 for not drawn
     * @param keep  packed dither windows, as {@link Frame#drawKeep} returns them (255: level alone)
     */
    public static void setDraw(Frame f, int p, int level, int keep) {
        access(f).setDraw(f, p, level, keep);
    }

    /**
     * Records the distance thinning the frame's decision used.
     *
     * @param f           the frame, owned by the caller
     * @param start       where thinning begins, metres
     * @param end         where it reaches its least share, metres
     * @param minFraction the least share, in (0, 1] (1: none)
     */
    public static void setThinning(Frame f, double start, double end, double minFraction) {
        access(f).setThinning(f, start, end, minFraction);
    }

    private static Access access(Frame f) {
        if (f == null) {
            throw new NullPointerException("frame");
        }
        return access;
    }
}
