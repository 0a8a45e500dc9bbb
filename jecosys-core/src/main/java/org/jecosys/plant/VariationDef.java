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
 * @param responseTime relative variation of the response time tau from plant to plant (paper §4.2),
 *                  in [0, 0.9]; neighbours then move alike but not in lockstep
 * @param stiffness relative variation of the spring constant PC from plant to plant, in [0, 0.9]
 * @param hue       colour only: standard deviation of the per-plant hue shift, degrees of hue (not an
 *                  angle in space, so degrees here too), in [0, 60]
 * @param value     colour only: standard deviation of the per-plant brightness factor (1 is the
 *                  species colour), in [0, 0.5]
 * @param dryTips   colour only: how far the tips of the leaves turn straw-coloured, in [0, 1]
 */
public record VariationDef(int variants, double length, double width, double curvature, double tilt,
                           double responseTime, double stiffness, double hue, double value, double dryTips) {
    /**
     * Checks the components.
     *
     * @param variants  shape variants, in [1, 64]
     * @param length    relative length variation, in [0, 0.9]
     * @param width     relative width variation, in [0, 0.9]
     * @param curvature relative curvature variation, in [0, 0.9]
     * @param tilt      extra tilt, radians, in [0, pi/4]
     * @param responseTime relative response-time variation, in [0, 0.9]
     * @param stiffness relative stiffness variation, in [0, 0.9]
     * @param hue       s.d. of the per-plant hue shift, degrees, in [0, 60]
     * @param value     s.d. of the per-plant brightness factor, in [0, 0.5]
     * @param dryTips   straw colour at the leaf tips, in [0, 1]
     * @throws IllegalArgumentException when a component is out of range
     */
    public VariationDef {
        Require.range("variants", variants, 1, MAX_VARIANTS);
        Require.range("length", length, 0, MAX_FRACTION);
        Require.range("width", width, 0, MAX_FRACTION);
        Require.range("curvature", curvature, 0, MAX_FRACTION);
        Require.degrees("tilt", tilt, 0, MAX_TILT_DEGREES);
        Require.range("responseTime", responseTime, 0, MAX_FRACTION);
        Require.range("stiffness", stiffness, 0, MAX_FRACTION);
        Require.range("hue", hue, 0, MAX_HUE_DEGREES);
        Require.range("value", value, 0, MAX_VALUE);
        Require.range("dryTips", dryTips, 0, 1);
    }

    /**
     * Shape and motion variation with no colour variation. Any thread; allocates.
     *
     * @param variants  shape variants, in [1, 64]
     * @param length    relative length variation, in [0, 0.9]
     * @param width     relative width variation, in [0, 0.9]
     * @param curvature relative curvature variation, in [0, 0.9]
     * @param tilt      extra tilt, radians, in [0, pi/4]
     * @param responseTime relative response-time variation, in [0, 0.9]
     * @param stiffness relative stiffness variation, in [0, 0.9]
     * @throws IllegalArgumentException when a component is out of range
     */
    public VariationDef(int variants, double length, double width, double curvature, double tilt,
                        double responseTime, double stiffness) {
        this(variants, length, width, curvature, tilt, responseTime, stiffness, 0, 0, 0);
    }

    /**
     * A copy with other colour variation (presentation only; the simulation does not read it). Any
     * thread; allocates.
     *
     * @param hue     s.d. of the per-plant hue shift, degrees, in [0, 60]
     * @param value   s.d. of the per-plant brightness factor, in [0, 0.5]
     * @param dryTips straw colour at the leaf tips, in [0, 1]
     * @return the copy
     * @throws IllegalArgumentException when a value is out of range
     */
    public VariationDef withColour(double hue, double value, double dryTips) {
        return new VariationDef(variants, length, width, curvature, tilt, responseTime, stiffness, hue, value,
                dryTips);
    }

    /**
     * Shape variation only: no response-time or stiffness variation between plants. Any thread;
     * allocates.
     *
     * @param variants  shape variants, in [1, 64]
     * @param length    relative length variation, in [0, 0.9]
     * @param width     relative width variation, in [0, 0.9]
     * @param curvature relative curvature variation, in [0, 0.9]
     * @param tilt      extra tilt, radians, in [0, pi/4]
     * @throws IllegalArgumentException when a component is out of range
     */
    public VariationDef(int variants, double length, double width, double curvature, double tilt) {
        this(variants, length, width, curvature, tilt, 0, 0);
    }

    /** Most shape variants (the scene schema's range and the API's). */
    public static final int MAX_VARIANTS = 64;
    /** Largest relative variation of length, width, curvature, response time and stiffness. */
    public static final double MAX_FRACTION = 0.9;
    /** Largest extra tilt, degrees (the API takes radians). */
    public static final double MAX_TILT_DEGREES = 45;

    /** Largest s.d. of the per-plant hue shift, degrees. */
    public static final double MAX_HUE_DEGREES = 60;
    /** Largest s.d. of the per-plant brightness factor. */
    public static final double MAX_VALUE = 0.5;

    /** No variation: one variant. */
    public static final VariationDef NONE = new VariationDef(1, 0, 0, 0, 0);
}
