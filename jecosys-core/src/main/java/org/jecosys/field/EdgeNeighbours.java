package org.jecosys.field;

import java.util.Arrays;

/**
 * The edge neighbours of {@link QuadtreeForceField}'s effective nodes (the nodes its gradients fit to),
 * kept from one update to the next while the cut stays the same. The neighbour of a ground point is
 * found by descending the visible nodes at or above the cut; so while those nodes (recorded in visiting
 * order by {@link #visited}) are the same as at the last update, every neighbour is too, and the four
 * an effective node looked up last time ({@link #probes()}, at 4 x its place among the effective
 * nodes) are still right. Changes to the tree ({@link #invalidate}) make the next update look them up
 * again. Single owner thread; allocates in {@link #resize} only.
 */
final class EdgeNeighbours {
    private int[] top = new int[0];
    private int[] topBefore = new int[0];
    private int topCount;
    private int topBeforeCount;
    private int[] probes = new int[0];
    private boolean valid;
    private long reuses;

    /** Room for a tree of {@code nodes} nodes; forgets what it kept. Allocates. */
    void resize(int nodes) {
        top = new int[nodes];
        topBefore = new int[nodes];
        topCount = 0;
        topBeforeCount = 0;
        probes = new int[4 * nodes];
        valid = false;
    }

    /** The tree changed (a plant added or moved): the next update looks every neighbour up again. */
    void invalidate() {
        valid = false;
    }

    /** An update begins: no node visited yet. */
    void begin() {
        topCount = 0;
    }

    /** Node n is visible and at or above the cut (visiting order). */
    void visited(int n) {
        top[topCount++] = n;
    }

    /**
     * After the visit: whether the cut is the last update's, so {@link #probes()} still hold; then this
     * update's cut becomes the one the next compares with. No allocation.
     */
    boolean keep() {
        boolean same = valid && topCount == topBeforeCount && Arrays.equals(top, 0, topCount, topBefore, 0, topCount);
        reuses += same ? 1 : 0;
        int[] swap = topBefore;
        topBefore = top;
        top = swap;
        topBeforeCount = topCount;
        valid = true;
        return same;
    }

    /** {@return per effective node (4 x its place among them) its four edge neighbours: the caller fills or reads them} */
    int[] probes() {
        return probes;
    }

    /** {@return how many updates kept the neighbours of the one before} */
    long reuses() {
        return reuses;
    }
}
