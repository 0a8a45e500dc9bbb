package org.jecosys.wind;

import org.jecosys.math.Noise;
import org.joml.Vector2d;

/**
 * Gusty, turbulent wind: a mean flow {@code U} (|U| = strength m/s, heading direction) modulated
 * by seeded value noise ({@link Noise#value3}) in space and time. With s = noiseScale (m),
 * f = noiseFrequency (Hz), A = {@link #AMPLITUDE}, and q = (p - U t) / s (the gust pattern drifts
 * downwind with the mean flow):
 * <pre>
 *   n1 = value3(seed,     q.x, q.z, f t)     n2 = value3(seed + 1, q.x, q.z, f t)
 *   u  = U (1 + A n1) + A |U| n2 * perp(U^)      perp(U^) = U^ turned +90 degrees (-U^z, U^x)
 * </pre>
 * Deterministic for a seed; |u| &lt;= |U| (1 + sqrt(2) A). Centre and influence radius are unused.
 * Single owner thread; no allocation after construction.
 */
public final class GustFlow extends FlowBase {
    /** Relative strength of the gusts (along and across the mean flow), dimensionless. */
    public static final double AMPLITUDE = 0.5;

    private final double ux;
    private final double uz;
    private final double invScale;
    private final double freq;
    private final long seed;

    /**
     * A gust flow from its def (kind GUST). Allocates.
     *
     * @param def a GUST flow: mean speed (m/s), direction, noise scale (metres) and frequency (Hz), seed
     * @throws IllegalArgumentException when the def is of another kind
     */
    public GustFlow(FlowDef def) {
        super(def);
        if (def.kind() != FlowKind.GUST) {
            throw new IllegalArgumentException("def.kind must be GUST, got " + def.kind());
        }
        ux = def.strength() * Math.cos(def.direction());
        uz = def.strength() * Math.sin(def.direction());
        invScale = 1.0 / def.noiseScale();
        freq = def.noiseFrequency();
        seed = def.seed();
    }

    @Override
    void unweighted(double x, double z, double time, Vector2d dest) {
        double qx = (x - ux * time) * invScale;
        double qz = (z - uz * time) * invScale;
        double ft = freq * time;
        double n1 = Noise.value3(seed, qx, qz, ft);
        double n2 = Noise.value3(seed + 1, qx, qz, ft);
        double along = 1 + AMPLITUDE * n1;
        double across = AMPLITUDE * n2;
        // perp(U) * |U| * across / |U| = (-uz, ux) * across
        dest.set(ux * along - uz * across, uz * along + ux * across);
    }
}
