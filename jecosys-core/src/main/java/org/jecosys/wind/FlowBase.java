package org.jecosys.wind;

import org.jecosys.math.Require;
import org.joml.Vector2d;

/**
 * What the built-in flows add to {@link AbstractWindSource} (id, enabled switch, activation window,
 * centre, influence radius and the weighting of {@code velocity}, shared with user flows): their
 * definition, core radius and scripted path. Each kind only adds its formula ({@link #unweighted}),
 * which applies the influence radius itself. {@link WindField} moves the centres of these flows
 * (PATH and ADVECTED motion). Not thread-safe; no allocation after construction.
 */
abstract sealed class FlowBase extends AbstractWindSource
        permits UniformFlow, SourceFlow, VortexFlow, GustFlow, BlastFlow, RainFlow {
    final FlowDef def;
    final double coreRadius;
    private final double[] pathLength;
    private final double[] pathX;
    private final double[] pathZ;

    FlowBase(FlowDef def) {
        super(Require.nonNull("def", def), start(def, true), start(def, false));
        this.def = def;
        this.coreRadius = def.coreRadius();
        MotionDef m = def.motion();
        if (m.kind() == MotionDef.Kind.PATH) {
            int n = m.waypoints().size();
            pathX = new double[n];
            pathZ = new double[n];
            pathLength = new double[n];
            for (int i = 0; i < n; i++) {
                pathX[i] = m.waypoints().get(i).x();
                pathZ[i] = m.waypoints().get(i).z();
                if (i > 0) {
                    pathLength[i] = pathLength[i - 1] + Math.hypot(pathX[i] - pathX[i - 1], pathZ[i] - pathZ[i - 1]);
                }
            }
        } else {
            pathX = null;
            pathZ = null;
            pathLength = null;
        }
    }

    /** The centre a flow starts at, X (or Z): its path's first waypoint, or its definition's centre. */
    private static double start(FlowDef def, boolean x) {
        MotionDef m = def.motion();
        if (m.kind() == MotionDef.Kind.PATH) {
            return x ? m.waypoints().get(0).x() : m.waypoints().get(0).z();
        }
        return x ? def.x() : def.z();
    }

    @Override
    public final FlowDef def() {
        return def;
    }

    @Override
    public final FlowKind kind() {
        return def.kind();
    }

    @Override
    protected final void flow(double x, double z, double time, Vector2d dest) {
        unweighted(x, z, time, dest);
    }

    /** The flow's own formula at full strength, written into dest (x = X, y = Z), m/s. */
    abstract void unweighted(double x, double z, double time, Vector2d dest);

    /** Whether this flow's centre moves along a scripted path. */
    final boolean hasPath() {
        return pathLength != null;
    }

    /**
     * Places the centre on the scripted path at time {@code time}: arc length
     * {@code speed * (time - start)} from the first waypoint, wrapped when looping, clamped at the
     * last waypoint otherwise. A pure function of time (no drift). No allocation.
     */
    final void placeOnPath(double time) {
        MotionDef m = def.motion();
        int n = pathLength.length;
        double total = pathLength[n - 1];
        double s = m.speed() * Math.max(0, time - def.activation().start());
        if (total <= 0) {
            cx = pathX[0];
            cz = pathZ[0];
            return;
        }
        if (m.loop()) {
            s = s % total;
        } else if (s >= total) {
            cx = pathX[n - 1];
            cz = pathZ[n - 1];
            return;
        }
        int i = 1;
        while (i < n - 1 && pathLength[i] < s) {
            i++;
        }
        double seg = pathLength[i] - pathLength[i - 1];
        double f = seg > 0 ? (s - pathLength[i - 1]) / seg : 0;
        cx = pathX[i - 1] + (pathX[i] - pathX[i - 1]) * f;
        cz = pathZ[i - 1] + (pathZ[i] - pathZ[i - 1]) * f;
    }

    /**
     * The shared kernel of point flows: writes {@code k * (dx, dz) / max(r, core)^2} into dest, or
     * 0 beyond the influence radius. Inside the core the magnitude tapers linearly to exactly 0 at
     * the centre (Rankine core), so the result is finite everywhere.
     */
    final void radial(double dx, double dz, double k, Vector2d dest) {
        double r2 = dx * dx + dz * dz;
        if (r2 > influenceRadius2) {
            dest.set(0, 0);
            return;
        }
        double d2 = Math.max(r2, coreRadius * coreRadius);
        double f = k / d2;
        dest.set(f * dx, f * dz);
    }
}
