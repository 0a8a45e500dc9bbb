package org.jecosys.plant;

/**
 * How a component's mesh ({@link MeshDef}) follows the component's animated skeleton.
 */
public enum MeshMode {
    /**
     * Bound along the skeleton: the mesh's height (its lowest to its highest point along +Y) spans
     * the skeleton from base to tip, and each vertex follows the bent skeleton at its own height, its
     * X and Z offsets along the skeleton's side and face normal there. A modelled leaf or a grass card
     * bends with the pose table like the component's own strip.
     */
    BOUND("bound"),
    /**
     * Rigid, riding a skeleton's tip: the mesh's origin sits on the tip, its +Y along the last segment,
     * +X along the side and +Z along the face normal there; it turns with the tip and keeps its shape.
     * On a component attached to another ({@code attachTo}) it rides the parent's point it sits on, the tip unless
     * {@code attachAt} says otherwise (a flower head
     * on its stalk); on a component on the ground, its own tip.
     */
    RIGID("rigid");

    private final String xmlName;

    MeshMode(String xmlName) {
        this.xmlName = xmlName;
    }

    /** {@return the attribute value in scene files: {@code "bound"} or {@code "rigid"}} */
    public String xmlName() {
        return xmlName;
    }
}
