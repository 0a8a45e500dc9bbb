package org.jecosys.field;

/**
 * Read-only per-node data of the last {@link ForceField#update}, for the viewer's overlays
 * (paper Figures 2 and 3): bounds, depth, visibility, LOD level used and wind vector of every node.
 * A live view over the field's preallocated arrays (no copy): read it on the field's owner
 * thread, or copy it out before the next update. No method allocates. Node ids are in
 * [0, {@link #nodeCount()}).
 */
public final class FieldDebugView {
    private final QuadtreeForceField field;

    FieldDebugView(QuadtreeForceField field) {
        this.field = field;
    }

    /** Number of nodes. */
    public int nodeCount() {
        return field.tree().nodeCount();
    }

    /** Node west edge, metres. */
    public float minX(int node) {
        return field.tree().minX(node);
    }

    /** Node north edge, metres. */
    public float minZ(int node) {
        return field.tree().minZ(node);
    }

    /** Node east edge, metres. */
    public float maxX(int node) {
        return field.tree().maxX(node);
    }

    /** Node south edge, metres. */
    public float maxZ(int node) {
        return field.tree().maxZ(node);
    }

    /** Depth of the node (root 0). */
    public int depth(int node) {
        return field.tree().depth(node);
    }

    /** Whether the node is a leaf. */
    public boolean isLeaf(int node) {
        return field.tree().firstChild(node) < 0;
    }

    /** Whether the node passed the frustum test (darker areas of Figure 2 are invisible nodes). */
    public boolean visible(int node) {
        return field.nodeVisible(node);
    }

    /** Whether the node is effective: it carries the wind of its visible subtree. */
    public boolean effective(int node) {
        return field.representative(node) == node;
    }

    /** The effective node representing this visible node, or -1 when invisible. */
    public int representative(int node) {
        return field.representative(node);
    }

    /**
     * LOD level used: for an effective node, how many levels of its subtree collapsed into it
     * (its height; 0 for a leaf); for a node inside a collapsed subtree, how many levels up its
     * representative is. -1 when invisible.
     */
    public int lodLevel(int node) {
        int r = field.representative(node);
        if (r < 0) {
            return -1;
        }
        Quadtree t = field.tree();
        return r == node ? t.height(node) : t.depth(node) - t.depth(r);
    }

    /** X of the wind (m/s) the node receives (its representative's), 0 when invisible (Figure 3). */
    public float windX(int node) {
        return field.nodeWindX(node);
    }

    /** Z of the wind (m/s) the node receives, 0 when invisible. */
    public float windZ(int node) {
        return field.nodeWindZ(node);
    }
}
