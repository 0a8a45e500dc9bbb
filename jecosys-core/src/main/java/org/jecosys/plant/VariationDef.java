package org.jecosys.plant;

import org.jecosys.math.Require;

/**
 * Per-instance variation of a species (paper §4.1: "small changes in their skeletons can generate
 * a great variety of components shapes"). A species pre-computes {@code variants} shape variants;
 * each plant picks one by seed and adds its own rest azimuth. Fractions are relative
 * (0.1 = up to plus or minus 10%). Immutable; any thread.
 *
 * @param variants  number of pre-computed shape variants sharing pose tables, in [1, 64]
 * @param length    relative length variation, in [0, 0.9]
 * @param width     relative width variation, in [0, 0.9]
 * @param curvature relative curvature variation, in [0, 0.9]
 * @param tilt      extra tilt from vertical, radians, in [0, pi/4]
 */
public record VariationDef(int variants, double length, double width, double curvature, double tilt) {
    /**
     * Checks the components.
     *
     * @param variants  shape variants, in [1, 64]
     * @param length    relative length variation, in [0, 0.9]
     * @param width     relative width variation, in [0, 0.9]
     * @param curvature relative curvature variation, in [0, 0.9]
     * @param tilt      extra tilt, radians, in [0, pi/4]
     * @throws IllegalArgumentException when a component is out of range
     */
    public VariationDef {
        Require.range("variants", variants, 1, 64);
        Require.range("length", length, 0, 0.9);
        Require.range("width", width, 0, 0.9);
        Require.range("curvature", curvature, 0, 0.9);
        Require.range("tilt", tilt, 0, Math.PI / 4);
    }

    /** No variation: one variant. */
    public static final VariationDef NONE = new VariationDef(1, 0, 0, 0, 0);
}
