package org.jecosys.sim.internal;

import org.jecosys.math.Camera;
import org.jecosys.sim.DrawDecision;
import org.jecosys.sim.Frame;

/**
 * Internal (not API; not exported by the module): changes a {@link DrawDecision} the caller made
 * itself ({@link DrawDecision#of}) and writes its decision into a frame the caller owns, for tests
 * and tools. A game changes the simulation's decision
 * through the simulation's queued commands ({@code Simulation.setLodTransition},
 * {@code Simulation.setThinning}). {@code DrawDecision} grants the access once, when its class is
 * initialised. Any thread; takes effect at the next decision.
 */
public final class DecisionWriter {
    /** What {@link DrawDecision} hands over; implemented by the decision's class. */
    public interface Access {
        /**
         * @param d      the decision
         * @param metres band width, in [0, 10]
         */
        void setTransition(DrawDecision d, double metres);

        /**
         * @param d           the decision
         * @param start       where thinning starts, metres
         * @param end         where the kept share reaches {@code minFraction}, metres
         * @param minFraction share of plants kept at and beyond {@code end}, in [0, 1]
         */
        void setThinning(DrawDecision d, double start, double end, double minFraction);

        /**
         * @param d      the decision
         * @param camera the viewer
         * @param frame  a frame of the decision's world, owned by the caller
         * @return {@code frame}
         */
        Frame decideAll(DrawDecision d, Camera camera, Frame frame);
    }

    private static volatile Access access;

    private DecisionWriter() {
    }

    /**
     * Called once by {@link DrawDecision}'s class initialiser.
     *
     * @param a the decision's access
     * @throws IllegalStateException on a second call
     */
    public static synchronized void grant(Access a) {
        if (access != null) {
            throw new IllegalStateException("DrawDecision's access is granted once");
        }
        access = a;
    }

    /**
     * Sets the transition band over which two levels are dithered.
     *
     * @param d      the decision, made by the caller
     * @param metres band width, in [0, 10]
     * @throws IllegalArgumentException when out of range
     */
    public static void setTransition(DrawDecision d, double metres) {
        access(d).setTransition(d, metres);
    }

    /**
     * Sets the distance thinning.
     *
     * @param d           the decision, made by the caller
     * @param start       where thinning starts, metres, in [0, 1e6]
     * @param end         where the kept share reaches {@code minFraction}, metres, in [start, 1e6]
     * @param minFraction share of plants kept at and beyond {@code end}, in [0, 1]; 1 for no thinning
     * @throws IllegalArgumentException when out of range
     */
    public static void setThinning(DrawDecision d, double start, double end, double minFraction) {
        access(d).setThinning(d, start, end, minFraction);
    }

    /**
     * Decides every plant of {@code frame} for {@code camera}, all taken as visible to the field, and
     * writes the decision into the frame: for frames built without the animation engine (a renderer
     * preview, tests). The caller's thread; one call at a time per decision; no allocation.
     *
     * @param d      the decision, made by the caller
     * @param camera the viewer
     * @param frame  a frame of the decision's world, owned by the caller
     * @return {@code frame}
     */
    public static Frame decideAll(DrawDecision d, Camera camera, Frame frame) {
        return access(d).decideAll(d, camera, frame);
    }

    private static Access access(DrawDecision d) {
        if (d == null) {
            throw new NullPointerException("decision");
        }
        return access;
    }
}
