package org.jecosys.wind;

import org.joml.Vector2d;

/**
 * Uniform flow (paper §3.2, [11]): {@code u = U}, with {@code |U| = strength} (m/s) and heading
 * {@code direction} (radians; 0 is +X, pi/2 is +Z). The centre and influence radius are unused.
 * Single owner thread; no allocation after construction.
 */
public final class UniformFlow extends FlowBase {
    private final double ux;
    private final double uz;

    /**
     * A uniform flow from its def (kind UNIFORM). Allocates.
     *
     * @param def a UNIFORM flow: speed (strength, m/s) and direction (radians)
     * @throws IllegalArgumentException when the def is of another kind
     */
    public UniformFlow(FlowDef def) {
        super(checkKind(def));
        ux = def.strength() * Math.cos(def.direction());
        uz = def.strength() * Math.sin(def.direction());
    }

    private static FlowDef checkKind(FlowDef def) {
        if (org.jecosys.math.Require.nonNull("def", def).kind() != FlowKind.UNIFORM) {
            throw new IllegalArgumentException("def.kind must be UNIFORM, got " + def.kind());
        }
        return def;
    }

    @Override
    void unweighted(double x, double z, double time, Vector2d dest) {
        dest.set(ux, uz);
    }
}
