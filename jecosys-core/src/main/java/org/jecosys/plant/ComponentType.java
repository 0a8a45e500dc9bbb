package org.jecosys.plant;

/** What a plant component is; it chooses defaults and how the viewer colours it (paper §4.1). */
public enum ComponentType {
    /** A grass blade or leaf: a strip narrowing to its tip. */
    LEAF("leaf"),
    /** A flower petal. */
    PETAL("petal"),
    /** A flower head (disc). */
    HEAD("head"),
    /** A stalk carrying other components at its tip. */
    STALK("stalk");

    private final String xmlName;

    ComponentType(String xmlName) {
        this.xmlName = xmlName;
    }

    /** {@return the attribute value used in scene files, e.g. {@code "leaf"}} */
    public String xmlName() {
        return xmlName;
    }
}
