package org.jecosys.scene;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.List;
import java.util.Objects;
import org.jecosys.math.Rgb;

/**
 * Writes a {@link SceneDef} as scene XML, driven by {@link SceneSchema}: attributes in schema
 * order, values equal to their defaults left out, numbers in their shortest exact decimal form and
 * angles in the shortest decimal degrees that read back to the same radians. The output is a pure
 * function of the Def, so {@code save(load(save(x)))} is byte-identical to {@code save(x)}.
 * Comments of a hand-written file are not kept. Any thread; allocates.
 */
final class SceneWriter {
    private static final int WRAP = 110;
    private final StringBuilder sb = new StringBuilder(4096);

    private SceneWriter() {
    }

    static String toXml(SceneDef scene) {
        SceneWriter w = new SceneWriter();
        w.sb.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        w.element(SceneSchema.ROOT, scene, 0, true);
        return w.sb.toString();
    }

    private void element(ElementSpec spec, Object def, int depth, boolean root) {
        String indent = "  ".repeat(depth);
        StringBuilder line = new StringBuilder(indent).append('<').append(spec.name);
        if (root) {
            line.append(" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\"");
            line.append(" xsi:noNamespaceSchemaLocation=\"jecosys-scene.xsd\"");
        }
        for (AttrSpec a : spec.attrs) {
            Object v = a.getter.apply(def);
            if (v == null || (!a.required && Objects.equals(v, a.defaultValue))) {
                continue;
            }
            String text = a.name + "=\"" + escape(format(a, v)) + "\"";
            if (line.length() + 1 + text.length() > WRAP && line.length() > indent.length() + spec.name.length() + 1) {
                sb.append(line).append('\n');
                line.setLength(0);
                line.append(indent).append("    ").append(text);
            } else {
                line.append(' ').append(text);
            }
        }
        int mark = sb.length();
        sb.append(line);
        int before = sb.length();
        sb.append(">\n");
        int childStart = sb.length();
        if (spec.choice) {
            for (Object item : spec.choiceItems.apply(def)) {
                for (ElementSpec.Child c : spec.children) {
                    if (c.accepts.test(item)) {
                        element(c.spec, item, depth + 1, false);
                        break;
                    }
                }
            }
        } else {
            for (ElementSpec.Child c : spec.children) {
                List<?> items = c.getter.apply(def);
                for (Object item : items) {
                    int childMark = sb.length();
                    element(c.spec, item, depth + 1, false);
                    if (c.min == 0 && c.max == 1 && isBare(childMark, c.spec.name, depth + 1)) {
                        sb.setLength(childMark); // an optional section equal to its defaults
                    }
                }
            }
        }
        if (sb.length() == childStart) {
            sb.setLength(before);
            sb.append("/>\n");
        } else {
            sb.append(indent).append("</").append(spec.name).append(">\n");
        }
        if (mark < 0) {
            throw new IllegalStateException();
        }
    }

    private boolean isBare(int mark, String name, int depth) {
        String bare = "  ".repeat(depth) + "<" + name + "/>\n";
        return sb.length() - mark == bare.length() && sb.indexOf(bare, mark) == mark;
    }

    @SuppressWarnings("unchecked")
    private static String format(AttrSpec a, Object v) {
        return switch (a.type) {
            case DOUBLE -> formatNumber((Double) v);
            case ANGLE -> formatAngle((Double) v);
            case INT, LONG, BOOL, ID, TEXT, PATH, ENUM -> v.toString();
            case COLOUR -> ((Rgb) v).toHex();
            case DOUBLE_LIST -> {
                StringBuilder s = new StringBuilder();
                for (Double d : (List<Double>) v) {
                    s.append(s.length() == 0 ? "" : " ").append(formatNumber(d));
                }
                yield s.toString();
            }
            case INT_LIST -> {
                StringBuilder s = new StringBuilder();
                for (Integer i : (List<Integer>) v) {
                    s.append(s.length() == 0 ? "" : " ").append(i);
                }
                yield s.toString();
            }
        };
    }

    /** The shortest plain decimal that parses back to exactly {@code v}; scientific when very large or small. */
    static String formatNumber(double v) {
        if (Double.isInfinite(v)) {
            return v > 0 ? "infinity" : "-infinity";
        }
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        BigDecimal bd = new BigDecimal(Double.toString(v)).stripTrailingZeros();
        if (bd.scale() > 12 || bd.precision() - bd.scale() > 15) {
            return Double.toString(v);
        }
        return bd.toPlainString();
    }

    /** Degrees with the fewest significant digits that read back to exactly {@code radians}. */
    static String formatAngle(double radians) {
        double deg = Math.toDegrees(radians);
        for (int p = 1; p <= 17; p++) {
            BigDecimal rounded = new BigDecimal(deg).round(new MathContext(p));
            String s = formatNumber(rounded.doubleValue());
            if (Math.toRadians(Double.parseDouble(s)) + 0.0 == radians) {
                return s;
            }
        }
        return formatNumber(deg);
    }

    private static String escape(String s) {
        StringBuilder out = null;
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            String rep = switch (c) {
                case '&' -> "&amp;";
                case '<' -> "&lt;";
                case '>' -> "&gt;";
                case '"' -> "&quot;";
                case '\t' -> "&#9;";
                default -> null;
            };
            if (rep != null && out == null) {
                out = new StringBuilder(s.substring(0, i));
            }
            if (out != null) {
                if (rep != null) {
                    out.append(rep);
                } else {
                    out.append(c);
                }
            }
        }
        return out == null ? s : out.toString();
    }
}
