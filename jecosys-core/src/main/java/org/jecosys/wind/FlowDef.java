package org.jecosys.wind;

import java.util.List;
import org.jecosys.math.Require;
import org.jecosys.math.Waypoint;

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
 * @param gustStrength    GUST: relative strength of the gusts along and across the mean wind, dimensionless
 *                        (0.5: the speed varies by up to about half the mean)
 * @param turbulence      GUST: relative strength of the small eddies (a quarter of the gust size),
 *                        dimensionless; 0 for none
 * @param gustStretch     GUST: how many times longer a gust is across the wind than along it, dimensionless;
 *                        1 (the default) for round gusts; above 1 the gusts are bands across the wind that
 *                        run with it, as wind over grass shows them
 */
public record FlowDef(String id, FlowKind kind, boolean enabled, double x, double z, double strength,
                      double direction, double coreRadius, double influenceRadius, ActivationDef activation,
                      MotionDef motion, double noiseScale, double noiseFrequency, long seed, double gustStrength,
                      double turbulence, double gustStretch) {
    /**
     * Checks the components.
     *
     * @param id              not empty
     * @param kind            not null
     * @param enabled         whether it starts enabled
     * @param x               centre X, metres, |x| &lt;= {@link Waypoint#MAX_COORDINATE}
     * @param z               centre Z, metres, |z| &lt;= {@link Waypoint#MAX_COORDINATE}
     * @param strength        m/s or m^2/s (see {@link FlowKind}); in [0, {@link #MAX_STRENGTH}], for
     *                        VORTEX in [-{@link #MAX_STRENGTH}, {@link #MAX_STRENGTH}]
     * @param direction       radians, within +-{@link #MAX_DIRECTION_DEGREES} degrees
     * @param coreRadius      metres, in [{@link #MIN_CORE_RADIUS}, {@link #MAX_CORE_RADIUS}]
     * @param influenceRadius metres, in (0, {@link #MAX_INFLUENCE_RADIUS}], or +Infinity (finite for RAIN)
     * @param activation      not null
     * @param motion          not null
     * @param noiseScale      metres, in [{@link #MIN_NOISE_SCALE}, {@link #MAX_NOISE_SCALE}]
     * @param noiseFrequency  Hz or drops per second per m^2, in (0, {@link #MAX_NOISE_FREQUENCY}]
     * @param seed            any value
     * @param gustStrength    dimensionless, in [0, {@link #MAX_GUST_STRENGTH}]
     * @param turbulence      dimensionless, in [0, {@link #MAX_TURBULENCE}]
     * @param gustStretch     dimensionless, in [1, {@link #MAX_GUST_STRETCH}]
     * @throws IllegalArgumentException when a component is null, empty or out of range
     */
    public FlowDef {
        FlowDefChecks.check(id, kind, x, z, strength, direction, coreRadius, influenceRadius, activation, motion,
                noiseScale, noiseFrequency, gustStrength, turbulence, gustStretch);
    }

    /**
     * A flow with round gusts ({@link #gustStretch()} 1). Values as the canonical constructor's.
     *
     * @param id              not empty
     * @param kind            not null
     * @param enabled         whether it starts enabled
     * @param x               centre X, metres
     * @param z               centre Z, metres
     * @param strength        m/s or m^2/s
     * @param direction       radians
     * @param coreRadius      metres
     * @param influenceRadius metres, or +Infinity
     * @param activation      not null
     * @param motion          not null
     * @param noiseScale      metres
     * @param noiseFrequency  Hz or drops per second per m^2
     * @param seed            any value
     * @param gustStrength    dimensionless
     * @param turbulence      dimensionless
     */
    public FlowDef(String id, FlowKind kind, boolean enabled, double x, double z, double strength, double direction,
                   double coreRadius, double influenceRadius, ActivationDef activation, MotionDef motion,
                   double noiseScale, double noiseFrequency, long seed, double gustStrength, double turbulence) {
        this(id, kind, enabled, x, z, strength, direction, coreRadius, influenceRadius, activation, motion, noiseScale,
                noiseFrequency, seed, gustStrength, turbulence, DEFAULT_GUST_STRETCH);
    }

    /** Default {@link #gustStretch()}: round gusts (dimensionless). */
    public static final double DEFAULT_GUST_STRETCH = 1;
    /** Largest {@link #gustStretch()} (dimensionless). */
    public static final double MAX_GUST_STRETCH = 10;

    /** Default {@link #gustStrength()}: gusts vary the speed by up to about half the mean (dimensionless). */
    public static final double DEFAULT_GUST_STRENGTH = 0.5;
    /** Largest {@link #gustStrength()} (dimensionless). */
    public static final double MAX_GUST_STRENGTH = 4;
    /** Default {@link #turbulence()}: no small eddies (dimensionless). */
    public static final double DEFAULT_TURBULENCE = 0;
    /** Largest {@link #turbulence()} (dimensionless). */
    public static final double MAX_TURBULENCE = 4;

    /**
     * Largest |strength|: m/s for UNIFORM and GUST, m^2/s for the others (scene schema and API). A
     * stronger flow would overflow the force on a component.
     */
    public static final double MAX_STRENGTH = 1e6;
    /** Largest |direction|, degrees (the API takes radians). */
    public static final double MAX_DIRECTION_DEGREES = 360;
    /** Smallest core radius, metres: the flows of sources, sinks and vortices stay finite. */
    public static final double MIN_CORE_RADIUS = 1e-3;
    /** Largest core radius, metres. */
    public static final double MAX_CORE_RADIUS = 10_000;
    /** Largest finite influence radius, metres. */
    public static final double MAX_INFLUENCE_RADIUS = 1e6;
    /**
     * Smallest noise scale (gust size, rain drop spacing), metres: a smaller one puts the gust noise
     * beyond double precision (1e-100 gave NaN).
     */
    public static final double MIN_NOISE_SCALE = 1e-3;
    /** Largest noise scale, metres. */
    public static final double MAX_NOISE_SCALE = 100_000;
    /** Largest noise frequency: Hz for GUST, drops per second per m^2 for RAIN. */
    public static final double MAX_NOISE_FREQUENCY = 10_000;

    /** Default core radius, metres. */
    public static final double DEFAULT_CORE_RADIUS = 0.5;
    /** Default gust noise scale, metres. */
    public static final double DEFAULT_NOISE_SCALE = 8;
    /** Default gust frequency, Hz. */
    public static final double DEFAULT_NOISE_FREQUENCY = 0.25;

    /**
     * A uniform flow, always on.
     *
     * @param id        unique flow id
     * @param speed     m/s, &gt;= 0
     * @param direction heading, radians; 0 is +X, pi/2 is +Z
     * @return the def (allocates)
     */
    public static FlowDef uniform(String id, double speed, double direction) {
        return new FlowDef(id, FlowKind.UNIFORM, true, 0, 0, speed, direction, DEFAULT_CORE_RADIUS,
                Double.POSITIVE_INFINITY, ActivationDef.ALWAYS, MotionDef.FIXED, DEFAULT_NOISE_SCALE,
                DEFAULT_NOISE_FREQUENCY, 0, DEFAULT_GUST_STRENGTH, DEFAULT_TURBULENCE);
    }

    /**
     * A point flow (SOURCE, SINK, VORTEX, BLAST) at (x, z), always on, with the default radii.
     *
     * @param id       unique flow id
     * @param kind     SOURCE, SINK, VORTEX or BLAST
     * @param x        centre X, metres
     * @param z        centre Z, metres
     * @param strength m^2/s; &gt;= 0, signed for VORTEX
     * @return the def (allocates)
     */
    public static FlowDef point(String id, FlowKind kind, double x, double z, double strength) {
        return new FlowDef(id, kind, true, x, z, strength, 0, DEFAULT_CORE_RADIUS,
                Double.POSITIVE_INFINITY, ActivationDef.ALWAYS, MotionDef.FIXED, DEFAULT_NOISE_SCALE,
                DEFAULT_NOISE_FREQUENCY, 0, DEFAULT_GUST_STRENGTH, DEFAULT_TURBULENCE);
    }

    /** Default {@link #enabled()}: the flow starts enabled. */
    public static final boolean DEFAULT_ENABLED = true;
    /** Default centre X, metres. */
    public static final double DEFAULT_X = 0;
    /** Default centre Z, metres. */
    public static final double DEFAULT_Z = 0;
    /** Default {@link #direction()}, radians: toward +X. */
    public static final double DEFAULT_DIRECTION = 0;
    /** Default {@link #influenceRadius()}: unbounded (RAIN has no default: its disc must be given). */
    public static final double DEFAULT_INFLUENCE_RADIUS = Double.POSITIVE_INFINITY;
    /** Default {@link #seed()} of the GUST noise and RAIN drops. */
    public static final long DEFAULT_SEED = 0;
    /** Default activation duration of a BLAST, seconds (the other kinds last forever by default). */
    public static final double DEFAULT_BLAST_DURATION = 0.5;

    /**
     * The scene schema's default activation duration of a kind: {@link #DEFAULT_BLAST_DURATION} for a
     * BLAST, {@link ActivationDef#DEFAULT_DURATION} (forever) otherwise.
     *
     * @param kind the flow kind
     * @return seconds, &gt; 0, or +Infinity
     */
    public static double defaultDuration(FlowKind kind) {
        return Require.nonNull("kind", kind) == FlowKind.BLAST ? DEFAULT_BLAST_DURATION
                : ActivationDef.DEFAULT_DURATION;
    }

    /**
     * A builder for flow {@code id} of kind {@code kind}, every other value at the scene schema's
     * default ({@code DEFAULT_*}, {@link ActivationDef}'s defaults with {@link #defaultDuration},
     * FIXED motion): what a flow element with only its required attributes loads as. The strength
     * has no default and must be set, and so must a RAIN flow's influence radius. Any thread;
     * allocates.
     *
     * @param id   unique within the scene, not empty
     * @param kind the flow primitive
     * @return a new builder
     */
    public static Builder builder(String id, FlowKind kind) {
        return new Builder(id, kind);
    }

    /**
     * A builder holding every value of this def, to change a few. Any thread; allocates.
     *
     * @return a new builder
     */
    public Builder toBuilder() {
        return new Builder(id, kind).enabled(enabled).centre(x, z).strength(strength).direction(direction)
                .coreRadius(coreRadius).influenceRadius(influenceRadius).activation(activation).motion(motion)
                .noiseScale(noiseScale).noiseFrequency(noiseFrequency).seed(seed).gustStrength(gustStrength)
                .turbulence(turbulence).gustStretch(gustStretch);
    }

    /**
     * Fluent builder of a {@link FlowDef} with the scene schema's defaults (see
     * {@link FlowDef#builder}); values are checked by {@link #build()}. One thread; allocates.
     */
    public static final class Builder {
        private final String id;
        private final FlowKind kind;
        private boolean enabled = DEFAULT_ENABLED;
        private double x = DEFAULT_X;
        private double z = DEFAULT_Z;
        private double strength = Double.NaN;
        private double direction = DEFAULT_DIRECTION;
        private double coreRadius = DEFAULT_CORE_RADIUS;
        private double influenceRadius = DEFAULT_INFLUENCE_RADIUS;
        private boolean influenceSet;
        private double start = ActivationDef.DEFAULT_START;
        private double duration;
        private double rampIn = ActivationDef.DEFAULT_RAMP_IN;
        private double rampOut = ActivationDef.DEFAULT_RAMP_OUT;
        private MotionDef motion = MotionDef.FIXED;
        private double noiseScale = DEFAULT_NOISE_SCALE;
        private double noiseFrequency = DEFAULT_NOISE_FREQUENCY;
        private long seed = DEFAULT_SEED;
        private double gustStrength = DEFAULT_GUST_STRENGTH;
        private double turbulence = DEFAULT_TURBULENCE;
        private double gustStretch = DEFAULT_GUST_STRETCH;

        private Builder(String id, FlowKind kind) {
            this.id = id;
            this.kind = kind;
            this.duration = kind == null ? ActivationDef.DEFAULT_DURATION : defaultDuration(kind);
        }

        /**
         * Sets whether the flow starts enabled.
         *
         * @param enabled the start state
         * @return this builder
         */
        public Builder enabled(boolean enabled) {
            this.enabled = enabled;
            return this;
        }

        /**
         * Sets the centre (unused by UNIFORM and GUST).
         *
         * @param x centre X, metres
         * @param z centre Z, metres
         * @return this builder
         */
        public Builder centre(double x, double z) {
            this.x = x;
            this.z = z;
            return this;
        }

        /**
         * Sets the strength (required): m/s for UNIFORM and GUST, m^2/s otherwise (see {@link FlowKind}).
         *
         * @param strength &gt;= 0; signed for VORTEX
         * @return this builder
         */
        public Builder strength(double strength) {
            this.strength = strength;
            return this;
        }

        /**
         * Sets the heading of a UNIFORM or GUST flow.
         *
         * @param direction radians; 0 is +X, pi/2 is +Z
         * @return this builder
         */
        public Builder direction(double direction) {
            this.direction = direction;
            return this;
        }

        /**
         * Sets the radius within which a singular flow tapers to 0.
         *
         * @param coreRadius metres, &gt; 0
         * @return this builder
         */
        public Builder coreRadius(double coreRadius) {
            this.coreRadius = coreRadius;
            return this;
        }

        /**
         * Sets the distance from the centre beyond which the flow is 0 (required for RAIN).
         *
         * @param influenceRadius metres, &gt; 0, or +Infinity
         * @return this builder
         */
        public Builder influenceRadius(double influenceRadius) {
            this.influenceRadius = influenceRadius;
            this.influenceSet = true;
            return this;
        }

        /**
         * Sets the activation window (start, duration, ramps) at once.
         *
         * @param activation not null
         * @return this builder
         */
        public Builder activation(ActivationDef activation) {
            Require.nonNull("activation", activation);
            start = activation.start();
            duration = activation.duration();
            rampIn = activation.rampIn();
            rampOut = activation.rampOut();
            return this;
        }

        /**
         * Sets when the flow begins.
         *
         * @param start simulation time, seconds, &gt;= 0
         * @return this builder
         */
        public Builder start(double start) {
            this.start = start;
            return this;
        }

        /**
         * Sets how long the flow lasts.
         *
         * @param duration seconds, &gt; 0, or +Infinity for forever
         * @return this builder
         */
        public Builder duration(double duration) {
            this.duration = duration;
            return this;
        }

        /**
         * Sets the ramps in and out.
         *
         * @param rampIn  seconds to reach full strength, &gt;= 0
         * @param rampOut seconds to fade out before the end, &gt;= 0
         * @return this builder
         */
        public Builder ramps(double rampIn, double rampOut) {
            this.rampIn = rampIn;
            this.rampOut = rampOut;
            return this;
        }

        /**
         * Sets how the centre moves.
         *
         * @param motion not null
         * @return this builder
         */
        public Builder motion(MotionDef motion) {
            this.motion = motion;
            return this;
        }

        /**
         * Makes the centre move with the other active flows ({@link MotionDef#ADVECTED}), or stay
         * fixed ({@link MotionDef#FIXED}).
         *
         * @param advected whether the centre is advected
         * @return this builder
         */
        public Builder advected(boolean advected) {
            this.motion = advected ? MotionDef.ADVECTED : MotionDef.FIXED;
            return this;
        }

        /**
         * Makes the centre walk a path at the schema's default speed, not looping.
         *
         * @param waypoints at least 2; y is ignored
         * @return this builder
         */
        public Builder path(List<Waypoint> waypoints) {
            this.motion = MotionDef.path(waypoints);
            return this;
        }

        /**
         * Sets the spatial scale of GUST noise or the radius of a RAIN drop's burst.
         *
         * @param noiseScale metres, &gt; 0
         * @return this builder
         */
        public Builder noiseScale(double noiseScale) {
            this.noiseScale = noiseScale;
            return this;
        }

        /**
         * Sets the GUST frequency (Hz) or the RAIN drops per second per m^2.
         *
         * @param noiseFrequency &gt; 0
         * @return this builder
         */
        public Builder noiseFrequency(double noiseFrequency) {
            this.noiseFrequency = noiseFrequency;
            return this;
        }

        /**
         * Sets the seed of the GUST noise or RAIN drops.
         *
         * @param seed any value
         * @return this builder
         */
        public Builder seed(long seed) {
            this.seed = seed;
            return this;
        }

        /**
         * Sets the relative strength of a GUST flow's gusts along and across its mean wind.
         *
         * @param gustStrength dimensionless, in [0, {@link FlowDef#MAX_GUST_STRENGTH}]
         * @return this builder
         */
        public Builder gustStrength(double gustStrength) {
            this.gustStrength = gustStrength;
            return this;
        }

        /**
         * Sets the relative strength of a GUST flow's small eddies (a quarter of its gust size).
         *
         * @param turbulence dimensionless, in [0, {@link FlowDef#MAX_TURBULENCE}]; 0 for none
         * @return this builder
         */
        public Builder turbulence(double turbulence) {
            this.turbulence = turbulence;
            return this;
        }

        /**
         * Sets how many times longer a GUST flow's gusts are across the wind than along it.
         *
         * @param gustStretch dimensionless, in [1, {@link FlowDef#MAX_GUST_STRETCH}]; 1 for round gusts
         * @return this builder
         */
        public Builder gustStretch(double gustStretch) {
            this.gustStretch = gustStretch;
            return this;
        }

        /**
         * The def. Allocates.
         *
         * @return a new def
         * @throws IllegalStateException    when the strength, or a RAIN flow's influence radius, was not set
         * @throws IllegalArgumentException when a value is out of range (see {@link FlowDef},
         *                                  {@link ActivationDef})
         */
        public FlowDef build() {
            FlowDefChecks.requireSet(id, kind, strength, influenceSet);
            return new FlowDef(id, kind, enabled, x, z, strength, direction, coreRadius, influenceRadius,
                    new ActivationDef(start, duration, rampIn, rampOut), motion, noiseScale, noiseFrequency, seed,
                    gustStrength, turbulence, gustStretch);
        }
    }
}
