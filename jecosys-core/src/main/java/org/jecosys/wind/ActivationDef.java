package org.jecosys.wind;

import org.jecosys.math.Require;

/**
 * When a flow acts (paper §3.2: "each flow can be activated/deactivated ... or can have a
 * predefined duration"). The flow's weight ramps linearly from 0 to 1 over {@code rampIn} seconds
 * after {@code start}, stays 1, and ramps back to 0 over the last {@code rampOut} seconds of its
 * {@code duration}. Immutable; any thread.
 *
 * @param start    simulation time the flow begins, seconds, &gt;= 0
 * @param duration how long it lasts, seconds, &gt; 0, or {@code +Infinity} for "forever"
 * @param rampIn   seconds to reach full strength, &gt;= 0
 * @param rampOut  seconds to fade out before the end, &gt;= 0 (ignored when the duration is infinite)
 */
public record ActivationDef(double start, double duration, double rampIn, double rampOut) {
    public ActivationDef {
        Require.nonNegative("start", start);
        Require.positiveOrInfinite("duration", duration);
        Require.nonNegative("rampIn", rampIn);
        Require.nonNegative("rampOut", rampOut);
        if (duration != Double.POSITIVE_INFINITY && rampIn + rampOut > duration) {
            throw new IllegalArgumentException("rampIn + rampOut must be <= duration, got "
                    + rampIn + " + " + rampOut + " > " + duration);
        }
    }

    /** Active from time 0, forever, no ramps. */
    public static final ActivationDef ALWAYS = new ActivationDef(0, Double.POSITIVE_INFINITY, 0, 0);
}
