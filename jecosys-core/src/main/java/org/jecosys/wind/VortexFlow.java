package org.jecosys.wind;

import org.joml.Vector2d;

/**
 * Vortex flow (paper §3.2, [11]): {@code u = (Gamma / 2 pi) y^ x (p - c) / r^2} with
 * Gamma = strength (m^2/s). With d = p - c = (dx, dz): {@code y^ x d = (dz, -dx)}, so
 * {@code u = (Gamma / 2 pi) (dz, -dx) / r^2}. Sign convention: positive Gamma is a rotation about
 * +Y by the right-hand rule, i.e. <b>counter-clockwise seen from above</b> (looking down -Y with
 * +X to the right, +Z points down the screen): at c + (1, 0) the wind blows toward -Z.
 * The velocity is always tangential (perpendicular to p - c). Rankine core: for r &lt; coreRadius
 * it is a solid-body rotation, 0 at the centre. Zero beyond the influence radius.
 * Single owner thread; no allocation after construction.
 */
public final class VortexFlow extends FlowBase {
    private final double k;

    /**
     * A vortex from its def (kind VORTEX). Allocates.
     *
     * @param def a VORTEX flow: centre (metres), circulation (strength, m^2/s, signed), core and
     *            influence radii
     * @throws IllegalArgumentException when the def is of another kind
     */
    public VortexFlow(FlowDef def) {
        super(def);
        if (def.kind() != FlowKind.VORTEX) {
            throw new IllegalArgumentException("def.kind must be VORTEX, got " + def.kind());
        }
        k = def.strength() / (2 * Math.PI);
    }

    @Override
    void unweighted(double x, double z, double time, Vector2d dest) {
        radial(x - cx, z - cz, k, dest);
        dest.set(dest.y, -dest.x);
    }
}
