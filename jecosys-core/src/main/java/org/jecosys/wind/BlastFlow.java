package org.jecosys.wind;

import org.joml.Vector2d;

/**
 * A blast (explosion): a short radial pulse. A source of strength a = strength (m^2/s) at the
 * centre whose front travels outward at {@link #FRONT_SPEED} and which fades over its duration D
 * (the activation duration, or {@link #DEFAULT_DURATION} when that is infinite). With
 * s = time - start:
 * <pre>
 *   u = (1 - s / D)^2 (a / 2 pi) (p - c) / max(r, core)^2   if r &lt;= FRONT_SPEED * s and s &lt; D
 *   u = 0                                                  otherwise
 * </pre>
 * times the activation weight. Zero beyond the influence radius. Single owner thread; no
 * allocation after construction.
 */
public final class BlastFlow extends FlowBase {
    /** Speed of the blast front, m/s. */
    public static final double FRONT_SPEED = 40;
    /** Fade time used when the activation duration is infinite, seconds. */
    public static final double DEFAULT_DURATION = 1.0;

    private final double k;
    private final double duration;

    /**
     * A blast from its def (kind BLAST). Allocates.
     *
     * @param def a BLAST flow: strength in m^2/s, activation giving its start and fade time
     * @throws IllegalArgumentException when the def is of another kind
     */
    public BlastFlow(FlowDef def) {
        super(def);
        if (def.kind() != FlowKind.BLAST) {
            throw new IllegalArgumentException("def.kind must be BLAST, got " + def.kind());
        }
        k = def.strength() / (2 * Math.PI);
        double d = def.activation().duration();
        duration = d == Double.POSITIVE_INFINITY ? DEFAULT_DURATION : d;
    }

    @Override
    void unweighted(double x, double z, double time, Vector2d dest) {
        double s = time - def.activation().start();
        if (s < 0 || s >= duration) {
            dest.set(0, 0);
            return;
        }
        double dx = x - cx;
        double dz = z - cz;
        double front = FRONT_SPEED * s;
        if (dx * dx + dz * dz > front * front) {
            dest.set(0, 0);
            return;
        }
        double e = 1 - s / duration;
        radial(dx, dz, k * e * e, dest);
    }
}
