package org.jecosys.scene;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Generates the XML Schema of the scene format from {@link SceneSchema}, so the documented schema
 * ({@code scenes/jecosys-scene.xsd}, also shipped in the jar) always states exactly what the loader
 * accepts: names, order, counts, lexical forms, ranges, units and defaults. A test fails when the
 * committed file differs; regenerate it with
 * {@code java -cp target/classes org.jecosys.scene.SchemaXsd scenes/jecosys-scene.xsd}.
 * Any thread; allocates.
 */
public final class SchemaXsd {
    private final StringBuilder sb = new StringBuilder(32_768);

    private SchemaXsd() {
    }

    /** {@return the schema text, an XML Schema 1.0 document} */
    public static String generate() {
        SchemaXsd x = new SchemaXsd();
        x.document();
        return x.sb.toString();
    }

    /**
     * Writes the schema to the path given as the only argument; exits with status 2 otherwise.
     *
     * @param args one argument: the output file, e.g. {@code scenes/jecosys-scene.xsd}
     * @throws IOException when the file cannot be written
     */
    public static void main(String[] args) throws IOException {
        if (args.length != 1) {
            System.err.println("usage: SchemaXsd OUTPUT.xsd");
            System.exit(2);
        }
        Files.writeString(Path.of(args[0]), generate(), StandardCharsets.UTF_8);
    }

    private void document() {
        line(0, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
        line(0, "<!-- JEcoSys scene format, version " + SceneDef.FORMAT_VERSION + ". Generated from "
                + "org.jecosys.scene.SceneSchema: do not edit by hand.");
        line(0, "     Units: metres, seconds, kilograms, newtons; angles in degrees. Y is up, the ground is the XZ "
                + "plane.");
        line(0, "     Files are UTF-8, at most " + SceneSchema.MAX_FILE_BYTES + " bytes; DOCTYPE and entities are "
                + "rejected. -->");
        line(0, "<xs:schema xmlns:xs=\"http://www.w3.org/2001/XMLSchema\" elementFormDefault=\"unqualified\">");
        simpleType("number", "xs:double", AttrType.NUMBER_PATTERN, "A finite decimal number: no NaN, no INF.");
        simpleType("integer", "xs:long", AttrType.INT_PATTERN, "A decimal integer.");
        simpleType("identifier", "xs:string", AttrType.ID_PATTERN,
                "A letter or '_', then up to 63 letters, digits, '_', '.', '-'.");
        simpleType("colour", "xs:string", AttrType.COLOUR_PATTERN, "A colour #rrggbb.");
        element(SceneSchema.ROOT, 1, "", 0);
        line(0, "</xs:schema>");
    }

    private void simpleType(String name, String base, String pattern, String doc) {
        line(1, "<xs:simpleType name=\"" + name + "\">");
        doc(2, doc);
        line(2, "<xs:restriction base=\"" + base + "\"><xs:pattern value=\"" + attr(pattern) + "\"/></xs:restriction>");
        line(1, "</xs:simpleType>");
    }

    private void element(ElementSpec spec, int depth, String occurs, int statedMax) {
        line(depth, "<xs:element name=\"" + spec.name + "\"" + occurs + ">");
        doc(depth + 1, statedMax > 0 ? spec.doc + " At most " + statedMax + " (checked by the loader)." : spec.doc);
        line(depth + 1, "<xs:complexType>");
        if (!spec.children.isEmpty()) {
            if (spec.choice) {
                line(depth + 2, "<xs:choice minOccurs=\"0\" maxOccurs=\"" + max(spec.maxChildren) + "\">");
                for (ElementSpec.Child c : spec.children) {
                    element(c.spec, depth + 3, "", 0);
                }
                line(depth + 2, "</xs:choice>");
            } else {
                line(depth + 2, "<xs:sequence>");
                for (ElementSpec.Child c : spec.children) {
                    element(c.spec, depth + 3, " minOccurs=\"" + c.min + "\" maxOccurs=\"" + max(c.max) + "\"",
                            c.max > XSD_MAX_OCCURS && c.max != Integer.MAX_VALUE ? c.max : 0);
                }
                line(depth + 2, "</xs:sequence>");
            }
        }
        for (AttrSpec a : spec.attrs) {
            attribute(a, depth + 2);
        }
        line(depth + 1, "</xs:complexType>");
        line(depth, "</xs:element>");
    }

    private void attribute(AttrSpec a, int depth) {
        line(depth, "<xs:attribute name=\"" + a.name + "\" use=\"" + (a.required ? "required" : "optional") + "\">");
        StringBuilder d = new StringBuilder(a.doc);
        if (!a.units.isEmpty()) {
            d.append(" Units: ").append(a.units).append('.');
        }
        d.append(" Allowed: ").append(a.allowed()).append('.');
        if (!a.required && a.defaultValue != null) {
            d.append(" Default: ").append(defaultText(a)).append('.');
        } else if (!a.required && a.defaultValue == null) {
            d.append(" Optional, no default.");
        }
        doc(depth + 1, d.toString());
        line(depth + 1, "<xs:simpleType>");
        switch (a.type) {
            case DOUBLE, ANGLE -> restriction(depth + 2, "number", a, false);
            case INT, LONG -> restriction(depth + 2, "integer", a, true);
            case BOOL -> enumeration(depth + 2, java.util.List.of("true", "false"));
            case ENUM -> enumeration(depth + 2, a.values);
            case ID -> line(depth + 2, "<xs:restriction base=\"identifier\"/>");
            case COLOUR -> line(depth + 2, "<xs:restriction base=\"colour\"/>");
            case TEXT -> line(depth + 2, "<xs:restriction base=\"xs:string\"><xs:maxLength value=\"256\"/>"
                    + "</xs:restriction>");
            case PATH -> line(depth + 2, "<xs:restriction base=\"xs:string\"><xs:minLength value=\"1\"/>"
                    + "<xs:maxLength value=\"1024\"/></xs:restriction>");
            case DOUBLE_LIST, INT_LIST -> {
                line(depth + 2, "<xs:restriction>");
                line(depth + 3, "<xs:simpleType>");
                line(depth + 4, "<xs:list>");
                line(depth + 5, "<xs:simpleType>");
                restriction(depth + 6, a.type == AttrType.DOUBLE_LIST ? "number" : "integer", a,
                        a.type == AttrType.INT_LIST);
                line(depth + 5, "</xs:simpleType>");
                line(depth + 4, "</xs:list>");
                line(depth + 3, "</xs:simpleType>");
                line(depth + 3, "<xs:minLength value=\"" + a.minItems + "\"/>");
                if (a.maxItems != Integer.MAX_VALUE) {
                    line(depth + 3, "<xs:maxLength value=\"" + a.maxItems + "\"/>");
                }
                line(depth + 2, "</xs:restriction>");
            }
            default -> throw new IllegalStateException("unhandled " + a.type);
        }
        line(depth + 1, "</xs:simpleType>");
        line(depth, "</xs:attribute>");
    }

    private void restriction(int depth, String base, AttrSpec a, boolean integral) {
        if (!a.hasRange()) {
            line(depth, "<xs:restriction base=\"" + base + "\"/>");
            return;
        }
        StringBuilder s = new StringBuilder("<xs:restriction base=\"" + base + "\">");
        if (a.min != Double.NEGATIVE_INFINITY) {
            s.append(a.minExclusive ? "<xs:minExclusive value=\"" : "<xs:minInclusive value=\"")
                    .append(bound(a.min, integral)).append("\"/>");
        }
        if (a.max != Double.POSITIVE_INFINITY) {
            s.append("<xs:maxInclusive value=\"").append(bound(a.max, integral)).append("\"/>");
        }
        line(depth, s.append("</xs:restriction>").toString());
    }

    private static String bound(double v, boolean integral) {
        return integral ? Long.toString((long) v) : SceneWriter.formatNumber(v);
    }

    private void enumeration(int depth, java.util.List<String> words) {
        StringBuilder s = new StringBuilder("<xs:restriction base=\"xs:string\">");
        for (String w : words) {
            s.append("<xs:enumeration value=\"").append(w).append("\"/>");
        }
        line(depth, s.append("</xs:restriction>").toString());
    }

    @SuppressWarnings("unchecked")
    private static String defaultText(AttrSpec a) {
        Object v = a.defaultValue;
        if (v instanceof Double d && d == Double.POSITIVE_INFINITY) {
            return "unbounded";
        }
        return switch (a.type) {
            case ANGLE -> SceneWriter.formatAngle((Double) v);
            case DOUBLE -> SceneWriter.formatNumber((Double) v);
            case COLOUR -> ((org.jecosys.math.Rgb) v).toHex();
            case DOUBLE_LIST -> {
                StringBuilder s = new StringBuilder();
                for (Double d : (java.util.List<Double>) v) {
                    s.append(s.length() == 0 ? "" : " ").append(SceneWriter.formatNumber(d));
                }
                yield "\"" + s + "\"";
            }
            case TEXT -> "\"" + v + "\"";
            default -> v.toString();
        };
    }

    private void doc(int depth, String text) {
        line(depth, "<xs:annotation><xs:documentation>" + text(text) + "</xs:documentation></xs:annotation>");
    }

    /**
     * Larger maxOccurs values are written as "unbounded": schema validators in secure mode refuse
     * content models that expand past a few thousand nodes. The element's documentation states the
     * real maximum, which the loader enforces.
     */
    static final int XSD_MAX_OCCURS = 1000;

    private static String max(int m) {
        return m == Integer.MAX_VALUE || m > XSD_MAX_OCCURS ? "unbounded" : Integer.toString(m);
    }

    private void line(int depth, String s) {
        sb.append("  ".repeat(depth)).append(s).append('\n');
    }

    private static String text(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    private static String attr(String s) {
        return text(s).replace("\"", "&quot;");
    }
}
