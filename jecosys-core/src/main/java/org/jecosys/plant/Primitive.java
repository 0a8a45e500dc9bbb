package org.jecosys.plant;

/** The primitive a level of detail draws with (paper Table 3). */
public enum Primitive {
    /** Filled triangles. */
    TRIANGLES("triangles"),
    /** Line segments. */
    LINES("lines");

    private final String xmlName;

    Primitive(String xmlName) {
        this.xmlName = xmlName;
    }

    /** {@return the attribute value used in scene files: {@code "triangles"} or {@code "lines"}} */
    public String xmlName() {
        return xmlName;
    }
}
