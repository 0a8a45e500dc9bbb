package org.jecosys.scene;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The checked, typed content of one element: each attribute's parsed value (an absent attribute
 * reads as its default, which is not stored, so an element costs what it holds), and the children's
 * Values in document order. Produced by {@link SceneValidator}; read by
 * {@link SceneBinder}. Not shared between threads.
 */
final class Values {
    final XmlNode node;
    final ElementSpec spec;
    final Map<String, Object> values = new LinkedHashMap<>();
    final List<Values> children = new ArrayList<>();

    Values(XmlNode node, ElementSpec spec) {
        this.node = node;
        this.spec = spec;
    }

    double num(String name) {
        return (Double) get(name);
    }

    int integer(String name) {
        return (Integer) get(name);
    }

    long longValue(String name) {
        return (Long) get(name);
    }

    boolean bool(String name) {
        return (Boolean) get(name);
    }

    String str(String name) {
        return (String) get(name);
    }

    /** The attribute's checked value, or its default when it is absent (or was refused). */
    Object get(String name) {
        if (values.containsKey(name)) {
            return values.get(name);
        }
        AttrSpec as = spec.attrSpec(name);
        return as == null ? null : as.defaultValue;
    }

    boolean present(String name) {
        return node.attrs.containsKey(name);
    }

    /** Line and column of an attribute if present, else of the element. */
    int[] where(String attr) {
        XmlNode.Attr a = node.attrs.get(attr);
        return a == null ? new int[] {node.line, node.column} : new int[] {a.line(), a.column()};
    }

    List<Values> children(String name) {
        List<Values> out = new ArrayList<>();
        for (Values v : children) {
            if (v.node.name.equals(name)) {
                out.add(v);
            }
        }
        return out;
    }

    Values child(String name) {
        for (Values v : children) {
            if (v.node.name.equals(name)) {
                return v;
            }
        }
        return null;
    }
}
