package org.jecosys.scene;

import java.util.List;
import java.util.function.Function;

/**
 * One attribute of the scene format: its type, range, default, units and documentation, and how
 * to read its value back from a Def (for saving). Built once in {@link SceneSchema}'s static
 * initialiser and never changed afterwards.
 */
final class AttrSpec {
    final String name;
    final AttrType type;
    final String units;
    final String doc;
    boolean required;
    /** Parsed default (radians for angles), or null when absence means "none". */
    Object defaultValue;
    double min = Double.NEGATIVE_INFINITY;
    double max = Double.POSITIVE_INFINITY;
    boolean minExclusive;
    int minItems;
    int maxItems = Integer.MAX_VALUE;
    List<String> values = List.of();
    /** Reads this attribute's value from the owning Def; null means "omit". */
    Function<Object, Object> getter;

    private AttrSpec(String name, AttrType type, String units, String doc) {
        this.name = name;
        this.type = type;
        this.units = units;
        this.doc = doc;
    }

    static AttrSpec of(String name, AttrType type, String units, String doc) {
        return new AttrSpec(name, type, units, doc);
    }

    AttrSpec required() {
        this.required = true;
        return this;
    }

    AttrSpec def(Object value) {
        this.defaultValue = value;
        return this;
    }

    /** Range [min, max]; for ANGLE both in degrees. */
    AttrSpec range(double lo, double hi) {
        this.min = lo;
        this.max = hi;
        return this;
    }

    /** Range (min, max]; for ANGLE both in degrees. */
    AttrSpec rangeAbove(double lo, double hi) {
        range(lo, hi);
        this.minExclusive = true;
        return this;
    }

    AttrSpec items(int lo, int hi) {
        this.minItems = lo;
        this.maxItems = hi;
        return this;
    }

    AttrSpec values(List<String> words) {
        this.values = List.copyOf(words);
        return this;
    }

    AttrSpec get(Function<Object, Object> g) {
        this.getter = g;
        return this;
    }

    boolean hasRange() {
        return min != Double.NEGATIVE_INFINITY || max != Double.POSITIVE_INFINITY;
    }

    /** What is allowed, in words, e.g. "a number in (0, 10] metres". */
    String allowed() {
        String unit = units.isEmpty() ? "" : " " + units;
        return switch (type) {
            case DOUBLE, ANGLE -> "a finite number" + rangeText() + unit;
            case INT, LONG -> "an integer" + rangeText() + unit;
            case BOOL -> "true or false";
            case ID -> "an identifier (a letter or '_', then up to 63 letters, digits, '_', '.', '-')";
            case TEXT -> "text of at most 256 characters";
            case PATH -> "a file path relative to the scene file, at most 1024 characters";
            case COLOUR -> "a colour #rrggbb";
            case ENUM -> "one of " + String.join(", ", values);
            case DOUBLE_LIST -> itemsText() + " finite numbers" + rangeText() + unit + ", separated by spaces";
            case INT_LIST -> itemsText() + " integers" + rangeText() + ", separated by spaces";
        };
    }

    private String itemsText() {
        if (maxItems == Integer.MAX_VALUE) {
            return minItems + " or more";
        }
        return minItems == maxItems ? String.valueOf(minItems) : minItems + " to " + maxItems;
    }

    String rangeText() {
        if (!hasRange()) {
            return "";
        }
        if (max == Double.POSITIVE_INFINITY) {
            return minExclusive ? " > " + num(min) : " >= " + num(min);
        }
        return " in " + (minExclusive ? "(" : "[") + num(min) + ", " + num(max) + "]";
    }

    static String num(double v) {
        return SceneWriter.formatNumber(v);
    }
}
