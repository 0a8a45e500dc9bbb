package org.jecosys.scene;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import java.util.function.Predicate;

/**
 * One element of the scene format: its attributes and children. An element's children are either
 * ordered (a sequence, each child kind with its own count range and Def getter) or a choice (any
 * order, each child's Def picked from one shared list by a predicate, so order is kept on save).
 * Built once in {@link SceneSchema}'s static initialiser and never changed afterwards.
 */
final class ElementSpec {
    /** A child element kind with how many may appear. */
    static final class Child {
        final ElementSpec spec;
        final int min;
        final int max;
        /** Ordered parents: the child Defs of a parent Def. */
        Function<Object, List<?>> getter;
        /** Choice parents: whether a Def of the shared list is written as this child. */
        Predicate<Object> accepts;

        Child(ElementSpec spec, int min, int max) {
            this.spec = spec;
            this.min = min;
            this.max = max;
        }
    }

    final String name;
    final String doc;
    final List<AttrSpec> attrs = new ArrayList<>();
    final List<Child> children = new ArrayList<>();
    boolean choice;
    int maxChildren = Integer.MAX_VALUE;
    /** Choice parents: the shared list of child Defs. */
    Function<Object, List<?>> choiceItems;

    ElementSpec(String name, String doc) {
        this.name = name;
        this.doc = doc;
    }

    ElementSpec attr(AttrSpec a) {
        attrs.add(a);
        return this;
    }

    ElementSpec child(ElementSpec spec, int min, int max, Function<Object, List<?>> getter) {
        Child c = new Child(spec, min, max);
        c.getter = getter;
        children.add(c);
        return this;
    }

    ElementSpec choiceChild(ElementSpec spec, Predicate<Object> accepts) {
        Child c = new Child(spec, 0, Integer.MAX_VALUE);
        c.accepts = accepts;
        children.add(c);
        return this;
    }

    AttrSpec attrSpec(String attrName) {
        for (AttrSpec a : attrs) {
            if (a.name.equals(attrName)) {
                return a;
            }
        }
        return null;
    }

    Child childSpec(String childName) {
        for (Child c : children) {
            if (c.spec.name.equals(childName)) {
                return c;
            }
        }
        return null;
    }

    List<String> attrNames() {
        List<String> out = new ArrayList<>();
        for (AttrSpec a : attrs) {
            out.add(a.name);
        }
        return out;
    }

    List<String> childNames() {
        List<String> out = new ArrayList<>();
        for (Child c : children) {
            out.add(c.spec.name);
        }
        return out;
    }
}
