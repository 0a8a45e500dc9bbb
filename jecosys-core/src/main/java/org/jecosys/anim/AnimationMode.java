package org.jecosys.anim;

/** The animation modes of paper Table 7. */
public enum AnimationMode {
    /** S1: no animation; plants keep their rest pose. */
    STATIC("static"),
    /** S2: seeded random animation while the force field is still updated. */
    RANDOM("random"),
    /** S3: the framework's dynamic-constraint model (paper §4.2). */
    CONSTRAINT("constraint");

    private final String xmlName;

    AnimationMode(String xmlName) {
        this.xmlName = xmlName;
    }

    /** {@return the value used in scene files and on the command line, e.g. {@code "constraint"}} */
    public String xmlName() {
        return xmlName;
    }
}
