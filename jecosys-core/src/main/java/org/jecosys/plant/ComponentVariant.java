package org.jecosys.plant;

import org.jecosys.math.Require;
import org.jecosys.math.Rng;

/**
 * The seeded changes one shape variant applies to one component type (paper §4.1: "small changes
 * in their skeletons can generate a great variety of components shapes"). Mass follows the area,
 * {@code mass * lengthScale * widthScale}. Immutable; any thread.
 *
 * @param lengthScale    factor on the length, in [1 - v.length, 1 + v.length] times the variant's size-class
 *                       factor {@link VariationDef#sizeScale} (1 with one size class)
 * @param widthScale     factor on both widths, in [1 - v.width, 1 + v.width]
 * @param curvatureScale factor on the rest curvature, in [1 - v.curvature, 1 + v.curvature]
 * @param extraTilt      added to the tilt (the sum clamped to [0, pi/2]), radians, in [0, v.tilt]
 */
public record ComponentVariant(double lengthScale, double widthScale, double curvatureScale, double extraTilt) {
    /** Smallest length factor: the shortest length variation in the smallest size class. */
    public static final double MIN_LENGTH_SCALE = (1 - VariationDef.MAX_FRACTION) * (1 - VariationDef.MAX_FRACTION);
    /** Largest length factor: the longest length variation in the largest size class. */
    public static final double MAX_LENGTH_SCALE = (1 + VariationDef.MAX_FRACTION) * (1 + VariationDef.MAX_FRACTION);

    /** The unchanged component. */
    public static final ComponentVariant IDENTITY = new ComponentVariant(1, 1, 1, 0);

    /**
     * Checks the components.
     *
     * @param lengthScale    factor on the length, in [{@link #MIN_LENGTH_SCALE}, {@link #MAX_LENGTH_SCALE}]
     * @param widthScale     factor on both widths, in [0.1, 1.9]
     * @param curvatureScale factor on the rest curvature, in [0.1, 1.9]
     * @param extraTilt      added tilt, radians, in [0, pi/4]
     * @throws IllegalArgumentException when a component is out of range
     */
    public ComponentVariant {
        Require.range("lengthScale", lengthScale, MIN_LENGTH_SCALE, MAX_LENGTH_SCALE);
        Require.range("widthScale", widthScale, 0.1, 1.9);
        Require.range("curvatureScale", curvatureScale, 0.1, 1.9);
        Require.range("extraTilt", extraTilt, 0, Math.PI / 4);
    }

    /**
     * Draws the variant {@code variant} of component type {@code component} from {@code seed}:
     * a pure function of its arguments (its own {@link Rng} sub-stream), so a species built twice
     * with one seed is identical and different seeds give different shapes. The length factor is the
     * drawn variation times the variant's size-class factor ({@link VariationDef#sizeScale}, exactly 1
     * with one size class, so such a species draws what it always drew).
     *
     * @param v         the species' variation
     * @param seed      the species' shape seed
     * @param variant   variant index, in [0, v.variants())
     * @param component component type index within the species
     * @return the variant (allocates)
     */
    public static ComponentVariant sample(VariationDef v, long seed, int variant, int component) {
        Require.nonNull("v", v);
        Rng rng = Rng.forStream(seed, (long) variant * 1024 + component);
        double len = (1 + v.length() * rng.nextDouble(-1, 1)) * v.sizeScale(variant);
        double wid = 1 + v.width() * rng.nextDouble(-1, 1);
        double cur = 1 + v.curvature() * rng.nextDouble(-1, 1);
        double tilt = v.tilt() * rng.nextDouble();
        return new ComponentVariant(len, wid, cur, tilt);
    }
}
