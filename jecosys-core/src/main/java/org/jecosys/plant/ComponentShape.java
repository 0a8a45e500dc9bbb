package org.jecosys.plant;

/**
 * How triangles and lines are generated from a component's skeleton points (paper §4.1).
 * The exact primitive counts per shape are documented on the mesh builder.
 */
public enum ComponentShape {
    /** A ribbon along the skeleton: two vertices per skeleton point (left and right edge). */
    STRIP("strip"),
    /** A fan around the skeleton's first point, for flower heads and discs. */
    FAN("fan");

    private final String xmlName;

    ComponentShape(String xmlName) {
        this.xmlName = xmlName;
    }

    /** {@return the attribute value used in scene files: {@code "strip"} or {@code "fan"}} */
    public String xmlName() {
        return xmlName;
    }
}
