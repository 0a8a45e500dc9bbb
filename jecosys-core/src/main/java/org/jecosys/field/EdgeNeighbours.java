package org.jecosys.field;

import java.util.Arrays;

/**
 * The edge neighbours of {@link QuadtreeForceField}'s effective nodes (the nodes its gradients fit to),
 * kept from one update to the next while the cut stays the same. The neighbour of a ground point is
 * found by descending the visible nodes at or above the cut; so while those nodes (recorded in visiting
 * order by {@link #visited}) are the same as at the last update, every neighbour is too, and the four
 * an effective node looked up last time ({@link #probes()}, at 4 x its place among the effective
 * nodes) are still right. Changes to the tree ({@link #invalidate}) make the next update look them up
 * again. The look-up itself ({@link #lookUp}) descends the field's visible nodes. Single owner thread;
 * allocates in {@link #resize} only.
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

    /**
     * Looks up the four edge neighbours of effective node n of tree t into {@link #probes()}, from
     * {@code o} on: the effective node holding the point just outside the middle of each edge (+X, -X,
     * +Z, -Z), level with its plants' centre of gravity (cx, cz), metres. The field's arrays of the
     * update say where a descent stops: {@code stamp[m] == current} for a node visible now, {@code rep[m]}
     * its effective node (or below 0 above the cut). No allocation.
     */
    void lookUp(Quadtree t, int n, int o, float cx, float cz, int[] stamp, int[] rep, int current) {
        // the node at the middle of each edge, just outside (a centroid is a function of the tree alone)
        double ex = 1e-4 * (t.maxX[n] - t.minX[n]);
        double ez = 1e-4 * (t.maxZ[n] - t.minZ[n]);
        probes[o] = holder(t, t.maxX[n] + ex, cz, stamp, rep, current);
        probes[o + 1] = holder(t, t.minX[n] - ex, cz, stamp, rep, current);
        probes[o + 2] = holder(t, cx, t.maxZ[n] + ez, stamp, rep, current);
        probes[o + 3] = holder(t, cx, t.minZ[n] - ez, stamp, rep, current);
    }

    /**
     * The effective node of the update (arrays as {@link #lookUp}) holding ground point (x, z), metres, or
     * -1 (outside, invisible).
     */
    private static int holder(Quadtree t, double x, double z, int[] stamp, int[] rep, int current) {
        if (!(x >= t.minX[0] && x <= t.maxX[0] && z >= t.minZ[0] && z <= t.maxZ[0])) {
            return -1;
        }
        int m = 0;
        while (stamp[m] == current) {
            if (rep[m] >= 0) {
                return rep[m];
            }
            int fc = t.firstChild[m];
            if (fc < 0) {
                return -1;
            }
            float mx = (t.minX[m] + t.maxX[m]) * 0.5f;
            float mz = (t.minZ[m] + t.maxZ[m]) * 0.5f;
            m = fc + (x >= mx ? 1 : 0) + (z >= mz ? 2 : 0);
        }
        return -1;
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
