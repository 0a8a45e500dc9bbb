package org.jecosys.scene;

/** The value types of scene attributes; each has one lexical form, shared by the loader and the XSD. */
enum AttrType {
    /** A finite decimal number (no NaN, no Infinity). */
    DOUBLE,
    /** A finite decimal number of degrees; held in radians in the Defs. */
    ANGLE,
    /** A 32-bit integer. */
    INT,
    /** A 64-bit integer. */
    LONG,
    /** {@code true} or {@code false}. */
    BOOL,
    /** An identifier: a letter or '_' then up to 63 letters, digits, '_', '.', '-'. */
    ID,
    /** Free text of at most 256 characters without control characters. */
    TEXT,
    /** A file path relative to the scene file, at most 1024 characters. */
    PATH,
    /** A colour {@code #rrggbb}. */
    COLOUR,
    /** One of a fixed set of words. */
    ENUM,
    /** Whitespace-separated finite decimal numbers. */
    DOUBLE_LIST,
    /** Whitespace-separated integers. */
    INT_LIST;

    /** Regular expression of a finite decimal number, as the XSD's pattern facet also states it. */
    static final String NUMBER_PATTERN = "[+\\-]?([0-9]+(\\.[0-9]*)?|\\.[0-9]+)([eE][+\\-]?[0-9]+)?";
    /** Regular expression of an integer. */
    static final String INT_PATTERN = "[+\\-]?[0-9]+";
    /** Regular expression of an identifier. */
    static final String ID_PATTERN = "[A-Za-z_][A-Za-z0-9_.\\-]{0,63}";
    /** Regular expression of a colour. */
    static final String COLOUR_PATTERN = "#[0-9A-Fa-f]{6}";
}
