package org.jecosys.wind;

import org.joml.Vector2d;

/**
 * A wind flow over the ground (paper §3.2, the primitives of Wejchert &amp; Haumann [11]): gives a
 * 2D velocity at a point of the XZ plane. Velocities are in m/s and written into a
 * {@link Vector2d} whose {@code x} is the X component and whose {@code y} is the <b>Z</b>
 * component. Flows are summed linearly by {@link WindField}.
 *
 * <p>Every flow has an activation window ({@link ActivationDef}: start, duration or forever, ramps
 * in and out), an enabled switch, an optional influence radius and a centre that may be fixed,
 * scripted along a path, advected by the other flows ({@link MotionDef}) or moved every frame by a
 * game (agents, see {@link WindField#attachAgent(FlowDef)}).
 *
 * <p>Sealed: the scene format knows every kind. Build one with {@link #of(FlowDef)}.
 *
 * <p>Threads: a flow is owned by one thread (the simulation's); it is not thread-safe. No method
 * allocates except {@link #of(FlowDef)}.
 */
public sealed interface WindSource permits FlowBase {

    /**
     * A new flow of the kind named by {@code def.kind()}: {@link UniformFlow}, {@link SourceFlow}
     * (SOURCE and SINK), {@link VortexFlow}, {@link GustFlow}, {@link BlastFlow} or {@link RainFlow}.
     * Allocates.
     *
     * @throws IllegalArgumentException for a RAIN flow with an infinite influence radius
     */
    static WindSource of(FlowDef def) {
        org.jecosys.math.Require.nonNull("def", def);
        return switch (def.kind()) {
            case UNIFORM -> new UniformFlow(def);
            case SOURCE, SINK -> new SourceFlow(def);
            case VORTEX -> new VortexFlow(def);
            case GUST -> new GustFlow(def);
            case BLAST -> new BlastFlow(def);
            case RAIN -> new RainFlow(def);
        };
    }

    /** The immutable definition this flow was built from. */
    FlowDef def();

    /** The flow's id (from its def). */
    String id();

    /** The flow's kind (from its def). */
    FlowKind kind();

    /** Whether the flow is switched on (independently of its activation window). */
    boolean isEnabled();

    /** Switches the flow on or off at runtime (paper §3.2: "activated/deactivated"). */
    void setEnabled(boolean enabled);

    /** Current centre X, metres (meaningless for UNIFORM and GUST flows). */
    double centreX();

    /** Current centre Z, metres (meaningless for UNIFORM and GUST flows). */
    double centreZ();

    /**
     * Moves the centre, metres. Agents call this every frame; a PATH flow's centre is overwritten
     * by the next {@link WindField#advance(double)}.
     */
    void setCentre(double x, double z);

    /**
     * The activation weight in [0, 1] at simulation time {@code time} (seconds): 0 before the
     * start, a linear ramp to 1 over {@code rampIn}, 1, a linear ramp to 0 over the last
     * {@code rampOut} seconds, 0 after the end. 0 when the flow is disabled.
     */
    double weight(double time);

    /** Whether the activation window has ended at {@code time} (seconds); never for a forever flow. */
    boolean expired(double time);

    /**
     * Writes the flow's velocity (m/s, activation weight applied) at ground point (x, z) at time
     * {@code time} into {@code dest} (x = X component, y = Z component) and returns it.
     * Finite everywhere, the centre included. No allocation.
     */
    Vector2d velocity(double x, double z, double time, Vector2d dest);
}
