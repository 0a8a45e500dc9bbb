package org.jecosys.terrain;

import org.jecosys.math.Require;
import org.jecosys.math.Rng;

/**
 * Where and how many plants of one species grow (paper §4.3). Plants are placed concurrently with
 * the other distributions, each consuming resources in its footprint. Immutable; any thread.
 *
 * @param species      id of the species
 * @param count        exact number of plants, in [0, 10,000,000], or -1 to use {@code density}
 * @param density      plants per square metre where conditions hold (used when count is -1), in [0, 10000]
 * @param minWater     lowest water level the species accepts, in [0, 1]
 * @param maxWater     highest water level, in [minWater, 1]
 * @param minNutrients lowest nutrient level, in [0, 1]
 * @param maxNutrients highest nutrient level, in [minNutrients, 1]
 * @param maxSlope     steepest ground, radians, in [0, pi/2]
 * @param minAltitude  lowest terrain height, metres
 * @param maxAltitude  highest terrain height, metres, &gt;= minAltitude
 * @param footprint    radius of ground a plant takes, metres, in (0, 100]
 * @param waterUse     water level a plant consumes in its footprint, in [0, 1]
 * @param nutrientUse  nutrient level a plant consumes in its footprint, in [0, 1]
 * @param clumpSize    typical radius of a clump (patch) of this species, metres, in
 *                     [{@link #MIN_CLUMP_SIZE}, {@link #MAX_CLUMP_SIZE}]
 * @param clumpStrength how strongly candidates gather into clumps, in [0, 1]: 0 places them uniformly
 *                     over the suitable ground (the paper's layout, bit for bit), 1 only inside the clumps
 *                     (see {@link CompetitiveDistributor})
 * @param tuftSize     small-scale grouping (not in the paper): standard deviation, metres, of a tuft's
 *                     candidates around their shared centre, in [{@link #MIN_TUFT_SIZE},
 *                     {@link #MAX_TUFT_SIZE}]; read only when {@code tuftCount > 1}
 * @param tuftCount    candidates drawn around each tuft centre, in [1, {@link #MAX_TUFT_COUNT}]: 1 draws
 *                     every candidate on its own (the paper's layout, bit for bit), more gather plants into
 *                     tufts (tussocks) of up to that many within about {@code 2 tuftSize} of each other
 *                     (see {@link CompetitiveDistributor})
 * @param tuftBunches  bunches a tuft splits into (not in the paper; a bunchgrass's hollow crown, whose
 *                     middle dies back and leaves a ring of daughter bunches), in [1,
 *                     {@link #MAX_TUFT_BUNCHES}]: each of the tuft's candidates joins one of that many bunches
 *                     at random (so bunches differ in size), the bunches' centres stand on a ring of radius
 *                     {@code tuftRing} round the tuft's centre (see {@link #bunchCentres}), and the
 *                     candidates spread round their bunch's centre by {@code tuftSize}; 1
 *                     (the default) keeps one bunch at the centre, the layout bit for bit as without it
 * @param tuftRing     radius, metres, of the ring the bunches stand on, in [0, {@link #MAX_TUFT_SIZE}];
 *                     read only when {@code tuftBunches > 1} and {@code tuftCount > 1}
 */
public record DistributionDef(String species, int count, double density, double minWater, double maxWater,
                              double minNutrients, double maxNutrients, double maxSlope, double minAltitude,
                              double maxAltitude, double footprint, double waterUse, double nutrientUse,
                              double clumpSize, double clumpStrength, double tuftSize, int tuftCount,
                              int tuftBunches, double tuftRing) {
    /** Largest exact count. */
    public static final int MAX_COUNT = 10_000_000;
    /** Largest density, plants per square metre (the scene schema's range and the API's). */
    public static final double MAX_DENSITY = 10_000;
    /** Steepest maxSlope, degrees (the API takes radians). */
    public static final double MAX_SLOPE_DEGREES = 90;
    /** Largest |altitude| bound, metres. */
    public static final double MAX_ALTITUDE = 1e5;
    /** Smallest footprint radius, metres. */
    public static final double MIN_FOOTPRINT = 1e-3;
    /** Largest footprint radius, metres. */
    public static final double MAX_FOOTPRINT = 100;
    /** Smallest clump radius, metres. */
    public static final double MIN_CLUMP_SIZE = 0.05;
    /** Largest clump radius, metres. */
    public static final double MAX_CLUMP_SIZE = 1000;
    /** Smallest tuft size, metres. */
    public static final double MIN_TUFT_SIZE = 0.005;
    /** Largest tuft size, metres. */
    public static final double MAX_TUFT_SIZE = 10;
    /** Most candidates per tuft centre. */
    public static final int MAX_TUFT_COUNT = 64;
    /** Most bunches per tuft. */
    public static final int MAX_TUFT_BUNCHES = 16;
    /** Largest move of a bunch along its tuft's ring, as a share of the bunches' even spacing. */
    public static final double BUNCH_JITTER = 0.1;

    /**
     * Checks the components.
     *
     * @param species      species id, not null
     * @param count        exact number of plants, in [-1, {@link #MAX_COUNT}]; -1 uses density
     * @param density      plants per square metre, in [0, {@link #MAX_DENSITY}]
     * @param minWater     lowest water level, in [0, 1]
     * @param maxWater     highest water level, in [minWater, 1]
     * @param minNutrients lowest nutrient level, in [0, 1]
     * @param maxNutrients highest nutrient level, in [minNutrients, 1]
     * @param maxSlope     steepest ground, radians, in [0, {@link #MAX_SLOPE_DEGREES}] degrees
     * @param minAltitude  lowest terrain height, metres, |minAltitude| &lt;= {@link #MAX_ALTITUDE}
     * @param maxAltitude  highest terrain height, metres, &gt;= minAltitude and &lt;= {@link #MAX_ALTITUDE}
     * @param footprint    radius of ground a plant takes, metres, in [{@link #MIN_FOOTPRINT},
     *                     {@link #MAX_FOOTPRINT}]
     * @param waterUse     water level a plant consumes, in [0, 1]
     * @param nutrientUse  nutrient level a plant consumes, in [0, 1]
     * @param clumpSize    clump radius, metres, in [{@link #MIN_CLUMP_SIZE}, {@link #MAX_CLUMP_SIZE}]
     * @param clumpStrength clumping, in [0, 1]; 0 for none
     * @param tuftSize      tuft spread (s.d.), metres, in [{@link #MIN_TUFT_SIZE}, {@link #MAX_TUFT_SIZE}]
     * @param tuftCount     candidates per tuft centre, in [1, {@link #MAX_TUFT_COUNT}]; 1 for none
     * @param tuftBunches   bunches per tuft, in [1, {@link #MAX_TUFT_BUNCHES}]; 1 for one at the centre
     * @param tuftRing      radius of the bunches' ring, metres, in [0, {@link #MAX_TUFT_SIZE}]
     * @throws IllegalArgumentException when a component is out of range or species is null
     */
    public DistributionDef {
        Require.nonNull("species", species);
        Require.range("count", count, -1, MAX_COUNT);
        Require.range("density", density, 0, MAX_DENSITY);
        Require.range("minWater", minWater, 0, 1);
        Require.range("maxWater", maxWater, minWater, 1);
        Require.range("minNutrients", minNutrients, 0, 1);
        Require.range("maxNutrients", maxNutrients, minNutrients, 1);
        Require.degrees("maxSlope", maxSlope, 0, MAX_SLOPE_DEGREES);
        Require.range("minAltitude", minAltitude, -MAX_ALTITUDE, MAX_ALTITUDE);
        Require.range("maxAltitude", maxAltitude, -MAX_ALTITUDE, MAX_ALTITUDE);
        if (maxAltitude < minAltitude) {
            throw new IllegalArgumentException("maxAltitude must be >= minAltitude");
        }
        Require.range("footprint", footprint, MIN_FOOTPRINT, MAX_FOOTPRINT);
        Require.range("waterUse", waterUse, 0, 1);
        Require.range("nutrientUse", nutrientUse, 0, 1);
        Require.range("clumpSize", clumpSize, MIN_CLUMP_SIZE, MAX_CLUMP_SIZE);
        Require.range("clumpStrength", clumpStrength, 0, 1);
        Require.range("tuftSize", tuftSize, MIN_TUFT_SIZE, MAX_TUFT_SIZE);
        Require.range("tuftCount", tuftCount, 1, MAX_TUFT_COUNT);
        Require.range("tuftBunches", tuftBunches, 1, MAX_TUFT_BUNCHES);
        Require.range("tuftRing", tuftRing, 0, MAX_TUFT_SIZE);
    }

    /** Default {@link #count()}: -1, place by {@link #density()}. */
    public static final int DEFAULT_COUNT = -1;
    /** Default {@link #density()}, plants per square metre. */
    public static final double DEFAULT_DENSITY = 1;
    /** Default {@link #minWater()}: any water level. */
    public static final double DEFAULT_MIN_WATER = 0;
    /** Default {@link #maxWater()}: any water level. */
    public static final double DEFAULT_MAX_WATER = 1;
    /** Default {@link #minNutrients()}: any nutrient level. */
    public static final double DEFAULT_MIN_NUTRIENTS = 0;
    /** Default {@link #maxNutrients()}: any nutrient level. */
    public static final double DEFAULT_MAX_NUTRIENTS = 1;
    /** Default {@link #maxSlope()}, radians: any slope (pi/2). */
    public static final double DEFAULT_MAX_SLOPE = Math.PI / 2;
    /** Default {@link #minAltitude()}, metres: the lowest height a scene may have. */
    public static final double DEFAULT_MIN_ALTITUDE = -1e5;
    /** Default {@link #maxAltitude()}, metres: the highest height a scene may have. */
    public static final double DEFAULT_MAX_ALTITUDE = 1e5;
    /** Default {@link #footprint()}, metres. */
    public static final double DEFAULT_FOOTPRINT = 0.2;
    /** Default {@link #waterUse()}. */
    public static final double DEFAULT_WATER_USE = 0.5;
    /** Default {@link #nutrientUse()}. */
    public static final double DEFAULT_NUTRIENT_USE = 0.5;
    /** Default {@link #clumpSize()}, metres. */
    public static final double DEFAULT_CLUMP_SIZE = 1;
    /** Default {@link #clumpStrength()}: no clumping, the paper's uniform candidates. */
    public static final double DEFAULT_CLUMP_STRENGTH = 0;
    /** Default {@link #tuftSize()}, metres (read only when {@link #tuftCount()} is above 1). */
    public static final double DEFAULT_TUFT_SIZE = 0.1;
    /** Default {@link #tuftCount()}: no tufts, every candidate drawn on its own. */
    public static final int DEFAULT_TUFT_COUNT = 1;
    /** Default {@link #tuftBunches()}: one bunch, at the tuft's centre. */
    public static final int DEFAULT_TUFT_BUNCHES = 1;
    /** Default {@link #tuftRing()}, metres (read only when {@link #tuftBunches()} is above 1). */
    public static final double DEFAULT_TUFT_RING = 0;

    /**
     * A builder for a distribution of {@code species}, every value at the scene schema's default
     * ({@code DEFAULT_*}): what a {@code <distribution species="...">} element loads as. Any thread;
     * allocates.
     *
     * @param species id of the species
     * @return a new builder
     */
    public static Builder builder(String species) {
        return new Builder(species);
    }

    /**
     * The centres of one tuft's {@link #tuftBunches()} bunches round the tuft's centre (x, z): evenly
     * spaced on a circle of radius {@link #tuftRing()}, the circle turned at random, each bunch moved
     * along it by up to {@link #BUNCH_JITTER} of the spacing, so that the bunches do not stand in
     * regular polygons. The placement's streams call it once per tuft (fixed scenes and tiles alike).
     * Any thread; no allocation; draws {@code tuftBunches + 1} numbers from rng.
     *
     * @param rng the tuft's random stream, not null
     * @param x   the tuft's centre, metres
     * @param z   the tuft's centre, metres
     * @param bx  receives the bunches' X, metres; length at least tuftBunches
     * @param bz  receives the bunches' Z, metres; length at least tuftBunches
     */
    public void bunchCentres(Rng rng, double x, double z, double[] bx, double[] bz) {
        int n = tuftBunches;
        double step = 2 * Math.PI / n;
        double turn = rng.nextDouble() * step;
        for (int b = 0; b < n; b++) {
            double a = turn + step * (b + BUNCH_JITTER * (2 * rng.nextDouble() - 1));
            bx[b] = x + tuftRing * Math.cos(a);
            bz[b] = z + tuftRing * Math.sin(a);
        }
    }

    /**
     * A builder holding every value of this def, to change a few. Any thread; allocates.
     *
     * @return a new builder
     */
    public Builder toBuilder() {
        return new Builder(species).count(count).density(density).water(minWater, maxWater)
                .nutrients(minNutrients, maxNutrients).maxSlope(maxSlope).altitude(minAltitude, maxAltitude)
                .footprint(footprint).waterUse(waterUse).nutrientUse(nutrientUse).clump(clumpSize, clumpStrength)
                .tufts(tuftSize, tuftCount).bunches(tuftRing, tuftBunches);
    }

    /**
     * Fluent builder of a {@link DistributionDef} with the scene schema's defaults (see
     * {@link DistributionDef#builder}); values are checked by {@link #build()}. One thread; allocates.
     */
    public static final class Builder {
        private final String species;
        private int count = DEFAULT_COUNT;
        private double density = DEFAULT_DENSITY;
        private double minWater = DEFAULT_MIN_WATER;
        private double maxWater = DEFAULT_MAX_WATER;
        private double minNutrients = DEFAULT_MIN_NUTRIENTS;
        private double maxNutrients = DEFAULT_MAX_NUTRIENTS;
        private double maxSlope = DEFAULT_MAX_SLOPE;
        private double minAltitude = DEFAULT_MIN_ALTITUDE;
        private double maxAltitude = DEFAULT_MAX_ALTITUDE;
        private double footprint = DEFAULT_FOOTPRINT;
        private double waterUse = DEFAULT_WATER_USE;
        private double nutrientUse = DEFAULT_NUTRIENT_USE;
        private double clumpSize = DEFAULT_CLUMP_SIZE;
        private double clumpStrength = DEFAULT_CLUMP_STRENGTH;
        private double tuftSize = DEFAULT_TUFT_SIZE;
        private int tuftCount = DEFAULT_TUFT_COUNT;
        private int tuftBunches = DEFAULT_TUFT_BUNCHES;
        private double tuftRing = DEFAULT_TUFT_RING;

        private Builder(String species) {
            this.species = species;
        }

        /**
         * Sets an exact number of plants.
         *
         * @param count in [0, {@link #MAX_COUNT}], or -1 to use the density
         * @return this builder
         */
        public Builder count(int count) {
            this.count = count;
            return this;
        }

        /**
         * Sets the density used when the count is -1.
         *
         * @param density plants per square metre, in [0, 10000]
         * @return this builder
         */
        public Builder density(double density) {
            this.density = density;
            return this;
        }

        /**
         * Sets the water levels the species accepts.
         *
         * @param min lowest, in [0, 1]
         * @param max highest, in [min, 1]
         * @return this builder
         */
        public Builder water(double min, double max) {
            this.minWater = min;
            this.maxWater = max;
            return this;
        }

        /**
         * Sets the nutrient levels the species accepts.
         *
         * @param min lowest, in [0, 1]
         * @param max highest, in [min, 1]
         * @return this builder
         */
        public Builder nutrients(double min, double max) {
            this.minNutrients = min;
            this.maxNutrients = max;
            return this;
        }

        /**
         * Sets the steepest ground the species accepts.
         *
         * @param maxSlope radians, in [0, pi/2]
         * @return this builder
         */
        public Builder maxSlope(double maxSlope) {
            this.maxSlope = maxSlope;
            return this;
        }

        /**
         * Sets the terrain heights the species accepts.
         *
         * @param min lowest, metres
         * @param max highest, metres, &gt;= min
         * @return this builder
         */
        public Builder altitude(double min, double max) {
            this.minAltitude = min;
            this.maxAltitude = max;
            return this;
        }

        /**
         * Sets the radius of ground a plant takes.
         *
         * @param footprint metres, in (0, 100]
         * @return this builder
         */
        public Builder footprint(double footprint) {
            this.footprint = footprint;
            return this;
        }

        /**
         * Sets the water level a plant consumes in its footprint.
         *
         * @param waterUse in [0, 1]
         * @return this builder
         */
        public Builder waterUse(double waterUse) {
            this.waterUse = waterUse;
            return this;
        }

        /**
         * Sets the nutrient level a plant consumes in its footprint.
         *
         * @param nutrientUse in [0, 1]
         * @return this builder
         */
        public Builder nutrientUse(double nutrientUse) {
            this.nutrientUse = nutrientUse;
            return this;
        }

        /**
         * Sets the clumping: candidates gather into seeded patches of about {@code size} metres radius.
         *
         * @param size     clump radius, metres, in [{@link #MIN_CLUMP_SIZE}, {@link #MAX_CLUMP_SIZE}]
         * @param strength in [0, 1]; 0 for none (uniform candidates), 1 for candidates only in clumps
         * @return this builder
         */
        public Builder clump(double size, double strength) {
            this.clumpSize = size;
            this.clumpStrength = strength;
            return this;
        }

        /**
         * Sets the tufts: {@code count} candidates drawn around each shared centre, offsets normal with
         * standard deviation {@code size} (a Thomas cluster process; see {@link CompetitiveDistributor}).
         *
         * @param size  metres, in [{@link #MIN_TUFT_SIZE}, {@link #MAX_TUFT_SIZE}]
         * @param count candidates per centre, in [1, {@link #MAX_TUFT_COUNT}]; 1 for none
         * @return this builder
         */
        public Builder tufts(double size, int count) {
            this.tuftSize = size;
            this.tuftCount = count;
            return this;
        }

        /**
         * Sets the bunches a tuft splits into (a bunchgrass's hollow crown): each of the tuft's
         * candidates joins one of {@code count} bunches at random, whose centres stand on a ring of radius
         * {@code ring} round the tuft's centre ({@link DistributionDef#bunchCentres}); {@link #tufts} gives
         * the spread round each bunch.
         *
         * @param ring  ring radius, metres, in [0, {@link #MAX_TUFT_SIZE}]
         * @param count bunches per tuft, in [1, {@link #MAX_TUFT_BUNCHES}]; 1 for one at the centre
         * @return this builder
         */
        public Builder bunches(double ring, int count) {
            this.tuftBunches = count;
            this.tuftRing = ring;
            return this;
        }

        /**
         * The def. Allocates.
         *
         * @return a new def
         * @throws IllegalArgumentException when a value is out of range (see {@link DistributionDef})
         */
        public DistributionDef build() {
            return new DistributionDef(species, count, density, minWater, maxWater, minNutrients, maxNutrients,
                    maxSlope, minAltitude, maxAltitude, footprint, waterUse, nutrientUse, clumpSize, clumpStrength,
                    tuftSize, tuftCount, tuftBunches, tuftRing);
        }
    }
}
