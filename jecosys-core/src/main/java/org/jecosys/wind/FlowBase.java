package org.jecosys.wind;

import org.jecosys.math.Require;
import org.joml.Vector2d;

/**
 * State every built-in flow shares: definition, enabled switch, activation window, centre and
 * scripted path. One level of inheritance; each kind only adds its formula ({@link #unweighted}).
 * {@link WindField} moves the centres of these flows itself (PATH and ADVECTED motion); user flows
 * extend {@link AbstractWindSource} instead. Not thread-safe; no allocation after construction.
 */
abstract sealed class FlowBase implements WindSource
        permits UniformFlow, SourceFlow, VortexFlow, GustFlow, BlastFlow, RainFlow {
    final FlowDef def;
    private boolean enabled;
    double cx;
    double cz;
    final double influenceRadius2;
    final double coreRadius;
    /** Cumulative arc length at each waypoint of a PATH motion (null otherwise). */
    private final double[] pathLength;
    private final double[] pathX;
    private final double[] pathZ;

    FlowBase(FlowDef def) {
        this.def = Require.nonNull("def", def);
        this.enabled = def.enabled();
        this.cx = def.x();
        this.cz = def.z();
        this.coreRadius = def.coreRadius();
        double r = def.influenceRadius();
        this.influenceRadius2 = r == Double.POSITIVE_INFINITY ? Double.POSITIVE_INFINITY : r * r;
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
            cx = pathX[0];
            cz = pathZ[0];
        } else {
            pathX = null;
            pathZ = null;
            pathLength = null;
        }
    }

    @Override
    public final FlowDef def() {
        return def;
    }

    @Override
    public final String id() {
        return def.id();
    }

    @Override
    public final FlowKind kind() {
        return def.kind();
    }

    @Override
    public final boolean isEnabled() {
        return enabled;
    }

    @Override
    public final void setEnabled(boolean enabled) {
        this.enabled = enabled;
    }

    @Override
    public final double centreX() {
        return cx;
    }

    @Override
    public final double centreZ() {
        return cz;
    }

    @Override
    public final void setCentre(double x, double z) {
        cx = Require.finite("x", x);
        cz = Require.finite("z", z);
    }

    @Override
    public final double weight(double time) {
        return enabled ? def.activation().weight(time) : 0;
    }

    @Override
    public final boolean expired(double time) {
        return def.activation().expired(time);
    }

    @Override
    public final double influenceRadius() {
        return def.influenceRadius();
    }

    @Override
    public final Vector2d velocity(double x, double z, double time, Vector2d dest) {
        double w = weight(time);
        if (w == 0) {
            return dest.set(0, 0);
        }
        unweighted(x, z, time, dest);
        return dest.set(dest.x * w, dest.y * w);
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
