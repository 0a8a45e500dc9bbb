package org.jecosys.scene;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import org.jecosys.math.Rgb;

/**
 * Checks a located XML tree against {@link SceneSchema}: element names, order and counts,
 * attribute names (with a did-you-mean), required values, lexical forms, NaN and Infinity, and
 * ranges; fills in defaults. Collects every problem rather than stopping at the first. One
 * instance per load; not thread-safe.
 */
final class SceneValidator {
    private static final Pattern NUMBER = Pattern.compile(AttrType.NUMBER_PATTERN);
    private static final Pattern INTEGER = Pattern.compile(AttrType.INT_PATTERN);
    private static final Pattern ID = Pattern.compile(AttrType.ID_PATTERN);
    private static final Pattern COLOUR = Pattern.compile(AttrType.COLOUR_PATTERN);
    /** Stop collecting after this many problems; one more entry then says that the list stopped. */
    static final int MAX_PROBLEMS = 50;

    private final String file;
    private final List<SceneProblem> problems = new ArrayList<>();

    SceneValidator(String file) {
        this.file = file;
    }

    List<SceneProblem> problems() {
        return problems;
    }

    void problem(int line, int column, String message) {
        if (problems.size() < MAX_PROBLEMS) {
            problems.add(new SceneProblem(file, line, column, message));
        } else if (problems.size() == MAX_PROBLEMS) {
            problems.add(new SceneProblem(file, line, column, "stopped after " + MAX_PROBLEMS
                    + " problems (the limit); there are more from here on: fix these and check again"));
        }
    }

    /** Validates the whole document from its root. */
    Values validateRoot(XmlNode root) {
        ElementSpec spec = SceneSchema.ROOT;
        if (!root.name.equals(spec.name)) {
            problem(root.line, root.column, "root element is <" + root.name + ">; expected <scene version=\"1\">"
                    + Names.didYouMean(root.name, List.of(spec.name)));
            return null;
        }
        return validate(root, spec);
    }

    private Values validate(XmlNode node, ElementSpec spec) {
        Values v = new Values(node, spec);
        for (XmlNode.Attr a : node.attrs.values()) {
            if (spec.attrSpec(a.name()) == null) {
                problem(a.line(), a.column(), "unknown attribute '" + a.name() + "' on <" + spec.name + ">"
                        + Names.didYouMean(a.name(), spec.attrNames()) + "; allowed: "
                        + String.join(", ", spec.attrNames()));
            }
        }
        for (AttrSpec as : spec.attrs) {
            XmlNode.Attr a = node.attrs.get(as.name);
            if (a == null) {
                if (as.required) {
                    problem(node.line, node.column, "<" + spec.name + "> is missing required attribute '" + as.name
                            + "' (" + as.allowed() + ")");
                }
                continue; // read as its default (Values.get)
            }
            Object parsed = parse(spec, as, a);
            v.values.put(as.name, parsed == null ? as.defaultValue : parsed);
        }
        children(node, spec, v);
        return v;
    }

    private void children(XmlNode node, ElementSpec spec, Values v) {
        int[] counts = new int[spec.children.size()];
        int lastIndex = -1;
        int total = 0;
        for (XmlNode child : node.children) {
            ElementSpec.Child cs = spec.childSpec(child.name);
            if (cs == null) {
                String allowed = spec.children.isEmpty() ? "it has no child elements"
                        : "allowed: " + String.join(", ", spec.childNames());
                problem(child.line, child.column, "unknown element <" + child.name + "> inside <" + spec.name + ">"
                        + Names.didYouMean(child.name, spec.childNames()) + "; " + allowed);
                continue;
            }
            int index = spec.children.indexOf(cs);
            total++;
            if (spec.choice) {
                if (total == spec.maxChildren + 1) {
                    problem(child.line, child.column, "more than " + spec.maxChildren + " elements inside <"
                            + spec.name + "> (the maximum)");
                }
            } else {
                if (index < lastIndex) {
                    problem(child.line, child.column, "<" + child.name + "> is out of order inside <" + spec.name
                            + ">: it must come before <" + spec.children.get(lastIndex).spec.name + ">; order: "
                            + String.join(", ", spec.childNames()));
                }
                lastIndex = Math.max(lastIndex, index);
                counts[index]++;
                if (counts[index] == cs.max + 1) {
                    problem(child.line, child.column, cs.max == 1
                            ? "<" + child.name + "> may appear only once inside <" + spec.name + ">"
                            : "more than " + cs.max + " <" + child.name + "> inside <" + spec.name + "> (the maximum)");
                }
            }
            v.children.add(validate(child, cs.spec));
        }
        if (!spec.choice) {
            for (int i = 0; i < counts.length; i++) {
                ElementSpec.Child cs = spec.children.get(i);
                if (counts[i] < cs.min) {
                    problem(node.line, node.column, "<" + spec.name + "> needs "
                            + (cs.min == 1 ? "a <" + cs.spec.name + "> element" : "at least " + cs.min + " <"
                            + cs.spec.name + "> elements") + ", found " + counts[i]);
                }
            }
        }
    }

    private Object parse(ElementSpec owner, AttrSpec as, XmlNode.Attr a) {
        String raw = a.value();
        String s = raw.strip();
        String where = "attribute '" + as.name + "' of <" + owner.name + ">";
        String bad = where + ": '" + abbreviate(raw) + "' is not allowed; expected " + as.allowed();
        switch (as.type) {
            case DOUBLE, ANGLE -> {
                Double d = number(s, as, where, a);
                if (d == null) {
                    return null;
                }
                return as.type == AttrType.ANGLE ? Math.toRadians(d) : d;
            }
            case INT, LONG -> {
                if (!INTEGER.matcher(s).matches()) {
                    problem(a.line(), a.column(), where + ": '" + abbreviate(raw) + "' is not an integer; expected "
                            + as.allowed());
                    return null;
                }
                long l;
                try {
                    l = Long.parseLong(s);
                } catch (NumberFormatException e) {
                    problem(a.line(), a.column(), bad);
                    return null;
                }
                if (as.type == AttrType.INT && (l < Integer.MIN_VALUE || l > Integer.MAX_VALUE)) {
                    problem(a.line(), a.column(), bad);
                    return null;
                }
                if (owner == SceneSchema.ROOT && as.name.equals("version") && l != SceneDef.FORMAT_VERSION) {
                    problem(a.line(), a.column(), "unsupported scene format version " + s + "; this build reads version "
                            + SceneDef.FORMAT_VERSION);
                    return null;
                }
                if (!inRange(l, as)) {
                    problem(a.line(), a.column(), where + ": " + s + " is out of range; expected " + as.allowed());
                    return null;
                }
                return as.type == AttrType.INT ? (Object) (int) l : (Object) l;
            }
            case BOOL -> {
                if (s.equals("true") || s.equals("false")) {
                    return Boolean.valueOf(s);
                }
                problem(a.line(), a.column(), bad);
                return null;
            }
            case ID -> {
                if (!ID.matcher(s).matches()) {
                    problem(a.line(), a.column(), bad);
                    return null;
                }
                return s;
            }
            case TEXT, PATH -> {
                int limit = as.type == AttrType.TEXT ? 256 : 1024;
                if (raw.length() > limit || hasControl(raw) || (as.type == AttrType.PATH && s.isEmpty())) {
                    problem(a.line(), a.column(), bad);
                    return null;
                }
                return as.type == AttrType.PATH ? s : raw;
            }
            case COLOUR -> {
                if (!COLOUR.matcher(s).matches()) {
                    problem(a.line(), a.column(), bad);
                    return null;
                }
                return Rgb.parseHex(s);
            }
            case ENUM -> {
                if (!as.values.contains(s)) {
                    problem(a.line(), a.column(), where + ": '" + abbreviate(raw) + "' is not allowed"
                            + Names.didYouMean(s, as.values) + "; expected " + as.allowed());
                    return null;
                }
                return s;
            }
            case DOUBLE_LIST, INT_LIST -> {
                return list(s, as, where, a);
            }
            default -> throw new IllegalStateException("unhandled type " + as.type);
        }
    }

    private Double number(String s, AttrSpec as, String where, XmlNode.Attr a) {
        if (!NUMBER.matcher(s).matches()) {
            String lower = s.toLowerCase(java.util.Locale.ROOT);
            String why = lower.contains("nan") ? "NaN is not allowed"
                    : lower.contains("inf") ? "Infinity is not allowed" + (as.defaultValue instanceof Double dv
                    && dv == Double.POSITIVE_INFINITY ? " (leave the attribute out for unbounded)" : "")
                    : "'" + abbreviate(a.value()) + "' is not a number";
            problem(a.line(), a.column(), where + ": " + why + "; expected " + as.allowed());
            return null;
        }
        double d = Double.parseDouble(s) + 0.0; // + 0.0 turns -0 into 0
        if (!Double.isFinite(d)) {
            problem(a.line(), a.column(), where + ": " + s + " overflows; expected " + as.allowed());
            return null;
        }
        if (!inRange(d, as)) {
            problem(a.line(), a.column(), where + ": " + s + " is out of range; expected " + as.allowed());
            return null;
        }
        return d;
    }

    private Object list(String s, AttrSpec as, String where, XmlNode.Attr a) {
        String[] parts = s.isEmpty() ? new String[0] : s.split("\\s+");
        if (parts.length < as.minItems || parts.length > as.maxItems) {
            problem(a.line(), a.column(), where + ": " + parts.length + " values given; expected " + as.allowed());
            return null;
        }
        List<Object> out = new ArrayList<>();
        for (String p : parts) {
            if (as.type == AttrType.DOUBLE_LIST) {
                Double d = number(p, as, where, a);
                if (d == null) {
                    return null;
                }
                out.add(d);
            } else {
                if (!INTEGER.matcher(p).matches() || p.length() > 10) {
                    problem(a.line(), a.column(), where + ": '" + abbreviate(p) + "' is not an integer; expected "
                            + as.allowed());
                    return null;
                }
                long l = Long.parseLong(p);
                if (!inRange(l, as)) {
                    problem(a.line(), a.column(), where + ": " + p + " is out of range; expected " + as.allowed());
                    return null;
                }
                out.add((int) l);
            }
        }
        return List.copyOf(out);
    }

    private static boolean inRange(double v, AttrSpec as) {
        if (as.minExclusive ? v <= as.min : v < as.min) {
            return false;
        }
        return v <= as.max;
    }

    private static boolean hasControl(String s) {
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c < 0x20 && c != '\t') {
                return true;
            }
        }
        return false;
    }

    static String abbreviate(String s) {
        return s.length() <= 40 ? s : s.substring(0, 37) + "...";
    }
}
