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
 * <h2>Built-in and user flows</h2>
 * The scene format's kinds are built with {@link #of(FlowDef)}. A game may add its own flow (a fan,
 * a helicopter's downwash, a scripted storm): implement this interface, most simply by extending
 * {@link AbstractWindSource} (an id and one formula), and add it with {@link WindField#add(WindSource)}
 * or {@code Simulation.addFlow(WindSource)}. The field then treats it exactly like a built-in flow:
 * its velocity is summed with the others' wherever the wind is evaluated (at the centroid of the
 * plants of every effective force-field node, paper §3), its enabled switch and activation apply,
 * and it is told when the clock advances ({@link #onAdvance}). A user flow has no {@link #def()}
 * and no {@link #kind()} (both null): it cannot be saved to a scene file, and PATH and ADVECTED
 * motion, which the field applies from a def, do not apply to it (move it in {@link #onAdvance} or
 * with {@link #setCentre}).
 *
 * <h2>What the field calls, and on which thread</h2>
 * A flow is owned by one thread, the one that owns its {@link WindField}: in a simulation, the
 * <em>stepping thread</em> (the one calling {@code Simulation.step}); the animation workers never
 * touch flows. Per fixed step the field calls {@link #onAdvance} once, then {@link #velocity} once
 * per effective node holding plants (thousands of times per step in a large meadow) and, for
 * ADVECTED built-in flows, at their centres; {@link #weight} when counting active flows;
 * {@link #id()} when flows are added or looked up; {@link #isEnabled}/{@link #setEnabled} and
 * {@link #setCentre} when the game's queued commands run. Implementations need not be thread-safe,
 * and {@link #velocity}, {@link #weight}, {@link #onAdvance} and {@link #setCentre} must not
 * allocate (the simulation allocates nothing per step) and must not block. No method of the
 * built-in flows allocates except {@link #of(FlowDef)}.
 */
public interface WindSource {

    /**
     * A new built-in flow of the kind named by {@code def.kind()}: {@link UniformFlow},
     * {@link SourceFlow} (SOURCE and SINK), {@link VortexFlow}, {@link GustFlow}, {@link BlastFlow} or
     * {@link RainFlow}. Any thread; allocates.
     *
     * @param def the flow's definition
     * @return a new flow at its def's centre, enabled as the def says
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

    /**
     * The immutable definition a built-in flow was built from; null for a user flow (the default).
     *
     * @return the def, or null
     */
    default FlowDef def() {
        return null;
    }

    /**
     * The flow's id: unique within its {@link WindField}. Must not change.
     *
     * @return the id, not null
     */
    String id();

    /**
     * The built-in flow's kind (from its def); null for a user flow (the default).
     *
     * @return the kind, or null
     */
    default FlowKind kind() {
        return null;
    }

    /**
     * Whether the flow is switched on (independently of its activation window). No allocation.
     *
     * @return true when on
     */
    boolean isEnabled();

    /**
     * Switches the flow on or off at runtime (paper §3.2: "activated/deactivated"). A disabled flow
     * must have weight 0 and velocity 0. Owner thread; no allocation.
     *
     * @param enabled the new state
     */
    void setEnabled(boolean enabled);

    /**
     * Current centre X, metres (meaningless for UNIFORM and GUST flows). Default 0.
     *
     * @return metres
     */
    default double centreX() {
        return 0;
    }

    /**
     * Current centre Z, metres (meaningless for UNIFORM and GUST flows). Default 0.
     *
     * @return metres
     */
    default double centreZ() {
        return 0;
    }

    /**
     * Moves the centre, metres. Agents call this every frame; a PATH flow's centre is overwritten
     * by the next {@link WindField#advance(double)}. Owner thread; no allocation. The default throws:
     * a flow without a centre cannot be moved.
     *
     * @param x centre X, metres, finite
     * @param z centre Z, metres, finite
     * @throws UnsupportedOperationException when the flow has no movable centre (the default)
     */
    default void setCentre(double x, double z) {
        throw new UnsupportedOperationException("flow '" + id() + "' has no movable centre");
    }

    /**
     * The distance from the centre beyond which the flow is 0, metres; +Infinity when unbounded (the
     * default). {@link #velocity} applies it itself; the field does not cull with it (a flow that
     * returns 0 beyond it adds nothing). No allocation.
     *
     * @return metres, &gt; 0, or +Infinity
     */
    default double influenceRadius() {
        return Double.POSITIVE_INFINITY;
    }

    /**
     * The activation weight in [0, 1] at simulation time {@code time} (seconds): 0 before the
     * start, a linear ramp to 1 over {@code rampIn}, 1, a linear ramp to 0 over the last
     * {@code rampOut} seconds, 0 after the end ({@link ActivationDef#weight}). 0 when the flow is
     * disabled. The default is 1 when enabled, 0 otherwise (always active). No allocation.
     *
     * @param time simulation time, seconds
     * @return the weight, in [0, 1]
     */
    default double weight(double time) {
        return isEnabled() ? 1 : 0;
    }

    /**
     * Whether the activation window has ended at {@code time} (seconds); never for a forever flow
     * (the default: false). No allocation.
     *
     * @param time simulation time, seconds
     * @return true once the flow will never act again
     */
    default boolean expired(double time) {
        return false;
    }

    /**
     * Called by {@link WindField#advance(double)} once per advance, after the clock has moved to
     * {@code time} and before any velocity at that time is evaluated: the place for a user flow to
     * update per-step state (a moving centre, a cached oscillation). The built-in flows do nothing
     * here (the field moves them). Owner thread; must not allocate. The default does nothing.
     *
     * @param time the new simulation time, seconds
     * @param dt   the time just advanced, seconds, &gt;= 0
     */
    default void onAdvance(double time, double dt) {
    }

    /**
     * Writes the flow's velocity (m/s, activation weight applied) at ground point (x, z) at time
     * {@code time} into {@code dest} (x = X component, y = Z component) and returns it. Must be
     * finite everywhere, the centre included, and (0, 0) when the flow is disabled or inactive.
     * Called very often on the owner thread (see the class comment); must not allocate.
     *
     * @param x    ground X, metres
     * @param z    ground Z, metres
     * @param time simulation time, seconds (the field's {@link WindField#time()})
     * @param dest where to write
     * @return {@code dest}
     */
    Vector2d velocity(double x, double z, double time, Vector2d dest);
}
