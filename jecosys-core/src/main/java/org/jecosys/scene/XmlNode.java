package org.jecosys.scene;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A parsed XML element with the position of the element and of each attribute, so that every
 * later check can name {@code FILE:LINE:COL}. Built once per load; not shared between threads.
 */
final class XmlNode {
    /** An attribute: its raw value and where its name starts. */
    record Attr(String name, String value, int line, int column) {
    }

    final String name;
    final int line;
    final int column;
    final Map<String, Attr> attrs = new LinkedHashMap<>();
    final List<XmlNode> children = new ArrayList<>();

    XmlNode(String name, int line, int column) {
        this.name = name;
        this.line = line;
        this.column = column;
    }
}
