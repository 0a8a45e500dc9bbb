package org.jecosys.plant;

import java.util.List;
import org.jecosys.math.Require;
import org.jecosys.math.Rgb;

/**
 * The checks of a {@link ComponentDef}: its canonical constructor's (every component in the range its
 * record documents, an {@code attachAt} below 1 only on a carried component, the level-of-detail
 * segments within the skeleton, a texture not blank and a textured mesh with texture coordinates) and
 * its builder's (every value without a default set). Static methods only; any thread; they allocate
 * only the checked copy of the level-of-detail segments and the messages they throw.
 */
final class ComponentDefChecks {
    private ComponentDefChecks() {
    }

    /**
     * Checks the components of a {@link ComponentDef}, in the order of its record (the first value out
     * of range is the one reported); arguments as its canonical constructor's.
     *
     * @return an unmodifiable copy of {@code lodSegments}
     * @throws IllegalArgumentException when a component is null, empty or out of range
     */
    static List<Integer> check(String id, ComponentType type, ComponentShape shape, int count, String attachTo,
                               int segments, double length, double baseWidth, double tipWidth, double curvature,
                               double twist, double tilt, double mass, double stiffness, double responseTime,
                               double dragArea, Rgb colour, List<Integer> lodSegments, String texture, MeshDef mesh,
                               double attachAt) {
        Require.nonNull("id", id);
        if (id.isEmpty()) {
            throw new IllegalArgumentException("id must not be empty");
        }
        Require.nonNull("type", type);
        Require.nonNull("shape", shape);
        Require.range("count", count, 1, ComponentDef.MAX_COUNT);
        Require.range("segments", segments, 1, ComponentDef.MAX_SEGMENTS);
        Require.range("length", length, ComponentDef.MIN_LENGTH, ComponentDef.MAX_LENGTH);
        Require.range("baseWidth", baseWidth, ComponentDef.MIN_WIDTH, ComponentDef.MAX_WIDTH);
        Require.range("tipWidth", tipWidth, 0, ComponentDef.MAX_WIDTH);
        Require.degrees("curvature", curvature, -ComponentDef.MAX_CURVATURE_DEGREES,
                ComponentDef.MAX_CURVATURE_DEGREES);
        Require.degrees("twist", twist, -ComponentDef.MAX_TWIST_DEGREES, ComponentDef.MAX_TWIST_DEGREES);
        Require.degrees("tilt", tilt, 0, ComponentDef.MAX_TILT_DEGREES);
        Require.range("mass", mass, ComponentDef.MIN_MASS, ComponentDef.MAX_MASS);
        Require.range("stiffness", stiffness, ComponentDef.MIN_STIFFNESS, ComponentDef.MAX_STIFFNESS);
        Require.range("responseTime", responseTime, ComponentDef.MIN_RESPONSE_TIME, ComponentDef.MAX_RESPONSE_TIME);
        Require.range("dragArea", dragArea, 0, ComponentDef.MAX_DRAG_AREA);
        Require.nonNull("colour", colour);
        Require.range("attachAt", attachAt, ComponentDef.MIN_ATTACH_AT, 1);
        if (attachTo == null && attachAt != 1) {
            throw new IllegalArgumentException("attachAt " + attachAt + " needs attachTo (a component on the ground "
                    + "stands at its base)");
        }
        List<Integer> lods = List.copyOf(Require.nonNull("lodSegments", lodSegments));
        for (int i = 0; i < lods.size(); i++) {
            Require.elementRange("lodSegments", i, lods.get(i), 0, segments);
        }
        if (texture != null && texture.isBlank()) {
            throw new IllegalArgumentException("texture must not be blank (null for none)");
        }
        if (texture != null && mesh != null && !mesh.geometry().hasUvs()) {
            throw new IllegalArgumentException("mesh '" + mesh.path() + "' has no texture coordinates (TEXCOORD_0) "
                    + "for the texture '" + texture + "'");
        }
        return lods;
    }

    /**
     * Checks that a {@link ComponentDef.Builder} of component {@code id} was given every value without a
     * default in the scene schema: segments (set when &gt;= 0), length, baseWidth, mass and stiffness (set
     * when not NaN) and lodSegments (set when not null).
     *
     * @throws IllegalStateException naming the values not set, in that order
     */
    static void requireSet(String id, int segments, double length, double baseWidth, double mass, double stiffness,
                           List<Integer> lodSegments) {
        List<String> missing = new java.util.ArrayList<>();
        if (segments < 0) {
            missing.add("segments");
        }
        if (Double.isNaN(length)) {
            missing.add("length");
        }
        if (Double.isNaN(baseWidth)) {
            missing.add("baseWidth");
        }
        if (Double.isNaN(mass)) {
            missing.add("mass");
        }
        if (Double.isNaN(stiffness)) {
            missing.add("stiffness");
        }
        if (lodSegments == null) {
            missing.add("lodSegments");
        }
        if (!missing.isEmpty()) {
            throw new IllegalStateException("component '" + id + "': set " + String.join(", ", missing)
                    + " (no default in the scene schema)");
        }
    }

    /** {@return the values as a new modifiable list, in order} (the builder's {@code lodSegments(int...)}) */
    static List<Integer> list(int... values) {
        List<Integer> l = new java.util.ArrayList<>(values.length);
        for (int v : values) {
            l.add(v);
        }
        return l;
    }
}
