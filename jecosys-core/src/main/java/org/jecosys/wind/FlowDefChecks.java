package org.jecosys.wind;

import org.jecosys.math.Require;
import org.jecosys.math.Waypoint;

/**
 * The checks of a {@link FlowDef}: its canonical constructor's (every component in the range its
 * record documents, a finite influence radius for RAIN) and its builder's (the values without a
 * default set). Static methods only; any thread; no allocation but the messages they throw.
 */
final class FlowDefChecks {
    private FlowDefChecks() {
    }

    /**
     * Checks the components of a {@link FlowDef}, in the order of its record (the first value out of
     * range is the one reported; RAIN's finite disc after the noise frequency); arguments as its
     * canonical constructor's ({@code enabled} and {@code seed} take any value).
     *
     * @throws IllegalArgumentException when a component is null, empty or out of range
     */
    static void check(String id, FlowKind kind, double x, double z, double strength, double direction,
                      double coreRadius, double influenceRadius, ActivationDef activation, MotionDef motion,
                      double noiseScale, double noiseFrequency, double gustStrength, double turbulence,
                      double gustStretch) {
        Require.nonNull("id", id);
        if (id.isEmpty()) {
            throw new IllegalArgumentException("id must not be empty");
        }
        Require.nonNull("kind", kind);
        Require.range("x", x, -Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE);
        Require.range("z", z, -Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE);
        Require.range("strength", strength, kind == FlowKind.VORTEX ? -FlowDef.MAX_STRENGTH : 0, FlowDef.MAX_STRENGTH);
        Require.degrees("direction", direction, -FlowDef.MAX_DIRECTION_DEGREES, FlowDef.MAX_DIRECTION_DEGREES);
        Require.range("coreRadius", coreRadius, FlowDef.MIN_CORE_RADIUS, FlowDef.MAX_CORE_RADIUS);
        Require.aboveOrInfinite("influenceRadius", influenceRadius, 0, FlowDef.MAX_INFLUENCE_RADIUS);
        Require.nonNull("activation", activation);
        Require.nonNull("motion", motion);
        Require.range("noiseScale", noiseScale, FlowDef.MIN_NOISE_SCALE, FlowDef.MAX_NOISE_SCALE);
        Require.above("noiseFrequency", noiseFrequency, 0, FlowDef.MAX_NOISE_FREQUENCY);
        if (kind == FlowKind.RAIN && influenceRadius == Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("a rain flow needs a finite influenceRadius (the radius of the rain disc)");
        }
        Require.range("gustStrength", gustStrength, 0, FlowDef.MAX_GUST_STRENGTH);
        Require.range("turbulence", turbulence, 0, FlowDef.MAX_TURBULENCE);
        Require.range("gustStretch", gustStretch, 1, FlowDef.MAX_GUST_STRETCH);
    }

    /**
     * Checks that a {@link FlowDef.Builder} of flow {@code id} was given the values without a default in
     * the scene schema: the strength (set when not NaN) and, for a RAIN flow, the influence radius.
     *
     * @throws IllegalStateException naming the first value not set
     */
    static void requireSet(String id, FlowKind kind, double strength, boolean influenceSet) {
        if (Double.isNaN(strength)) {
            throw new IllegalStateException("flow '" + id + "': set the strength (no default in the scene schema)");
        }
        if (kind == FlowKind.RAIN && !influenceSet) {
            throw new IllegalStateException("flow '" + id + "': a RAIN flow needs its influenceRadius (the rain "
                    + "disc; no default in the scene schema)");
        }
    }
}
