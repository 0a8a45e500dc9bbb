package org.jecosys.wind;

import org.jecosys.math.Noise;
import org.joml.Vector2d;

/**
 * Gusty, turbulent wind as frozen turbulence (Taylor's hypothesis): a mean flow {@code U} (|U| =
 * strength m/s, heading direction) modulated by a seeded value-noise pattern ({@link Noise#value3})
 * that travels downwind with the mean flow, so gust fronts cross the ground at the wind's speed, and
 * changes slowly as it goes. With s = noiseScale (m), f = noiseFrequency (Hz, how fast the pattern
 * changes as it travels; a fixed point sees gusts about |U| / s times per second), A = gustStrength
 * and T = turbulence (dimensionless), q = (p - U t) / s the point in the travelling pattern:
 * <pre>
 *   n1 = value3(seed,     q.x,   q.z,   f t)     n2 = value3(seed + 1, q.x,   q.z,   f t)
 *   m1 = value3(seed + 2, 4 q.x, 4 q.z, 2 f t)   m2 = value3(seed + 3, 4 q.x, 4 q.z, 2 f t)
 *   u  = U (1 + A n1 + T m1) + |U| (A n2 + T m2) perp(U^)      perp(U^) = U^ turned +90 degrees (-U^z, U^x)
 * </pre>
 * The second octave (eddies a quarter of the gust size, changing twice as fast) is skipped when T is
 * 0, which gives the gusts of earlier versions exactly. With a stretch k = gustStretch above 1, the
 * gusts' pattern (n1, n2) is read at (q . U^, q . perp(U^) / k) instead of q: bands k times longer
 * across the wind than along it, running with it (the eddies stay round); k = 1 reads q as before. Deterministic for a seed; a pure function of
 * position and time; |u| &lt;= |U| (1 + sqrt(2) (A + T)). Centre and influence radius are unused.
 * Single owner thread; no allocation after construction.
 */
public final class GustFlow extends FlowBase {
    /** The default relative strength of the gusts ({@link FlowDef#DEFAULT_GUST_STRENGTH}), dimensionless. */
    public static final double AMPLITUDE = FlowDef.DEFAULT_GUST_STRENGTH;
    /** Size of the turbulent eddies relative to the gusts' ({@code noiseScale}), dimensionless. */
    public static final double EDDY_SCALE = 0.25;

    private final double ux;
    private final double uz;
    private final double invScale;
    private final double freq;
    private final long seed;
    private final double amplitude;
    private final double turbulence;
    /** 1 / gustStretch, and the wind's unit heading; the pattern is stretched across it when below 1. */
    private final double invStretch;
    private final double hx;
    private final double hz;

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
        amplitude = def.gustStrength();
        turbulence = def.turbulence();
        invStretch = 1.0 / def.gustStretch();
        hx = Math.cos(def.direction());
        hz = Math.sin(def.direction());
    }

    /**
     * The speed of this flow's small eddies at {@code time}: {@code turbulence x strength x weight},
     * m/s (0 when disabled, outside its window or without turbulence). Owner thread; no allocation.
     *
     * @param time simulation time, seconds
     * @return m/s, &gt;= 0
     */
    public double eddySpeed(double time) {
        return turbulence * def.strength() * weight(time);
    }

    /**
     * The velocity at which this flow's gust pattern travels over the ground, its mean wind U (m/s; x =
     * X, y = Z), whatever its weight. Owner thread; no allocation.
     *
     * @param dest where to write
     * @return {@code dest}
     */
    public Vector2d travel(Vector2d dest) {
        return dest.set(ux, uz);
    }

    @Override
    void unweighted(double x, double z, double time, Vector2d dest) {
        double qx = (x - ux * time) * invScale;
        double qz = (z - uz * time) * invScale;
        double ft = freq * time;
        double gx = qx;
        double gz = qz;
        if (invStretch < 1) {
            gx = qx * hx + qz * hz;                   // along the wind
            gz = (qz * hx - qx * hz) * invStretch;    // across it, stretched
        }
        double along = 1 + amplitude * Noise.value3(seed, gx, gz, ft);
        double across = amplitude * Noise.value3(seed + 1, gx, gz, ft);
        if (turbulence > 0) {
            double ex = qx / EDDY_SCALE;
            double ez = qz / EDDY_SCALE;
            along += turbulence * Noise.value3(seed + 2, ex, ez, 2 * ft);
            across += turbulence * Noise.value3(seed + 3, ex, ez, 2 * ft);
        }
        // perp(U) * |U| * across / |U| = (-uz, ux) * across
        dest.set(ux * along - uz * across, uz * along + ux * across);
    }
}
