package org.jecosys.wind;

import java.util.List;
import org.jecosys.math.Require;
import org.joml.Vector2d;

/**
 * The set of wind flows of a scene and the simulation clock that drives them (paper §3.2): sums
 * every active flow's velocity at a ground point (flows superpose linearly), moves flow centres
 * along their paths or with the other flows (advection), and manages runtime flows for games:
 * agents (a flow attached to a moving entity), blasts, rain showers and a game's own
 * {@link WindSource} implementations, which are summed, switched and advanced like the built-ins.
 * The sums over the flows of some kinds (the gusts, the flows that flatten) are in {@code FlowSums}.
 *
 * <p>Switches: the sum of the flows jumps when a flow is added, removed, enabled or disabled, or when
 * its activation window opens or closes without a ramp. {@link #advance} reports the earliest such
 * time within the step it made ({@link #lastEdge}), so that the animation can switch the force at
 * that time instead of spreading the jump over the step (a user flow's own jumps inside
 * {@link WindSource#velocity} are not known). Changes made before the first advance (building the
 * field) are not switches: nothing was sampled before them.
 *
 * <p>Threads: owned by one thread (the simulation's); not thread-safe. Flows and agents may be
 * added or removed by that thread between updates. {@link #velocity} and {@link #advance} do not
 * allocate; adding flows allocates (and may grow the internal array).
 */
public final class WindField {
    private WindSource[] flows;
    private boolean[] oneShot;
    private double[] advX;
    private double[] advZ;
    private boolean[] wasEnabled;
    private int count;
    private double time;
    private boolean advanced;
    /** The earliest switch since the last advance (add, remove, enable), or NaN. */
    private double pendingEdge = Double.NaN;
    private double lastEdge = Double.NaN;
    private final Vector2d tmp = new Vector2d();
    private final Vector2d adv = new Vector2d();

    /** An empty field at time 0. Allocates. */
    public WindField() {
        flows = new WindSource[8];
        oneShot = new boolean[8];
        advX = new double[8];
        advZ = new double[8];
        wasEnabled = new boolean[8];
    }

    /**
     * A field holding one flow per def, in order, at time 0. Allocates.
     *
     * @param defs the flows, ids unique
     * @return the new field
     * @throws IllegalArgumentException when two defs share an id
     */
    public static WindField of(List<FlowDef> defs) {
        Require.nonNull("defs", defs);
        WindField w = new WindField();
        for (int i = 0; i < defs.size(); i++) {
            w.add(defs.get(i));
        }
        return w;
    }

    /** {@return the simulation time, seconds since the start} */
    public double time() {
        return time;
    }

    /**
     * Moves the clock forward to {@code t} in one jump, without the steps between: flows on a path are
     * placed where they are at {@code t}, advected flows stay where they are, one-shot flows that have
     * expired by then are dropped, and no switch is reported for the jump. For a part of a world that
     * joins a running simulation later than the rest (a tile of an open world built while the others
     * ran): its flows then blow as the others' do, since a flow's wind depends on the time, not on the
     * steps that led to it (advected flows excepted). Stepping thread; no allocation.
     *
     * @param t the new time, seconds, finite and at least {@link #time()}
     * @throws IllegalArgumentException when {@code t} is not finite or lies before {@link #time()}
     */
    public void startAt(double t) {
        Require.finite("t", t);
        if (t < time) {
            throw new IllegalArgumentException("the wind's clock cannot go back from " + time + " s to " + t + " s");
        }
        time = t;
        for (int i = 0; i < count; i++) {
            if (flows[i] instanceof FlowBase f && f.def.motion().kind() == MotionDef.Kind.PATH) {
                f.placeOnPath(time);
            }
        }
        for (int i = count - 1; i >= 0; i--) {
            if (oneShot[i] && flows[i].expired(time)) {
                removeAt(i);
            }
        }
    }

    /** {@return the number of flows held (enabled or not, active or not)} */
    public int size() {
        return count;
    }

    /**
     * {@return the i-th flow, in the order added}
     *
     * @param i in [0, size())
     * @throws IllegalArgumentException when i is out of range
     */
    public WindSource get(int i) {
        Require.range("i", i, 0, count - 1);
        return flows[i];
    }

    /**
     * {@return the index of the flow with this id, or -1 when there is none} No allocation.
     *
     * @param id a flow id
     */
    public int indexOf(String id) {
        for (int i = 0; i < count; i++) {
            if (flows[i].id().equals(id)) {
                return i;
            }
        }
        return -1;
    }

    /**
     * Builds a flow from {@code def} ({@link WindSource#of}) and adds it. Allocates.
     *
     * @param def the flow's definition
     * @return the new flow
     * @throws IllegalArgumentException when a flow with the same id is already held
     */
    public WindSource add(FlowDef def) {
        return add(WindSource.of(def));
    }

    /**
     * Adds a flow: a built-in one ({@link WindSource#of}) or a user implementation, which is then
     * evaluated exactly like the built-ins (see {@link WindSource}). A PATH flow is placed on its
     * path at the current time. Owner thread, between updates; allocates only when the internal
     * arrays grow.
     *
     * @param source the flow, not already held
     * @return {@code source}
     * @throws IllegalArgumentException when a flow with the same id is already held
     */
    public WindSource add(WindSource source) {
        return add(source, false);
    }

    private WindSource add(WindSource source, boolean removeWhenExpired) {
        Require.nonNull("source", source);
        if (indexOf(source.id()) >= 0) {
            throw new IllegalArgumentException("a flow with id '" + source.id() + "' is already in the wind field");
        }
        if (count == flows.length) {
            int n = count * 2;
            flows = java.util.Arrays.copyOf(flows, n);
            oneShot = java.util.Arrays.copyOf(oneShot, n);
            advX = java.util.Arrays.copyOf(advX, n);
            advZ = java.util.Arrays.copyOf(advZ, n);
            wasEnabled = java.util.Arrays.copyOf(wasEnabled, n);
        }
        if (source instanceof FlowBase f && f.hasPath()) {
            f.placeOnPath(time);
        }
        flows[count] = source;
        oneShot[count] = removeWhenExpired;
        wasEnabled[count] = source.isEnabled();
        if (source.weight(time) > 0) {
            noteSwitch();
        }
        count++;
        return source;
    }

    /**
     * Removes a flow. No allocation.
     *
     * @param source the flow (compared by identity)
     * @return whether it was held
     */
    public boolean remove(WindSource source) {
        for (int i = 0; i < count; i++) {
            if (flows[i] == source) {
                removeAt(i);
                return true;
            }
        }
        return false;
    }

    private void removeAt(int i) {
        if (flows[i].weight(time) > 0) {
            noteSwitch();
        }
        int tail = count - i - 1;
        System.arraycopy(flows, i + 1, flows, i, tail);
        System.arraycopy(oneShot, i + 1, oneShot, i, tail);
        System.arraycopy(wasEnabled, i + 1, wasEnabled, i, tail);
        count--;
        flows[count] = null;
    }

    /**
     * Agents: attaches a flow to a moving entity (character, vehicle). The game calls
     * {@link WindSource#setCentre(double, double)} every frame with the entity's position and
     * {@link #remove(WindSource)} when it goes. {@code def.motion()} must be FIXED. Allocates.
     *
     * @param def the agent's flow, e.g. a SOURCE around a character
     * @return the new flow, to move with {@link WindSource#setCentre(double, double)}
     * @throws IllegalArgumentException when the motion is not FIXED or the id is already held
     */
    public WindSource attachAgent(FlowDef def) {
        Require.nonNull("def", def);
        if (def.motion().kind() != MotionDef.Kind.FIXED) {
            throw new IllegalArgumentException("an agent's motion must be FIXED (the game moves it), got "
                    + def.motion().kind());
        }
        return add(def);
    }

    /**
     * An explosion at (x, z) now: a {@link BlastFlow} of strength a (m^2/s, &gt; 0) lasting
     * {@code duration} seconds (&gt; 0), removed automatically once over. Allocates.
     *
     * @param id       unique flow id
     * @param x        centre X, metres
     * @param z        centre Z, metres
     * @param strength m^2/s, &gt; 0
     * @param duration seconds, &gt; 0
     * @return the new flow
     * @throws IllegalArgumentException when a value is out of range or the id is already held
     */
    public WindSource blast(String id, double x, double z, double strength, double duration) {
        ActivationDef act = new ActivationDef(time, Require.positive("duration", duration), 0, 0);
        FlowDef def = new FlowDef(id, FlowKind.BLAST, true, x, z, Require.positive("strength", strength), 0,
                FlowDef.DEFAULT_CORE_RADIUS, Double.POSITIVE_INFINITY, act, MotionDef.FIXED,
                FlowDef.DEFAULT_NOISE_SCALE, FlowDef.DEFAULT_NOISE_FREQUENCY, 0, FlowDef.DEFAULT_GUST_STRENGTH,
                FlowDef.DEFAULT_TURBULENCE);
        return add(WindSource.of(def), true);
    }

    /**
     * A rain shower over the disc of centre (x, z) and {@code radius} metres starting now, as
     * short seeded impulses ({@link RainFlow}), removed automatically after {@code duration}
     * seconds (or never, for +Infinity). Allocates.
     *
     * @param id         unique flow id
     * @param x          disc centre X, metres
     * @param z          disc centre Z, metres
     * @param radius     disc radius, metres, &gt; 0
     * @param strength   impulse strength, m^2/s, &gt; 0
     * @param spacing    cell size between impulses, metres, &gt; 0
     * @param rate       impulses per second per m^2, &gt; 0
     * @param duration   seconds, &gt; 0, or +Infinity for a shower that never stops
     * @param seed       seed of the impulses
     * @return the new flow
     * @throws IllegalArgumentException when a value is out of range or the id is already held
     */
    public WindSource rain(String id, double x, double z, double radius, double strength, double spacing,
                           double rate, double duration, long seed) {
        ActivationDef act = new ActivationDef(time, duration, 0, 0);
        FlowDef def = new FlowDef(id, FlowKind.RAIN, true, x, z, Require.positive("strength", strength), 0,
                FlowDef.DEFAULT_CORE_RADIUS, Require.positive("radius", radius), act, MotionDef.FIXED,
                spacing, rate, seed, FlowDef.DEFAULT_GUST_STRENGTH, FlowDef.DEFAULT_TURBULENCE);
        return add(WindSource.of(def), true);
    }

    /**
     * Advances the clock by {@code dt} seconds (finite, &gt;= 0) and moves the centres: PATH flows
     * to their scripted position at the new time; ADVECTED flows by Euler integration of the sum
     * of the <i>other</i> flows' velocities at their centre at the old time (all advected flows
     * read the same state, so the result does not depend on flow order). Then every flow, in order,
     * is told the new time ({@link WindSource#onAdvance}). Blasts and showers made by {@link #blast}
     * and {@link #rain} are removed once their window has ended. No allocation.
     *
     * @param dt seconds, finite, &gt;= 0
     */
    public void advance(double dt) {
        Require.nonNegative("dt", dt);
        double t0 = time;
        double edge = advanced ? pendingEdge : Double.NaN;
        pendingEdge = Double.NaN;
        for (int i = 0; i < count; i++) {
            boolean on = flows[i].isEnabled();
            if (on != wasEnabled[i] && advanced) {
                edge = FlowEdges.earliest(edge, t0);
            }
            wasEnabled[i] = on;
        }
        for (int i = 0; i < count; i++) {
            if (flows[i] instanceof FlowBase f && f.def.motion().kind() == MotionDef.Kind.ADVECTED) {
                velocityExcept(f.cx, f.cz, f, adv);
                advX[i] = adv.x;
                advZ[i] = adv.y;
            }
        }
        time += dt;
        for (int i = 0; i < count; i++) {
            if (flows[i] instanceof FlowBase f) {
                MotionDef.Kind k = f.def.motion().kind();
                if (k == MotionDef.Kind.ADVECTED) {
                    f.cx += advX[i] * dt;
                    f.cz += advZ[i] * dt;
                } else if (k == MotionDef.Kind.PATH) {
                    f.placeOnPath(time);
                }
            }
            flows[i].onAdvance(time, dt);
            if (wasEnabled[i]) {
                edge = FlowEdges.windowEdge(flows[i], t0, time, edge);
            }
        }
        lastEdge = edge;
        advanced = true;
        for (int i = count - 1; i >= 0; i--) {
            if (oneShot[i] && flows[i].expired(time)) {
                removeAt(i);
            }
        }
    }

    /**
     * The earliest time within the last {@link #advance}, from the time before it to the time after
     * it, at which the sum of the flows may jump: a flow added, removed, enabled or disabled since the
     * advance before (reported at the time before this one), or an activation window of a built-in
     * flow or an {@link AbstractWindSource} opening or closing without a ramp. NaN when there was
     * none, and before the first advance. Owner thread; no allocation.
     *
     * @return seconds of simulation time, or NaN
     */
    public double lastEdge() {
        return lastEdge;
    }

    /** Notes that the sum changes now (a flow added or removed), once the field has been advanced. */
    private void noteSwitch() {
        if (advanced) {
            pendingEdge = FlowEdges.earliest(pendingEdge, time);
        }
    }

    /**
     * Writes the sum of every enabled, active flow's velocity (m/s; x = X, y = Z) at ground point
     * (x, z) at the current time into dest. Linear superposition. No allocation.
     *
     * @param x    ground point X, metres
     * @param z    ground point Z, metres
     * @param dest where to write
     * @return {@code dest}
     */
    public Vector2d velocity(double x, double z, Vector2d dest) {
        return velocityExcept(x, z, null, dest);
    }

    /**
     * Like {@link #velocity} but leaves out {@code skip}. No allocation.
     *
     * @param x    ground point X, metres
     * @param z    ground point Z, metres
     * @param skip the flow to leave out (compared by identity), or null for none
     * @param dest where to write (m/s; x = X, y = Z)
     * @return {@code dest}
     */
    public Vector2d velocityExcept(double x, double z, WindSource skip, Vector2d dest) {
        double sx = 0;
        double sz = 0;
        Vector2d t = tmp;
        for (int i = 0; i < count; i++) {
            WindSource f = flows[i];
            if (f == skip) {
                continue;
            }
            if (f instanceof FlowBase b) {
                b.velocity(x, z, time, t); // the built-ins: one final method, no interface dispatch
            } else {
                f.velocity(x, z, time, t);
            }
            sx += t.x;
            sz += t.y;
        }
        return dest.set(sx, sz);
    }

    /**
     * The speed of the small eddies the flows declare now, m/s: the sum over GUST flows of
     * {@code turbulence x strength x weight} (see {@link GustFlow}). A force field that samples the
     * wind at nodes wider than these eddies may add them per plant (the quadtree field's flutter).
     * Owner thread; no allocation.
     *
     * @return m/s, &gt;= 0
     */
    public double eddySpeed() {
        return FlowSums.eddySpeed(flows, count, time);
    }

    /**
     * The velocity at which the gusts travel over the ground now (m/s; x = X, y = Z): the mean wind of
     * the GUST flows ({@link GustFlow#travel}), their weights' mean when several are active (frozen
     * turbulence: a gust front crosses the ground at the wind's speed). Zero without an active GUST flow.
     * What an on-screen measure of travelling gusts compares with. Owner thread; no allocation.
     *
     * @param dest where to write
     * @return {@code dest}
     */
    public Vector2d gustTravel(Vector2d dest) {
        return FlowSums.gustTravel(flows, count, time, dest);
    }

    /**
     * Whether flows of this kind flatten the plants they push hard enough (trails,
     * {@code org.jecosys.plant.TrailDef}): the point flows, what an agent, a blast or a whirl does
     * (SOURCE, SINK, VORTEX, BLAST), not the ambient wind or rain (UNIFORM, GUST, RAIN), however
     * strong its gusts. Any thread; no allocation.
     *
     * @param kind a flow kind
     * @return whether it flattens
     */
    public static boolean flattens(FlowKind kind) {
        return kind == FlowKind.SOURCE || kind == FlowKind.SINK || kind == FlowKind.VORTEX || kind == FlowKind.BLAST;
    }

    /**
     * {@return the number of flows that flatten ({@link #flattens}) and act now (enabled, weight &gt; 0)}
     * Owner thread; no allocation.
     */
    public int flatteningCount() {
        return FlowSums.flatteningCount(flows, count, time);
    }

    /**
     * Writes the sum of the velocities (m/s; x = X, y = Z) of the flows that flatten ({@link #flattens})
     * at ground point (x, z) at the current time into dest: the push that may leave a trail, evaluated
     * exactly rather than through a force field's nodes. Owner thread; no allocation.
     *
     * @param x    ground point X, metres
     * @param z    ground point Z, metres
     * @param dest where to write
     * @return {@code dest}
     */
    public Vector2d flatteningVelocity(double x, double z, Vector2d dest) {
        return FlowSums.flatteningVelocity(flows, count, time, x, z, tmp, dest);
    }

    /** {@return the number of flows enabled and inside their activation window now (weight &gt; 0)} No allocation. */
    public int activeCount() {
        int n = 0;
        for (int i = 0; i < count; i++) {
            if (flows[i].weight(time) > 0) {
                n++;
            }
        }
        return n;
    }
}
