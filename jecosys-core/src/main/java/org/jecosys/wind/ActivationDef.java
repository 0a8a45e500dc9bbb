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
    /**
     * Checks the components.
     *
     * @param start    start time, seconds, in [0, {@link #MAX_TIME}]
     * @param duration seconds, in (0, {@link #MAX_TIME}], or +Infinity
     * @param rampIn   seconds, in [0, {@link #MAX_TIME}]
     * @param rampOut  seconds, in [0, {@link #MAX_TIME}]; {@code rampIn + rampOut <= duration} for a
     *                 finite duration
     * @throws IllegalArgumentException when a value is out of range or the ramps exceed the duration
     */
    public ActivationDef {
        Require.range("start", start, 0, MAX_TIME);
        Require.aboveOrInfinite("duration", duration, 0, MAX_TIME);
        Require.range("rampIn", rampIn, 0, MAX_TIME);
        Require.range("rampOut", rampOut, 0, MAX_TIME);
        if (duration != Double.POSITIVE_INFINITY && rampIn + rampOut > duration) {
            throw new IllegalArgumentException("rampIn + rampOut must be <= duration, got "
                    + rampIn + " + " + rampOut + " > " + duration);
        }
    }

    /** Latest start, longest finite duration and longest ramp, seconds (scene schema and API). */
    public static final double MAX_TIME = 1e9;
    /** Default {@link #start()}: the beginning of the simulation, seconds (the scene schema's default too). */
    public static final double DEFAULT_START = 0;
    /** Default {@link #duration()}: forever (the scene schema's default for every kind but BLAST). */
    public static final double DEFAULT_DURATION = Double.POSITIVE_INFINITY;
    /** Default {@link #rampIn()}, seconds: none. */
    public static final double DEFAULT_RAMP_IN = 0;
    /** Default {@link #rampOut()}, seconds: none. */
    public static final double DEFAULT_RAMP_OUT = 0;

    /** Active from time 0, forever, no ramps: every default. */
    public static final ActivationDef ALWAYS = new ActivationDef(DEFAULT_START, DEFAULT_DURATION, DEFAULT_RAMP_IN,
            DEFAULT_RAMP_OUT);

    /**
     * The activation weight at simulation time {@code time} (paper §3.2): 0 before the start, a
     * linear ramp to 1 over {@code rampIn}, 1, a linear ramp to 0 over the last {@code rampOut}
     * seconds, 0 after the end. The built-in flows and {@link AbstractWindSource} use it. Any thread;
     * no allocation.
     *
     * @param time simulation time, seconds
     * @return the weight, in [0, 1]
     */
    public double weight(double time) {
        double s = time - start;
        if (s < 0) {
            return 0;
        }
        double w = 1;
        if (rampIn > 0 && s < rampIn) {
            w = s / rampIn;
        }
        if (duration != Double.POSITIVE_INFINITY) {
            double left = duration - s;
            if (left <= 0) {
                return 0;
            }
            if (rampOut > 0 && left < rampOut) {
                w = Math.min(w, left / rampOut);
            }
        }
        return w;
    }

    /**
     * Whether the window has ended at {@code time}; never for a forever activation. Any thread; no
     * allocation.
     *
     * @param time simulation time, seconds
     * @return true from {@code start + duration} on
     */
    public boolean expired(double time) {
        return duration != Double.POSITIVE_INFINITY && time >= start + duration;
    }
}
