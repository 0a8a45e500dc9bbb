package org.jecosys.anim;

import org.jecosys.math.Require;

/**
 * Animation settings (paper §4.2). Immutable; any thread.
 *
 * @param mode         static, random or constraint (paper Table 7's S1, S2, S3)
 * @param fixedStep    the simulation's fixed step, seconds, in [1e-5, 1]
 * @param maxSubSteps  cap on fixed steps taken in one call to step(dt), in [1, 1000]
 * @param subIntervals sub-intervals of each step in the spring update (paper §4.2.1), in [1, 64]: a flow
 *                     switched inside a step acts from the next sub-interval boundary ({@link SpringKinds})
 * @param workers      animation workers, in [0, 256]; 0 means the available processors (the scene
 *                     file's {@code <animation threads>})
 * @param seed         seed of the random mode and of any other randomness in animation
 * @param prewarm      seconds of wind the simulation runs before its first step, in [0,
 *                     {@link #MAX_PREWARM}] (not in the paper): the plants start at the equilibrium of
 *                     the wind and still, so without it the first second after a scene starts moves
 *                     less than any later one; with it the first frame a viewer sees is already in
 *                     motion. 0 (the default) starts at t = 0 as the paper's scenes do.
 */
public record AnimationDef(AnimationMode mode, double fixedStep, int maxSubSteps, int subIntervals, int workers,
                           long seed, double prewarm) {
    /** Longest {@link #prewarm()}, seconds. */
    public static final double MAX_PREWARM = 60;

    /**
     * Checks the components.
     *
     * @param mode         static, random or constraint, not null
     * @param fixedStep    fixed step, seconds, in [1e-5, 1]
     * @param maxSubSteps  most fixed steps per step(dt) call, in [1, 1000]
     * @param subIntervals spring sub-intervals per step, in [1, 64]
     * @param workers      animation workers, in [0, 256]; 0 means the available processors
     * @param seed         seed of the random mode (any value)
     * @param prewarm      seconds run before the first step, in [0, {@link #MAX_PREWARM}]
     * @throws IllegalArgumentException when mode is null or a number is out of range
     */
    public AnimationDef {
        Require.nonNull("mode", mode);
        Require.range("fixedStep", fixedStep, 1e-5, 1);
        Require.range("maxSubSteps", maxSubSteps, 1, 1000);
        Require.range("subIntervals", subIntervals, 1, 64);
        Require.range("workers", workers, 0, 256);
        Require.range("prewarm", prewarm, 0, MAX_PREWARM);
    }

    /**
     * Settings without a prewarm (the paper's start at t = 0).
     *
     * @param mode         static, random or constraint, not null
     * @param fixedStep    fixed step, seconds, in [1e-5, 1]
     * @param maxSubSteps  most fixed steps per step(dt) call, in [1, 1000]
     * @param subIntervals spring sub-intervals per step, in [1, 64]
     * @param workers      animation workers, in [0, 256]; 0 means the available processors
     * @param seed         seed of the random mode (any value)
     * @throws IllegalArgumentException when mode is null or a number is out of range
     */
    public AnimationDef(AnimationMode mode, double fixedStep, int maxSubSteps, int subIntervals, int workers,
                        long seed) {
        this(mode, fixedStep, maxSubSteps, subIntervals, workers, seed, 0);
    }

    /**
     * {@return the fixed steps the prewarm runs: {@link #prewarm()} / {@link #fixedStep()}, rounded to the
     * nearest}
     */
    public int prewarmSteps() {
        return (int) Math.round(prewarm / fixedStep);
    }

    /**
     * {@return these settings with another prewarm} Any thread; allocates the record.
     *
     * @param seconds the prewarm, seconds, in [0, {@link #MAX_PREWARM}]
     * @throws IllegalArgumentException when it is out of range or NaN
     */
    public AnimationDef withPrewarm(double seconds) {
        return new AnimationDef(mode, fixedStep, maxSubSteps, subIntervals, workers, seed, seconds);
    }

    /**
     * {@return these settings with another mode, everything else kept} Any thread; allocates the record.
     *
     * @param mode static, random or constraint, not null
     * @throws IllegalArgumentException when it is null
     */
    public AnimationDef withMode(AnimationMode mode) {
        return new AnimationDef(mode, fixedStep, maxSubSteps, subIntervals, workers, seed, prewarm);
    }

    /** {@return constraint mode at 60 Hz, at most 8 sub-steps, 4 sub-intervals, all processors, seed 1, no prewarm} */
    public static AnimationDef defaults() {
        return new AnimationDef(AnimationMode.CONSTRAINT, 1.0 / 60, 8, 4, 0, 1);
    }
}
