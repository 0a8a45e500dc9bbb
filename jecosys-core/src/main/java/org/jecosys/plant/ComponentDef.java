package org.jecosys.plant;

import java.util.List;
import org.jecosys.math.Require;
import org.jecosys.math.Rgb;

/**
 * One component type of a species: its skeleton shape (paper §4.1), its dynamic-constraint
 * parameters (paper §4.2, eq. 4-5, with tau a response time as DESIGN.md resolves it) and its
 * drag. Immutable; any thread.
 *
 * @param id           unique within the species
 * @param type         leaf, petal, head or stalk
 * @param shape        how primitives are generated from the skeleton
 * @param count        how many of this component a plant has, in [1, 256]
 * @param attachTo     id of the component at whose tip these sit (e.g. petals on a stalk), or null for the ground
 * @param segments     skeleton segments (points = segments + 1), in [1, 32]
 * @param length       skeleton length, metres, in (0, 10]
 * @param baseWidth    width at the base, metres, in (0, 1]
 * @param tipWidth     width at the tip, metres, in [0, 1]
 * @param curvature    rest curvature before gravity, radians over the whole length, in [-pi, pi]
 * @param twist        twist around the skeleton over the whole length, radians, in [-2 pi, 2 pi]
 * @param tilt         angle of the base from vertical, radians, in [0, pi/2]
 * @param mass         mass, kilograms, in (0, 10]
 * @param stiffness    spring constant PC of eq. 4, N/m, in (0, 1e6]
 * @param responseTime response time tau of the spring, seconds, in [1e-3, 10]
 * @param dragArea     drag coefficient times area, m^2, in [0, 10]; force = 0.5 rho dragArea |u| u
 * @param colour       base colour
 * @param lodSegments  per species level of detail, how many segments this component uses there
 *                     (0 = not drawn at that level), each in [0, segments]
 */
public record ComponentDef(String id, ComponentType type, ComponentShape shape, int count, String attachTo,
                           int segments, double length, double baseWidth, double tipWidth, double curvature,
                           double twist, double tilt, double mass, double stiffness, double responseTime,
                           double dragArea, Rgb colour, List<Integer> lodSegments) {
    public ComponentDef {
        Require.nonNull("id", id);
        if (id.isEmpty()) {
            throw new IllegalArgumentException("id must not be empty");
        }
        Require.nonNull("type", type);
        Require.nonNull("shape", shape);
        Require.range("count", count, 1, 256);
        Require.range("segments", segments, 1, 32);
        Require.range("length", length, 1e-6, 10);
        Require.range("baseWidth", baseWidth, 1e-6, 1);
        Require.range("tipWidth", tipWidth, 0, 1);
        Require.range("curvature", curvature, -Math.PI, Math.PI);
        Require.range("twist", twist, -2 * Math.PI, 2 * Math.PI);
        Require.range("tilt", tilt, 0, Math.PI / 2);
        Require.range("mass", mass, 1e-9, 10);
        Require.range("stiffness", stiffness, 1e-9, 1e6);
        Require.range("responseTime", responseTime, 1e-3, 10);
        Require.range("dragArea", dragArea, 0, 10);
        Require.nonNull("colour", colour);
        lodSegments = List.copyOf(Require.nonNull("lodSegments", lodSegments));
        for (int i = 0; i < lodSegments.size(); i++) {
            Require.range("lodSegments[" + i + "]", lodSegments.get(i), 0, segments);
        }
    }
}
