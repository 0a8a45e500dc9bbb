package org.jecosys.app;

import java.util.function.Predicate;
import org.jecosys.render.overlay.GizmoKind;
import org.jecosys.render.overlay.Gizmos;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindField;
import org.jecosys.wind.WindSource;

/**
 * Turns the running flows and agents into {@link Gizmos} for {@link org.jecosys.render.overlay.GizmoRenderer}
 * (one per flow of the {@link WindField}, blasts and a program's own flows included), and remembers
 * which flow each gizmo stands for, for picking. A gizmo sits at its flow's current centre (so a
 * flow walking a path or advected by the others is seen where it is); its colour shows the flow's
 * switch and activation weight now. Uniform and gust flows have no centre that matters to the wind:
 * theirs is where the scene puts their gizmo, and gizmos that would sit on top of one another are
 * spread along +X so each can be picked. Render thread; allocates only when the list grows.
 */
final class FlowGizmos {
    private final Gizmos gizmos = new Gizmos();
    private final Heightfield ground;
    private final double spread;
    private WindSource[] sources = new WindSource[16];

    FlowGizmos(Heightfield ground) {
        this.ground = ground;
        this.spread = 0.05 * Math.min(ground.sizeX(), ground.sizeZ());
    }

    /** {@return the gizmos of the last {@link #fill}} */
    Gizmos gizmos() {
        return gizmos;
    }

    /** {@return the flow gizmo i stands for} */
    WindSource source(int i) {
        return sources[i];
    }

    /** {@return the gizmo index of {@code w} in the last fill, or -1} */
    int indexOf(WindSource w) {
        for (int i = 0; i < gizmos.size(); i++) {
            if (sources[i] == w) {
                return i;
            }
        }
        return -1;
    }

    /** The gizmo kind of a flow: its own kind, AGENT for an agent, USER for a program's own flow. */
    static GizmoKind kind(WindSource w, boolean agent) {
        if (agent) {
            return GizmoKind.AGENT;
        }
        FlowKind k = w.kind();
        if (k == null) {
            return GizmoKind.USER;
        }
        return switch (k) {
            case UNIFORM -> GizmoKind.UNIFORM;
            case GUST -> GizmoKind.GUST;
            case SOURCE -> GizmoKind.SOURCE;
            case SINK -> GizmoKind.SINK;
            case VORTEX -> GizmoKind.VORTEX;
            case BLAST -> GizmoKind.BLAST;
            case RAIN -> GizmoKind.RAIN;
        };
    }

    /**
     * Fills the gizmos from the flows now.
     *
     * @param wind     the running flows
     * @param isAgent  which flows are agents
     * @param selected the selected flow, or null
     * @param hovered  the flow under the pointer, or null
     */
    void fill(WindField wind, Predicate<WindSource> isAgent, WindSource selected, WindSource hovered) {
        gizmos.clear();
        double time = wind.time();
        for (int i = 0; i < wind.size(); i++) {
            WindSource w = wind.get(i);
            FlowDef d = w.def();
            GizmoKind kind = kind(w, isAgent.test(w));
            double x = w.centreX();
            double z = w.centreZ();
            if (kind == GizmoKind.UNIFORM || kind == GizmoKind.GUST) {
                x = free(x, z);
            }
            if (!ground.contains(x, z)) {
                x = Math.max(ground.minX(), Math.min(ground.maxX(), x));
                z = Math.max(ground.minZ(), Math.min(ground.maxZ(), z));
            }
            int g = gizmos.add(kind, x, z, w.influenceRadius(), d == null ? 0 : d.coreRadius());
            if (d != null) {
                gizmos.direction(g, d.direction());
                if (d.kind() == FlowKind.VORTEX) {
                    gizmos.spin(g, d.strength() >= 0 ? 1 : -1);
                }
            }
            gizmos.state(g, w.isEnabled(), w.weight(time));
            gizmos.highlight(g, w == selected ? Gizmos.SELECTED : w == hovered ? Gizmos.HOVERED : Gizmos.NORMAL);
            if (g == sources.length) {
                sources = java.util.Arrays.copyOf(sources, 2 * g);
            }
            sources[g] = w;
        }
        for (int i = gizmos.size(); i < sources.length && sources[i] != null; i++) {
            sources[i] = null;
        }
    }

    /** X moved along +X past any gizmo already within {@code spread} of (x, z). */
    private double free(double x, double z) {
        for (int tries = 0; tries < 16; tries++) {
            boolean clear = true;
            for (int i = 0; i < gizmos.size(); i++) {
                if (Math.abs(gizmos.x(i) - x) < spread && Math.abs(gizmos.z(i) - z) < spread) {
                    clear = false;
                    break;
                }
            }
            if (clear) {
                return x;
            }
            x += spread;
        }
        return x;
    }
}
