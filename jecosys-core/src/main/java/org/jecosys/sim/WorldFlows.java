package org.jecosys.sim;

import java.util.Arrays;
import org.jecosys.math.Require;
import org.jecosys.math.Waypoint;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.jecosys.wind.WindSource;

/**
 * The flows an {@link OpenWorld} adds at run time (beyond its def's): kept as defs, since each tile's
 * simulation holds its own instance of every flow, with each agent's latest position. A tile gets them
 * all when it starts ({@link #startTile}); a change goes to every live tile as a command of its
 * simulation, applied at its next step, so all tiles see it at the same step. Stepping thread only.
 * Adding and removing allocate; {@link #move} allocates nothing after a flow's first move in a tile.
 */
final class WorldFlows {
    private FlowDef[] defs = new FlowDef[4];
    private double[] x = new double[4];
    private double[] z = new double[4];
    private boolean[] moved = new boolean[4];
    /** For blasts, the time after which they are dropped (their window has ended); +Infinity for the rest. */
    private double[] ends = new double[4];
    private int count;

    /** {@return the flows added at run time and not removed} */
    int count() {
        return count;
    }

    /** The index of flow {@code id}, or -1. */
    int indexOf(String id) {
        for (int k = 0; k < count; k++) {
            if (defs[k].id().equals(id)) {
                return k;
            }
        }
        return -1;
    }

    /** Adds a flow: to this list and to every live tile. */
    void add(FlowDef def, double end, WorldTile[] live, int n, SimulationDef world) {
        Require.nonNull("def", def);
        if (indexOf(def.id()) >= 0) {
            throw new IllegalArgumentException("a flow with id '" + def.id() + "' is already in the open world");
        }
        for (FlowDef f : world.flows()) {
            if (f.id().equals(def.id())) {
                throw new IllegalArgumentException("the scene's flow '" + def.id() + "' already has this id");
            }
        }
        if (count + world.flows().size() >= Simulation.MAX_FLOWS) {
            throw new IllegalStateException("an open world holds at most " + Simulation.MAX_FLOWS + " flows");
        }
        if (count == defs.length) {
            defs = Arrays.copyOf(defs, 2 * count);
            x = Arrays.copyOf(x, 2 * count);
            z = Arrays.copyOf(z, 2 * count);
            moved = Arrays.copyOf(moved, 2 * count);
            ends = Arrays.copyOf(ends, 2 * count);
        }
        defs[count] = def;
        x[count] = def.x();
        z[count] = def.z();
        moved[count] = false;
        ends[count] = end;
        count++;
        for (int k = 0; k < n; k++) {
            live[k].handles = append(live[k].handles, count - 1, live[k].simulation().addFlow(def));
        }
    }

    /** Removes flow k: from this list and from every live tile. */
    void remove(int k, WorldTile[] live, int n) {
        for (int t = 0; t < n; t++) {
            WindSource[] h = live[t].handles;
            live[t].simulation().removeFlow(h[k]);
            System.arraycopy(h, k + 1, h, k, count - k - 1);
            h[count - 1] = null;
        }
        int tail = count - k - 1;
        System.arraycopy(defs, k + 1, defs, k, tail);
        System.arraycopy(x, k + 1, x, k, tail);
        System.arraycopy(z, k + 1, z, k, tail);
        System.arraycopy(moved, k + 1, moved, k, tail);
        System.arraycopy(ends, k + 1, ends, k, tail);
        count--;
        defs[count] = null;
    }

    /** Moves flow k's centre in every live tile (and in the tiles that start later). */
    void move(int k, double px, double pz, WorldTile[] live, int n) {
        Require.range("x", px, -Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE);
        Require.range("z", pz, -Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE);
        x[k] = px;
        z[k] = pz;
        moved[k] = true;
        for (int t = 0; t < n; t++) {
            live[t].simulation().moveAgent(live[t].handles[k], px, pz);
        }
    }

    /** Drops the blasts whose window ended before {@code time}. */
    void expire(double time, WorldTile[] live, int n) {
        for (int k = count - 1; k >= 0; k--) {
            if (ends[k] < time) {
                remove(k, live, n);
            }
        }
    }

    /** Gives a tile that starts now every flow, each agent at its latest position. */
    void startTile(WorldTile t) {
        t.handles = new WindSource[Math.max(4, count)];
        for (int k = 0; k < count; k++) {
            t.handles[k] = t.simulation().addFlow(defs[k]);
            if (moved[k]) {
                t.simulation().moveAgent(t.handles[k], x[k], z[k]);
            }
        }
    }

    /** The def of a blast at (px, pz) starting at {@code time} (as {@code WindField.blast} makes it). */
    static FlowDef blast(String id, double px, double pz, double strength, double duration, double time) {
        ActivationDef act = new ActivationDef(time, Require.positive("duration", duration), 0, 0);
        return new FlowDef(id, FlowKind.BLAST, true, px, pz, Require.positive("strength", strength), 0,
                FlowDef.DEFAULT_CORE_RADIUS, Double.POSITIVE_INFINITY, act, MotionDef.FIXED,
                FlowDef.DEFAULT_NOISE_SCALE, FlowDef.DEFAULT_NOISE_FREQUENCY, 0, FlowDef.DEFAULT_GUST_STRENGTH,
                FlowDef.DEFAULT_TURBULENCE);
    }

    private static WindSource[] append(WindSource[] h, int at, WindSource s) {
        WindSource[] a = at < h.length ? h : Arrays.copyOf(h, 2 * h.length);
        a[at] = s;
        return a;
    }
}
