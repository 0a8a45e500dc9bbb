package org.jecosys.plant;

import org.jecosys.math.Require;
import org.jecosys.math.Rng;

/**
 * The seeded changes one shape variant applies to one component type (paper §4.1: "small changes
 * in their skeletons can generate a great variety of components shapes"). Mass follows the area,
 * {@code mass * lengthScale * widthScale}. Immutable; any thread.
 *
 * @param lengthScale    factor on the length: drawn in [1 - v.length, 1 + v.length], and for a component type
 *                       on the ground times the variant's size-class factor {@link VariationDef#sizeScale}
 *                       (applied by the species build; 1 with one size class)
 * @param widthScale     factor on both widths: drawn in [1 - v.width, 1 + v.width], and for a component type
 *                       on the ground times the size-class factor too (a bigger plant is stouter, so its
 *                       stalks bend under their own weight as a smaller one's do)
 * @param curvatureScale factor on the rest curvature, in [1 - v.curvature, 1 + v.curvature]
 * @param extraTilt      added to the tilt (the sum clamped to [0, pi/2]), radians, in [0, v.tilt]
 */
public record ComponentVariant(double lengthScale, double widthScale, double curvatureScale, double extraTilt) {
    /** Smallest length or width factor: the shortest drawn length in the smallest size class. */
    public static final double MIN_LENGTH_SCALE = (1 - VariationDef.MAX_FRACTION) * (1 - VariationDef.MAX_FRACTION);
    /** Largest length or width factor: the longest drawn length in the largest size class. */
    public static final double MAX_LENGTH_SCALE = (1 + VariationDef.MAX_FRACTION) * (1 + VariationDef.MAX_FRACTION);

    /** The unchanged component. */
    public static final ComponentVariant IDENTITY = new ComponentVariant(1, 1, 1, 0);

    /**
     * Checks the components.
     *
     * @param lengthScale    factor on the length, in [{@link #MIN_LENGTH_SCALE}, {@link #MAX_LENGTH_SCALE}]
     * @param widthScale     factor on both widths, in [{@link #MIN_LENGTH_SCALE}, {@link #MAX_LENGTH_SCALE}]
     * @param curvatureScale factor on the rest curvature, in [0.1, 1.9]
     * @param extraTilt      added tilt, radians, in [0, pi/4]
     * @throws IllegalArgumentException when a component is out of range
     */
    public ComponentVariant {
        Require.range("lengthScale", lengthScale, MIN_LENGTH_SCALE, MAX_LENGTH_SCALE);
        Require.range("widthScale", widthScale, MIN_LENGTH_SCALE, MAX_LENGTH_SCALE);
        Require.range("curvatureScale", curvatureScale, 0.1, 1.9);
        Require.range("extraTilt", extraTilt, 0, Math.PI / 4);
    }

    /**
     * Draws the variant {@code variant} of component type {@code component} from {@code seed}:
     * a pure function of its arguments (its own {@link Rng} sub-stream), so a species built twice
     * with one seed is identical and different seeds give different shapes. The size-class factor is not
     * in it: the species build applies it to the component types on the ground.
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
        double len = 1 + v.length() * rng.nextDouble(-1, 1);
        double wid = 1 + v.width() * rng.nextDouble(-1, 1);
        double cur = 1 + v.curvature() * rng.nextDouble(-1, 1);
        double tilt = v.tilt() * rng.nextDouble();
        return new ComponentVariant(len, wid, cur, tilt);
    }
}
