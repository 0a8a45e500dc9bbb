package org.jecosys.plant;

import org.jecosys.math.Require;

/**
 * Per-instance variation of a species (paper §4.1: "small changes in their skeletons can generate
 * a great variety of components shapes"). A species pre-computes {@code variants} shape variants;
 * each plant picks one by seed and adds its own rest azimuth. Fractions are relative
 * (0.1 = up to plus or minus 10%). Immutable; any thread.
 *
 * <h2>Size classes and uneven tufts (not in the paper)</h2>
 * A plant's component instances use different variants (the slot of instance {@code j} uses
 * {@link #slotVariant}), so the leaves of a tuft differ in length, width, curvature and lean. With one
 * size class (the default) they cycle through <em>all</em> variants, and a tuft with as many leaves as
 * there are variants has the same leaves, so the same height, as every other. With
 * {@code sizeClasses} K &gt; 1 the variants are split into K consecutive classes of nearly equal size
 * (variant v is in class {@code floor(v K / variants)}); a plant's instances cycle only through its
 * own class's variants, and every variant of class g has the lengths and widths of its component types
 * on the ground (leaves, stalks) scaled by {@code 1 + size (2 (g + 0.5) / K - 1)}, evenly spaced in
 * [1 - size, 1 + size], while what sits on them (petals, heads) keeps its size: plants differ in height
 * while still picking among precomputed shapes (the pose tables stay per variant). With
 * {@code azimuth} &gt; 0 the ground instances of a multi-instance type leave their golden-angle spread
 * by a seeded offset each, uniform in [-azimuth, azimuth], so a tuft's leaves bunch and gap unevenly
 * (the layout is the species', turned by each plant's own rest azimuth).
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
 * @param size      relative spread of plant size between size classes, in [0, 0.9]: the classes' factors on
 *                  the length of every component type on the ground lie evenly in [1 - size, 1 + size]; no
 *                  effect with one class
 * @param sizeClasses number of plant size classes the variants are split into, in [1, variants]; 1 (the
 *                  paper's layout) lets a plant's instances use every variant
 * @param azimuth   largest seeded offset of a ground instance's azimuth from the even (golden-angle)
 *                  spread, radians, in [0, pi]; 0 keeps the even spread
 */
public record VariationDef(int variants, double length, double width, double curvature, double tilt,
                           double responseTime, double stiffness, double hue, double value, double dryTips,
                           double size, int sizeClasses, double azimuth) {
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
     * @param size      relative size spread of the size classes, in [0, 0.9]
     * @param sizeClasses size classes, in [1, variants]
     * @param azimuth   largest azimuth offset of a ground instance, radians, in [0, pi]
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
        Require.range("size", size, 0, MAX_FRACTION);
        if (sizeClasses < 1 || sizeClasses > variants) {
            throw new IllegalArgumentException("sizeClasses must be in [1, variants = " + variants
                    + "] (each class needs a variant of its own), got " + sizeClasses);
        }
        Require.degrees("azimuth", azimuth, 0, MAX_AZIMUTH_DEGREES);
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
                dryTips, size, sizeClasses, azimuth);
    }

    /**
     * A copy with other size classes and azimuth spread (see the class comment). Any thread; allocates.
     *
     * @param size        relative size spread of the classes, in [0, 0.9]
     * @param sizeClasses size classes, in [1, variants()]
     * @param azimuth     largest azimuth offset of a ground instance, radians, in [0, pi]
     * @return the copy
     * @throws IllegalArgumentException when a value is out of range
     */
    public VariationDef withTufts(double size, int sizeClasses, double azimuth) {
        return new VariationDef(variants, length, width, curvature, tilt, responseTime, stiffness, hue, value,
                dryTips, size, sizeClasses, azimuth);
    }

    /**
     * {@return the size class of a variant: {@code floor(variant sizeClasses / variants)}} Pure; no
     * allocation.
     *
     * @param variant shape variant, in [0, variants())
     */
    public int sizeClassOf(int variant) {
        return (int) ((long) variant * sizeClasses / variants);
    }

    /**
     * {@return the factor of a variant's size class on the length of every component type on the ground:
     * {@code 1 + size (2 (class + 0.5) / sizeClasses - 1)}, exactly 1 with one class} Pure; no allocation.
     *
     * @param variant shape variant, in [0, variants())
     */
    public double sizeScale(int variant) {
        if (sizeClasses == 1) {
            return 1;
        }
        return 1 + size * (2 * (sizeClassOf(variant) + 0.5) / sizeClasses - 1);
    }

    /**
     * The variant that instance {@code offset} of a component type uses in a plant of variant
     * {@code plantVariant}: the plant's variant advanced by the offset, cyclically within the plant's
     * size class ({@code (plantVariant + offset) mod variants} with one class, the paper's). Pure; no
     * allocation; any thread.
     *
     * @param plantVariant the plant's variant, in [0, variants())
     * @param offset       the instance's index within its type, &gt;= 0
     * @return a variant of the plant's size class, in [0, variants())
     */
    public int slotVariant(int plantVariant, int offset) {
        if (sizeClasses == 1) {
            return (plantVariant + offset) % variants;
        }
        int g = sizeClassOf(plantVariant);
        int start = classStart(g);
        int n = classStart(g + 1) - start;
        return start + (plantVariant - start + offset) % n;
    }

    /** First variant of size class g (g = sizeClasses gives variants): {@code ceil(g variants / sizeClasses)}. */
    private int classStart(int g) {
        return (int) (((long) g * variants + sizeClasses - 1) / sizeClasses);
    }

    /** Most shape variants (the scene schema's range and the API's). */
    public static final int MAX_VARIANTS = 64;
    /** Largest relative variation of length, width, curvature, response time and stiffness. */
    public static final double MAX_FRACTION = 0.9;
    /** Largest extra tilt, degrees (the API takes radians). */
    public static final double MAX_TILT_DEGREES = 45;

    /** Largest azimuth offset of a ground instance, degrees (the API takes radians). */
    public static final double MAX_AZIMUTH_DEGREES = 180;
    /** Default {@link #size()}: no size spread. */
    public static final double DEFAULT_SIZE = 0;
    /** Default {@link #sizeClasses()}: one class, every variant open to every plant (the paper's). */
    public static final int DEFAULT_SIZE_CLASSES = 1;
    /** Default {@link #azimuth()}, radians: the even spread. */
    public static final double DEFAULT_AZIMUTH = 0;

    /** Largest s.d. of the per-plant hue shift, degrees. */
    public static final double MAX_HUE_DEGREES = 60;
    /** Largest s.d. of the per-plant brightness factor. */
    public static final double MAX_VALUE = 0.5;

    /** Default {@link #variants()}: one shape. */
    public static final int DEFAULT_VARIANTS = 1;

    /** No variation: one variant, {@code builder().build()}, what a species without {@code <variation>} has. */
    public static final VariationDef NONE = builder().build();

    /**
     * A builder with every value at the scene schema's default: one variant, no variation, one size
     * class, the even azimuth spread (what an empty {@code <variation/>} element loads as). Any thread;
     * allocates.
     *
     * @return a new builder
     */
    public static Builder builder() {
        return new Builder();
    }

    /**
     * A builder holding every value of this def, to change a few. Any thread; allocates.
     *
     * @return a new builder
     */
    public Builder toBuilder() {
        return new Builder().variants(variants).length(length).width(width).curvature(curvature).tilt(tilt)
                .responseTime(responseTime).stiffness(stiffness).hue(hue).value(value).dryTips(dryTips).size(size)
                .sizeClasses(sizeClasses).azimuth(azimuth);
    }

    /**
     * Fluent builder of a {@link VariationDef} with the scene schema's defaults (see
     * {@link VariationDef#builder}); values are checked by {@link #build()}. One thread; allocates.
     */
    public static final class Builder {
        private int variants = DEFAULT_VARIANTS;
        private double length = 0;
        private double width = 0;
        private double curvature = 0;
        private double tilt = 0;
        private double responseTime = 0;
        private double stiffness = 0;
        private double hue = 0;
        private double value = 0;
        private double dryTips = 0;
        private double size = DEFAULT_SIZE;
        private int sizeClasses = DEFAULT_SIZE_CLASSES;
        private double azimuth = DEFAULT_AZIMUTH;

        private Builder() {
        }

        /**
         * Sets the number of shape variants (default 1).
         *
         * @param variants shape variants sharing pose tables, in [1, {@link #MAX_VARIANTS}]
         * @return this builder
         */
        public Builder variants(int variants) {
            this.variants = variants;
            return this;
        }

        /**
         * Sets the relative length variation (default 0).
         *
         * @param length in [0, {@link #MAX_FRACTION}]
         * @return this builder
         */
        public Builder length(double length) {
            this.length = length;
            return this;
        }

        /**
         * Sets the relative width variation (default 0).
         *
         * @param width in [0, {@link #MAX_FRACTION}]
         * @return this builder
         */
        public Builder width(double width) {
            this.width = width;
            return this;
        }

        /**
         * Sets the relative curvature variation (default 0).
         *
         * @param curvature in [0, {@link #MAX_FRACTION}]
         * @return this builder
         */
        public Builder curvature(double curvature) {
            this.curvature = curvature;
            return this;
        }

        /**
         * Sets the extra tilt from vertical (default 0).
         *
         * @param tilt radians, in [0, pi/4]
         * @return this builder
         */
        public Builder tilt(double tilt) {
            this.tilt = tilt;
            return this;
        }

        /**
         * Sets the relative response-time variation from plant to plant (default 0).
         *
         * @param responseTime in [0, {@link #MAX_FRACTION}]
         * @return this builder
         */
        public Builder responseTime(double responseTime) {
            this.responseTime = responseTime;
            return this;
        }

        /**
         * Sets the relative stiffness variation from plant to plant (default 0).
         *
         * @param stiffness in [0, {@link #MAX_FRACTION}]
         * @return this builder
         */
        public Builder stiffness(double stiffness) {
            this.stiffness = stiffness;
            return this;
        }

        /**
         * Sets the s.d. of the per-plant hue shift (default 0; colour only).
         *
         * @param hue degrees of hue, in [0, {@link #MAX_HUE_DEGREES}]
         * @return this builder
         */
        public Builder hue(double hue) {
            this.hue = hue;
            return this;
        }

        /**
         * Sets the s.d. of the per-plant brightness factor (default 0; colour only).
         *
         * @param value in [0, {@link #MAX_VALUE}]
         * @return this builder
         */
        public Builder value(double value) {
            this.value = value;
            return this;
        }

        /**
         * Sets how far the leaf tips turn straw-coloured (default 0; colour only).
         *
         * @param dryTips in [0, 1]
         * @return this builder
         */
        public Builder dryTips(double dryTips) {
            this.dryTips = dryTips;
            return this;
        }

        /**
         * Sets the relative size spread of the size classes (default {@link #DEFAULT_SIZE}).
         *
         * @param size in [0, {@link #MAX_FRACTION}]
         * @return this builder
         */
        public Builder size(double size) {
            this.size = size;
            return this;
        }

        /**
         * Sets the number of size classes (default {@link #DEFAULT_SIZE_CLASSES}).
         *
         * @param sizeClasses in [1, variants]
         * @return this builder
         */
        public Builder sizeClasses(int sizeClasses) {
            this.sizeClasses = sizeClasses;
            return this;
        }

        /**
         * Sets the largest azimuth offset of a ground instance (default {@link #DEFAULT_AZIMUTH}).
         *
         * @param azimuth radians, in [0, pi]
         * @return this builder
         */
        public Builder azimuth(double azimuth) {
            this.azimuth = azimuth;
            return this;
        }

        /**
         * The def. Allocates.
         *
         * @return a new def
         * @throws IllegalArgumentException when a value is out of range
         */
        public VariationDef build() {
            return new VariationDef(variants, length, width, curvature, tilt, responseTime, stiffness, hue, value, dryTips, size,
                    sizeClasses, azimuth);
        }
    }
}
