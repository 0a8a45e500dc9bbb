package org.jecosys.wind;

import org.jecosys.math.Require;

/**
 * One wind flow of a scene (paper §3.2). All kinds share this record; fields a kind does not use
 * keep their defaults (see {@link FlowKind} for what strength means for each). Velocities are
 * 2D, in the ground (XZ) plane. Immutable; any thread.
 *
 * @param id              unique name within the scene
 * @param kind            the flow primitive
 * @param enabled         whether it starts enabled (the viewer may toggle it)
 * @param x               centre X, metres (unused by UNIFORM and GUST)
 * @param z               centre Z, metres (unused by UNIFORM and GUST)
 * @param strength        speed in m/s (UNIFORM, GUST) or circulation/strength in m^2/s (others); &gt;= 0,
 *                        except VORTEX, whose sign gives the sense of rotation (negative turns clockwise)
 * @param direction       heading of UNIFORM and GUST flows, radians; 0 is +X, pi/2 is +Z
 * @param coreRadius      radius within which a singular flow is tapered linearly to 0, metres, &gt; 0
 * @param influenceRadius beyond this distance from the centre the flow is 0, metres, or +Infinity
 * @param activation      when it acts
 * @param motion          how its centre moves
 * @param noiseScale      GUST and RAIN: spatial scale of the noise / drop spacing, metres, &gt; 0
 * @param noiseFrequency  GUST: temporal frequency of gusts, Hz; RAIN: drops per second per m^2; &gt; 0
 * @param seed            seed of the GUST noise and RAIN drops
 */
public record FlowDef(String id, FlowKind kind, boolean enabled, double x, double z, double strength,
                      double direction, double coreRadius, double influenceRadius, ActivationDef activation,
                      MotionDef motion, double noiseScale, double noiseFrequency, long seed) {
    public FlowDef {
        Require.nonNull("id", id);
        if (id.isEmpty()) {
            throw new IllegalArgumentException("id must not be empty");
        }
        Require.nonNull("kind", kind);
        Require.finite("x", x);
        Require.finite("z", z);
        if (kind == FlowKind.VORTEX) {
            Require.finite("strength", strength);
        } else {
            Require.nonNegative("strength", strength);
        }
        Require.finite("direction", direction);
        Require.positive("coreRadius", coreRadius);
        Require.positiveOrInfinite("influenceRadius", influenceRadius);
        Require.nonNull("activation", activation);
        Require.nonNull("motion", motion);
        Require.positive("noiseScale", noiseScale);
        Require.positive("noiseFrequency", noiseFrequency);
        if (kind == FlowKind.RAIN && influenceRadius == Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("a rain flow needs a finite influenceRadius (the radius of the rain disc)");
        }
    }

    /** Default core radius, metres. */
    public static final double DEFAULT_CORE_RADIUS = 0.5;
    /** Default gust noise scale, metres. */
    public static final double DEFAULT_NOISE_SCALE = 8;
    /** Default gust frequency, Hz. */
    public static final double DEFAULT_NOISE_FREQUENCY = 0.25;

    /** A uniform flow of {@code speed} m/s toward heading {@code direction} (radians), always on. */
    public static FlowDef uniform(String id, double speed, double direction) {
        return new FlowDef(id, FlowKind.UNIFORM, true, 0, 0, speed, direction, DEFAULT_CORE_RADIUS,
                Double.POSITIVE_INFINITY, ActivationDef.ALWAYS, MotionDef.FIXED, DEFAULT_NOISE_SCALE,
                DEFAULT_NOISE_FREQUENCY, 0);
    }

    /** A point flow (SOURCE, SINK, VORTEX, BLAST) of the given strength at (x, z), always on. */
    public static FlowDef point(String id, FlowKind kind, double x, double z, double strength) {
        return new FlowDef(id, kind, true, x, z, strength, 0, DEFAULT_CORE_RADIUS,
                Double.POSITIVE_INFINITY, ActivationDef.ALWAYS, MotionDef.FIXED, DEFAULT_NOISE_SCALE,
                DEFAULT_NOISE_FREQUENCY, 0);
    }
}
