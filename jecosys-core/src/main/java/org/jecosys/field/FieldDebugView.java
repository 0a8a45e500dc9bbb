package org.jecosys.field;

/**
 * Read-only per-node data of the last {@link ForceField#update}, for the viewer's overlays
 * (paper Figures 2 and 3): bounds, depth, visibility, LOD level used and wind vector of every node.
 * A live view over the field's preallocated arrays (no copy): read it on the field's owner
 * thread, or copy it out before the next update. No method allocates. Node ids are in
 * [0, {@link #nodeCount()}).
 */
public final class FieldDebugView {
    /**
     * A view with no nodes, for fields that have none to show ({@link ForceField#debugView()}); no
     * node id is valid on it.
     */
    public static final FieldDebugView EMPTY = new FieldDebugView(null);

    private final QuadtreeForceField field;

    FieldDebugView(QuadtreeForceField field) {
        this.field = field;
    }

    /** {@return the number of nodes; 0 for {@link #EMPTY}} */
    public int nodeCount() {
        return field == null ? 0 : field.tree().nodeCount();
    }

    /**
     * {@return the node's west edge (lowest X), metres}
     *
     * @param node node id, in [0, nodeCount())
     */
    public float minX(int node) {
        return field.tree().minX(node);
    }

    /**
     * {@return the node's north edge (lowest Z), metres}
     *
     * @param node node id, in [0, nodeCount())
     */
    public float minZ(int node) {
        return field.tree().minZ(node);
    }

    /**
     * {@return the node's east edge (highest X), metres}
     *
     * @param node node id, in [0, nodeCount())
     */
    public float maxX(int node) {
        return field.tree().maxX(node);
    }

    /**
     * {@return the node's south edge (highest Z), metres}
     *
     * @param node node id, in [0, nodeCount())
     */
    public float maxZ(int node) {
        return field.tree().maxZ(node);
    }

    /**
     * {@return the depth of the node (root 0)}
     *
     * @param node node id, in [0, nodeCount())
     */
    public int depth(int node) {
        return field.tree().depth(node);
    }

    /**
     * {@return whether the node is a leaf}
     *
     * @param node node id, in [0, nodeCount())
     */
    public boolean isLeaf(int node) {
        return field.tree().firstChild(node) < 0;
    }

    /**
     * {@return whether the node passed the frustum test (darker areas of Figure 2 are invisible nodes)}
     *
     * @param node node id, in [0, nodeCount())
     */
    public boolean visible(int node) {
        return field.nodeVisible(node);
    }

    /**
     * {@return whether the node is effective: it carries the wind of its visible subtree}
     *
     * @param node node id, in [0, nodeCount())
     */
    public boolean effective(int node) {
        return field.representative(node) == node;
    }

    /**
     * {@return the effective node representing this visible node, or -1 when invisible}
     *
     * @param node node id, in [0, nodeCount())
     */
    public int representative(int node) {
        return field.representative(node);
    }

    /**
     * LOD level used: for an effective node, how many levels of its subtree collapsed into it
     * (its height; 0 for a leaf); for a node inside a collapsed subtree, how many levels up its
     * representative is. -1 when invisible.
     *
     * @param node node id, in [0, nodeCount())
     * @return levels, &gt;= 0, or -1
     */
    public int lodLevel(int node) {
        int r = field.representative(node);
        if (r < 0) {
            return -1;
        }
        Quadtree t = field.tree();
        return r == node ? t.height(node) : t.depth(node) - t.depth(r);
    }

    /**
     * {@return the X of the wind (m/s) the node receives (its representative's), 0 when invisible (Figure 3)}
     *
     * @param node node id, in [0, nodeCount())
     */
    public float windX(int node) {
        return field.nodeWindX(node);
    }

    /**
     * {@return the Z of the wind (m/s) the node receives, 0 when invisible}
     *
     * @param node node id, in [0, nodeCount())
     */
    public float windZ(int node) {
        return field.nodeWindZ(node);
    }
}
