package org.jecosys.terrain;

import java.util.Arrays;
import java.util.List;
import org.jecosys.math.Require;

/**
 * Plants placed on a terrain by a {@link TerrainDistributor} (paper §4.3): flat arrays indexed by
 * plant, in the order the plants were placed (hand placements first). Positions are metres on the
 * terrain surface ({@code y = height(x, z)}); azimuths radians; the variant seed picks a plant's
 * per-instance variation. For inspection and tests it also keeps what each plant "saw" when it was
 * placed (footprint-mean water and nutrient levels before it consumed), the resources left after all
 * plants, and the warnings (e.g. a shortfall, or a species that matches nowhere).
 *
 * <p>Immutable; any thread. Per-plant getters do not allocate; the {@code copy*} methods do.
 */
public final class PlantLayout {
    private final float[] x;
    private final float[] y;
    private final float[] z;
    private final float[] azimuth;
    private final float[] footprint;
    private final float[] water;
    private final float[] nutrients;
    private final int[] species;
    private final int[] distribution;
    private final long[] variantSeed;
    private final int[] placedPerDistribution;
    private final int[] targetPerDistribution;
    private final List<String> warnings;
    private final ResourceMap remainingWater;
    private final ResourceMap remainingNutrients;
    private final long occupancyVisits;

    private PlantLayout(Builder b, int[] placed, int[] target, List<String> warnings,
                        ResourceMap remainingWater, ResourceMap remainingNutrients) {
        int n = b.n;
        this.x = Arrays.copyOf(b.x, n);
        this.y = Arrays.copyOf(b.y, n);
        this.z = Arrays.copyOf(b.z, n);
        this.azimuth = Arrays.copyOf(b.azimuth, n);
        this.footprint = Arrays.copyOf(b.footprint, n);
        this.water = Arrays.copyOf(b.water, n);
        this.nutrients = Arrays.copyOf(b.nutrients, n);
        this.species = Arrays.copyOf(b.species, n);
        this.distribution = Arrays.copyOf(b.distribution, n);
        this.variantSeed = Arrays.copyOf(b.variantSeed, n);
        this.placedPerDistribution = placed.clone();
        this.targetPerDistribution = target.clone();
        this.warnings = List.copyOf(warnings);
        this.remainingWater = remainingWater.copy().freeze();
        this.remainingNutrients = remainingNutrients.copy().freeze();
        this.occupancyVisits = b.occupancyVisits;
    }

    /**
     * {@return the buckets and discs the distributor's footprint search looked at while placing (its
     * work, for tests of the placement's cost; 0 when the distributor did not say)}
     */
    long occupancyVisits() {
        return occupancyVisits;
    }

    /** {@return the number of plants} */
    public int count() {
        return x.length;
    }

    /**
     * {@return the X of plant i, metres}
     *
     * @param i plant index, in [0, count())
     */
    public float x(int i) {
        return x[i];
    }

    /**
     * {@return the Y (terrain height under the plant) of plant i, metres}
     *
     * @param i plant index, in [0, count())
     */
    public float y(int i) {
        return y[i];
    }

    /**
     * {@return the Z of plant i, metres}
     *
     * @param i plant index, in [0, count())
     */
    public float z(int i) {
        return z[i];
    }

    /**
     * {@return the rest azimuth of plant i, radians in [0, 2 pi)}
     *
     * @param i plant index, in [0, count())
     */
    public float azimuth(int i) {
        return azimuth[i];
    }

    /**
     * {@return the footprint radius of plant i, metres}
     *
     * @param i plant index, in [0, count())
     */
    public float footprint(int i) {
        return footprint[i];
    }

    /**
     * {@return the species index of plant i (into the species ids given to the distributor)}
     *
     * @param i plant index, in [0, count())
     */
    public int species(int i) {
        return species[i];
    }

    /**
     * {@return the distribution index of plant i, or -1 for a hand placement}
     *
     * @param i plant index, in [0, count())
     */
    public int distribution(int i) {
        return distribution[i];
    }

    /**
     * {@return the variant seed of plant i, which picks its per-instance variation}
     *
     * @param i plant index, in [0, count())
     */
    public long variantSeed(int i) {
        return variantSeed[i];
    }

    /**
     * {@return the footprint-mean water level plant i found when placed (before it consumed), in [0, 1]}
     *
     * @param i plant index, in [0, count())
     */
    public float waterAtPlacement(int i) {
        return water[i];
    }

    /**
     * {@return the footprint-mean nutrient level plant i found when placed (before it consumed), in [0, 1]}
     *
     * @param i plant index, in [0, count())
     */
    public float nutrientsAtPlacement(int i) {
        return nutrients[i];
    }

    /**
     * {@return the number of plants placed by distribution d}
     *
     * @param d distribution index, in the order of the distributor's distributions
     */
    public int placed(int d) {
        return placedPerDistribution[d];
    }

    /**
     * {@return the number of plants distribution d asked for (its count, or density x suitable area)}
     *
     * @param d distribution index, in the order of the distributor's distributions
     */
    public int target(int d) {
        return targetPerDistribution[d];
    }

    /** {@return human-readable warnings, in a fixed order (unmodifiable); empty when every target was met} */
    public List<String> warnings() {
        return warnings;
    }

    /** {@return the water left after all plants consumed (frozen)} */
    public ResourceMap remainingWater() {
        return remainingWater;
    }

    /** {@return the nutrients left after all plants consumed (frozen)} */
    public ResourceMap remainingNutrients() {
        return remainingNutrients;
    }

    /** {@return a copy of all X, metres, one per plant} Allocates. */
    public float[] copyX() {
        return x.clone();
    }

    /** {@return a copy of all Y, metres, one per plant} Allocates. */
    public float[] copyY() {
        return y.clone();
    }

    /** {@return a copy of all Z, metres, one per plant} Allocates. */
    public float[] copyZ() {
        return z.clone();
    }

    /** {@return a copy of all rest azimuths, radians, one per plant} Allocates. */
    public float[] copyAzimuths() {
        return azimuth.clone();
    }

    /** {@return a copy of all footprint radii, metres, one per plant} Allocates. */
    public float[] copyFootprints() {
        return footprint.clone();
    }

    /** {@return a copy of all species indices, one per plant} Allocates. */
    public int[] copySpecies() {
        return species.clone();
    }

    /** {@return a copy of all distribution indices (-1 for hand placements), one per plant} Allocates. */
    public int[] copyDistributions() {
        return distribution.clone();
    }

    /** {@return a copy of all variant seeds, one per plant} Allocates. */
    public long[] copyVariantSeeds() {
        return variantSeed.clone();
    }

    /**
     * Growable per-plant arrays a {@link TerrainDistributor} fills, plant by plant, in placement
     * order. One thread; {@link #add} allocates only when it grows its arrays (doubling).
     */
    public static final class Builder {
        private int n;
        private float[] x = new float[16];
        private float[] y = new float[16];
        private float[] z = new float[16];
        private float[] azimuth = new float[16];
        private float[] footprint = new float[16];
        private float[] water = new float[16];
        private float[] nutrients = new float[16];
        private int[] species = new int[16];
        private int[] distribution = new int[16];
        private long[] variantSeed = new long[16];
        private long occupancyVisits;

        /** An empty builder. */
        public Builder() {
        }

        /** {@return the number of plants added so far} */
        public int size() {
            return n;
        }

        /**
         * Adds one plant.
         *
         * @param px   X, metres
         * @param py   Y (terrain height), metres
         * @param pz   Z, metres
         * @param az   rest azimuth, radians
         * @param fp   footprint radius, metres
         * @param w    footprint-mean water level it found, in [0, 1]
         * @param nu   footprint-mean nutrient level it found, in [0, 1]
         * @param sp   species index
         * @param dist distribution index, or -1 for a hand placement
         * @param seed variant seed
         */
        public void add(float px, float py, float pz, float az, float fp, double w, double nu, int sp, int dist, long seed) {
            if (n == x.length) {
                int cap = n * 2;
                x = Arrays.copyOf(x, cap);
                y = Arrays.copyOf(y, cap);
                z = Arrays.copyOf(z, cap);
                azimuth = Arrays.copyOf(azimuth, cap);
                footprint = Arrays.copyOf(footprint, cap);
                water = Arrays.copyOf(water, cap);
                nutrients = Arrays.copyOf(nutrients, cap);
                species = Arrays.copyOf(species, cap);
                distribution = Arrays.copyOf(distribution, cap);
                variantSeed = Arrays.copyOf(variantSeed, cap);
            }
            x[n] = px;
            y[n] = py;
            z[n] = pz;
            azimuth[n] = az;
            footprint[n] = fp;
            water[n] = (float) w;
            nutrients[n] = (float) nu;
            species[n] = sp;
            distribution[n] = dist;
            variantSeed[n] = seed;
            n++;
        }

        /** Records the footprint search's work (buckets and discs looked at) for the layout. */
        void occupancyVisits(long visits) {
            occupancyVisits = visits;
        }

        /**
         * The layout of the plants added so far. Copies everything it is given (the maps as frozen
         * copies), so the builder and the arguments may be reused.
         *
         * @param placed   plants placed per distribution
         * @param target   plants asked for per distribution, same length as placed
         * @param warnings human-readable warnings
         * @param w        water left after all plants
         * @param nu       nutrients left after all plants
         * @return a new, immutable layout
         * @throws IllegalArgumentException when an argument is null or {@code placed} and
         *                                  {@code target} differ in length
         */
        public PlantLayout build(int[] placed, int[] target, List<String> warnings, ResourceMap w, ResourceMap nu) {
            Require.nonNull("placed", placed);
            Require.nonNull("target", target);
            Require.nonNull("warnings", warnings);
            Require.nonNull("w", w);
            Require.nonNull("nu", nu);
            if (placed.length != target.length) {
                throw new IllegalArgumentException("placed and target must have the same length, got "
                        + placed.length + " and " + target.length);
            }
            return new PlantLayout(this, placed, target, warnings, w, nu);
        }
    }
}
