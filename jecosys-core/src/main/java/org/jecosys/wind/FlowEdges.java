package org.jecosys.wind;

/**
 * Where in an advance of the {@link WindField} the sum of the flows may jump (its
 * {@link WindField#lastEdge}): static helpers, no state, no allocation.
 */
final class FlowEdges {
    private FlowEdges() {
    }

    /** {@return the earlier of a (NaN: none) and b} */
    static double earliest(double a, double b) {
        return Double.isNaN(a) ? b : Math.min(a, b);
    }

    /** The earlier of {@code edge} and an unramped opening or closing of the flow's window in (t0, t1]. */
    static double windowEdge(WindSource f, double t0, double t1, double edge) {
        ActivationDef a = f instanceof FlowBase b ? b.def.activation()
                : f instanceof AbstractWindSource u ? u.activation() : null;
        if (a == null) {
            return edge;
        }
        double start = a.start();
        if (a.rampIn() == 0 && start > t0 && start <= t1) {
            edge = earliest(edge, start);
        }
        double end = start + a.duration();
        if (a.duration() != Double.POSITIVE_INFINITY && a.rampOut() == 0 && end > t0 && end <= t1) {
            edge = earliest(edge, end);
        }
        return edge;
    }
}
