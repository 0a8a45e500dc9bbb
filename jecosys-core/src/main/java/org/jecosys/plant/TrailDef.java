package org.jecosys.plant;

import org.jecosys.math.Require;

/**
 * How a species keeps the mark of a strong push: trails behind walkers, flattened rings after a blast
 * (not in the paper, which has only the elastic spring of §4.2). A push of the point flows (an
 * agent's source, a blast, a sink or a vortex; never the ambient wind) whose equilibrium bend passes
 * {@code flattenAt} of the plant's bend limit flattens the plant in that direction; the flattening
 * then recovers over {@code recovery} seconds as {@code (1 + s) e^-s} with {@code s = t / recovery}
 * (the critically damped release of the spring, slowed down): 74% of it is left after one recovery
 * time, 4% after five. While flattened the plant's rest point is the flattening plus what is left of
 * its elastic range bent by the wind (see {@code org.jecosys.anim.Trails}). Immutable; any thread.
 *
 * @param recovery  time constant of the recovery, seconds, in [0, {@link #MAX_RECOVERY}]; 0 keeps the
 *                  purely elastic spring (no trails), exactly as without this setting
 * @param flattenAt the equilibrium bend, as a fraction of the bend limit, beyond which a push flattens
 *                  the plant, in [{@link #MIN_FLATTEN_AT}, {@link #MAX_FLATTEN_AT}]
 */
public record TrailDef(double recovery, double flattenAt) {
    /** Longest {@link #recovery()}, seconds: an hour. */
    public static final double MAX_RECOVERY = 3600;
    /** Smallest {@link #flattenAt()}: below it the wind's ordinary sway would flatten the plant. */
    public static final double MIN_FLATTEN_AT = 0.1;
    /** Largest {@link #flattenAt()}: the stiffened spring never reaches the bend limit itself. */
    public static final double MAX_FLATTEN_AT = 0.95;
    /** Default {@link #flattenAt()}: the knee, where the spring leaves its linear range. */
    public static final double DEFAULT_FLATTEN_AT = 0.5;
    /** No trails: the elastic spring alone (every species' default). */
    public static final TrailDef NONE = new TrailDef(0, DEFAULT_FLATTEN_AT);

    /**
     * Checks the components.
     *
     * @param recovery  seconds, in [0, {@link #MAX_RECOVERY}]
     * @param flattenAt fraction of the bend limit, in [{@link #MIN_FLATTEN_AT}, {@link #MAX_FLATTEN_AT}]
     * @throws IllegalArgumentException when a value is out of range or not finite
     */
    public TrailDef {
        Require.range("recovery", recovery, 0, MAX_RECOVERY);
        Require.range("flattenAt", flattenAt, MIN_FLATTEN_AT, MAX_FLATTEN_AT);
    }

    /**
     * A species that leaves trails recovering over {@code recovery} seconds, flattened past the default
     * threshold. Any thread; allocates.
     *
     * @param recovery seconds, in [0, {@link #MAX_RECOVERY}]
     * @return the def
     */
    public static TrailDef recovering(double recovery) {
        return new TrailDef(recovery, DEFAULT_FLATTEN_AT);
    }

    /** {@return whether pushes leave a mark: {@code recovery > 0}} */
    public boolean leavesTrails() {
        return recovery > 0;
    }
}
