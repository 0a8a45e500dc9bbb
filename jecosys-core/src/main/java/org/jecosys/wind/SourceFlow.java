package org.jecosys.wind;

import org.joml.Vector2d;

/**
 * Source and sink flows (paper §3.2, [11]): {@code u = (a / 2 pi) (p - c) / r^2}, r = |p - c|,
 * with {@code a = +strength} for SOURCE (outward) and {@code a = -strength} for SINK (inward),
 * strength in m^2/s. For r &lt; coreRadius the magnitude tapers linearly to 0 at the centre:
 * {@code u = (a / 2 pi) (p - c) / coreRadius^2}. Zero beyond the influence radius.
 * Single owner thread; no allocation after construction.
 */
public final class SourceFlow extends FlowBase {
    private final double k;

    /**
     * A source or sink from its def (kind SOURCE or SINK). Allocates.
     *
     * @param def a SOURCE or SINK flow: centre (metres), strength (m^2/s), core and influence radii
     * @throws IllegalArgumentException when the def is of another kind
     */
    public SourceFlow(FlowDef def) {
        super(def);
        if (def.kind() != FlowKind.SOURCE && def.kind() != FlowKind.SINK) {
            throw new IllegalArgumentException("def.kind must be SOURCE or SINK, got " + def.kind());
        }
        double a = def.kind() == FlowKind.SINK ? -def.strength() : def.strength();
        k = a / (2 * Math.PI);
    }

    @Override
    void unweighted(double x, double z, double time, Vector2d dest) {
        radial(x - cx, z - cz, k, dest);
    }
}
