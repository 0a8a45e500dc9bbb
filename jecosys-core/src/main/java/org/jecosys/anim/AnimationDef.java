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
 */
public record AnimationDef(AnimationMode mode, double fixedStep, int maxSubSteps, int subIntervals, int workers,
                           long seed) {
    /**
     * Checks the components.
     *
     * @param mode         static, random or constraint, not null
     * @param fixedStep    fixed step, seconds, in [1e-5, 1]
     * @param maxSubSteps  most fixed steps per step(dt) call, in [1, 1000]
     * @param subIntervals spring sub-intervals per step, in [1, 64]
     * @param workers      animation workers, in [0, 256]; 0 means the available processors
     * @param seed         seed of the random mode (any value)
     * @throws IllegalArgumentException when mode is null or a number is out of range
     */
    public AnimationDef {
        Require.nonNull("mode", mode);
        Require.range("fixedStep", fixedStep, 1e-5, 1);
        Require.range("maxSubSteps", maxSubSteps, 1, 1000);
        Require.range("subIntervals", subIntervals, 1, 64);
        Require.range("workers", workers, 0, 256);
    }

    /** {@return constraint mode at 60 Hz, at most 8 sub-steps, 4 sub-intervals, all processors, seed 1} */
    public static AnimationDef defaults() {
        return new AnimationDef(AnimationMode.CONSTRAINT, 1.0 / 60, 8, 4, 0, 1);
    }
}
