package org.jecosys.field;

/**
 * Counters of the last {@link ForceField#update} (paper §3.1.1: what the LOD spares). A live view
 * overwritten by each update; read it on the field's owner thread. No method allocates.
 */
public final class FieldCounters {
    int nodes;
    int leaves;
    int visibleNodes;
    int visibleLeaves;
    int effectiveNodes;
    int flowEvaluations;

    /** All zero, never written: the counters of a field that does not count ({@link ForceField#counters()}). */
    public static final FieldCounters NONE = new FieldCounters();

    FieldCounters() {
    }

    /** {@return the number of nodes of the tree} */
    public int nodes() {
        return nodes;
    }

    /** {@return the number of leaves of the tree} */
    public int leaves() {
        return leaves;
    }

    /** {@return the number of nodes that passed the frustum test (those inside collapsed subtrees included)} */
    public int visibleNodes() {
        return visibleNodes;
    }

    /** {@return the number of visible leaves: the effective nodes full resolution would have} */
    public int visibleLeaves() {
        return visibleLeaves;
    }

    /**
     * {@return the number of nodes whose wind represents a visible area (visible leaves, or ancestors
     * standing for them)}
     */
    public int effectiveNodes() {
        return effectiveNodes;
    }

    /**
     * Evaluations of the summed flows: one per effective node holding at least one plant
     * (0 when the field is disabled). Each is a sum over every flow of the wind field.
     *
     * @return evaluations in the last update, &gt;= 0
     */
    public int flowEvaluations() {
        return flowEvaluations;
    }

    @Override
    public String toString() {
        return "nodes=" + nodes + " leaves=" + leaves + " visibleNodes=" + visibleNodes + " visibleLeaves="
                + visibleLeaves + " effectiveNodes=" + effectiveNodes + " flowEvaluations=" + flowEvaluations;
    }
}
