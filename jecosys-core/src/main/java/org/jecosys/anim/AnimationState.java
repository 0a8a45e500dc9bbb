package org.jecosys.anim;

import org.jecosys.math.Require;

/**
 * The animated state of every plant component in flat arrays indexed by component (paper §4.2;
 * structure of arrays, no object per component or plant), and its updater. Per component:
 * deviation D and velocity v (2D, ground plane, x = X, z = Z); its outputs, the continuous pose
 * coordinate and the bend azimuth, are a pure function of D and the component's constants
 * ({@link BendGeometry}), computed on demand. Per plant: the force input of the last update, the
 * level of detail, its response variant and compliance (the seeded variation of response time and
 * stiffness between plants, {@link SpringKinds}), and whether its state follows the wind (see
 * "Start"). Sized at construction; nothing grows.
 *
 * <h2>Bend</h2>
 * How D turns a component's rest shape into its pose coordinate and azimuth: see {@link BendGeometry}.
 *
 * <h2>Start</h2>
 * A plant's state follows the wind once it has been animated and as long as it stays visible. A
 * plant that does not (new, or invisible at the last update, or in RANDOM mode) starts its next
 * CONSTRAINT update at the equilibrium of that update's wind, at zero velocity: the field does not
 * lean in from upright at start-up, and a plant coming into view is already bent by the wind.
 * {@link #settle} does the same for the wind at a given time (the simulation's first sample, at
 * t = 0), and {@link #resetToRest} puts plants at rest as a state that does follow (STATIC mode).
 * The mapping from D to the outputs lives in {@link BendGeometry}; the spring runs, their state and
 * their step in {@code SpringRuns}; the step of a plant range ({@link #animate}) in {@code RangeUpdate};
 * the checks of the constructors' arrays in {@code StateArrays}.
 *
 * <h2>Update order</h2>
 * At construction the components of each plant are cut into <em>spring runs</em> ({@link SpringRuns}):
 * maximal runs of consecutive components with the same spring coefficients
 * ({@link SpringKinds#springClass}: the shape variants of one component type share them, so a 25-leaf
 * tuft is one run) and the same level-of-detail mask. The components of a run are driven by the same
 * force from the same start, so they share one D and one v, kept once per run: {@link #animate}
 * advances each drawn run of a plant once (the per-component update's arithmetic, hence its bits)
 * and writes the run's D to each of its components. The outputs, which differ per component through
 * its rest lean and shape, are not part of the step: they are computed where they are read, from D
 * ({@link BendGeometry}; {@link #copyOutputs} for many at once; a renderer on the GPU). RANDOM mode
 * gives each component its own deviation, kept per component ({@link ScatteredState})
 * until the plant settles again.
 *
 * <h2>Threads</h2>
 * {@link #animate} touches only the plants of its range and their components, so disjoint ranges
 * may run on different threads at once; the results do not depend on which thread runs a range
 * (no reductions, no shared random state). Everything else: one thread while no range runs.
 * Nothing here allocates after construction.
 */
public final class AnimationState implements AnimationView {
    private final SpringKinds kinds;
    private final int plants;
    private final int components;
    private final int[] plantSpecies;
    private final int[] firstComponent;
    /** Where the plants stand and their levels of detail. */
    private final PlantLevels levels;
    private final LodBands lod;

    private final short[] kind;
    /** The spring runs and their D, v and force (see "Update order"). */
    private final SpringRuns runs;
    /** Per-component D and v of plants in RANDOM mode. */
    private final ScatteredState scattered;
    // per component the constants that map its D to pose and azimuth
    private final BendGeometry geometry;
    /** Per component its deviation, packed ({@link SpringRuns#pack}): {@link SpringRuns#compDev}, read in place. */
    private final long[] dev;
    private final float[] plantCompliance;
    /** Per plant its force, whether it follows the wind, and the CONSTRAINT update ({@link PlantSprings}). */
    private final PlantSprings springs;
    /** The step of a plant range: levels, then the mode's update ({@link #animate}). */
    private final RangeUpdate ranges;
    /** Per plant, incremented whenever its deviations may have changed (an update, a reset). */
    private final long[] plantVersion;
    /** The flattening of plants whose species leave trails, or null when none does ({@link #useTrails}). */
    private Trails trails;

    /**
     * State for a set of plants, all in their nominal response variant with their species' stiffness:
     * {@link #AnimationState(SpringKinds, double[][], int[], int[], float[], float[], float[], int[], float[],
     * byte[], float[])} without variation between plants. Build time; allocates. Arrays are copied.
     *
     * @param kinds          the component kinds
     * @param lodEdges       per species, the ascending distances (metres) where its levels of detail end,
     *                       the last (unbounded) level left out
     * @param plantSpecies   per plant, its species index into {@code lodEdges}
     * @param firstComponent per plant its first component, plus the total at the end (length plants + 1)
     * @param plantX         per plant X, metres
     * @param plantY         per plant base height, metres
     * @param plantZ         per plant Z, metres
     * @param componentKind  per component its kind
     * @param restHeading    per component its rest heading h, radians (plant rest azimuth + slot azimuth)
     */
    public AnimationState(SpringKinds kinds, double[][] lodEdges, int[] plantSpecies, int[] firstComponent,
                          float[] plantX, float[] plantY, float[] plantZ, int[] componentKind, float[] restHeading) {
        this(kinds, lodEdges, plantSpecies, firstComponent, plantX, plantY, plantZ, componentKind, restHeading,
                null, null);
    }

    /**
     * State for a set of plants: D = v = 0 (pose 0), every plant to start at the equilibrium of the
     * wind of its first update (see "Start" in the class comment). Build time; allocates. Arrays are
     * copied.
     *
     * @param kinds          the component kinds
     * @param lodEdges       per species, the ascending distances (metres) where its levels of detail end,
     *                       the last (unbounded) level left out
     * @param plantSpecies   per plant, its species index into {@code lodEdges}
     * @param firstComponent per plant its first component, plus the total at the end (length plants + 1)
     * @param plantX         per plant X, metres
     * @param plantY         per plant base height, metres
     * @param plantZ         per plant Z, metres
     * @param componentKind  per component its kind
     * @param restHeading    per component its rest heading h, radians (plant rest azimuth + slot azimuth)
     * @param response       per plant its response variant, in [0, {@link SpringKinds#RESPONSE_VARIANTS}),
     *                       or null for {@link SpringKinds#NOMINAL_VARIANT} everywhere
     * @param compliance     per plant the factor on its equilibrium deviation (1 / its stiffness factor),
     *                       in [0.5, 10], or null for 1 everywhere
     * @throws IllegalArgumentException when an array has the wrong length or a value is out of range
     */
    public AnimationState(SpringKinds kinds, double[][] lodEdges, int[] plantSpecies, int[] firstComponent,
                          float[] plantX, float[] plantY, float[] plantZ, int[] componentKind, float[] restHeading,
                          byte[] response, float[] compliance) {
        this(kinds, lodEdges, plantSpecies, firstComponent, plantX, plantY, plantZ, componentKind,
                BendGeometry.of(Require.nonNull("kinds", kinds), componentKind, restHeading), response, compliance);
    }

    /**
     * As {@link #AnimationState(SpringKinds, double[][], int[], int[], float[], float[], float[], int[],
     * float[], byte[], float[])}, with the components' bend geometry built already (from the same kinds
     * and their rest headings, {@link BendGeometry#of}) and shared, not copied. Build time; allocates.
     *
     * @param kinds          the component kinds
     * @param lodEdges       per species, the ascending distances (metres) where its levels of detail end,
     *                       the last (unbounded) level left out
     * @param plantSpecies   per plant, its species index into {@code lodEdges}
     * @param firstComponent per plant its first component, plus the total at the end (length plants + 1)
     * @param plantX         per plant X, metres
     * @param plantY         per plant base height, metres
     * @param plantZ         per plant Z, metres
     * @param componentKind  per component its kind
     * @param geometry       the bend geometry of the components, one entry per component
     * @param response       per plant its response variant, or null (as the other constructor)
     * @param compliance     per plant the factor on its equilibrium deviation, or null (as the other
     *                       constructor)
     * @throws IllegalArgumentException when an array has the wrong length or a value is out of range
     */
    public AnimationState(SpringKinds kinds, double[][] lodEdges, int[] plantSpecies, int[] firstComponent,
                          float[] plantX, float[] plantY, float[] plantZ, int[] componentKind, BendGeometry geometry,
                          byte[] response, float[] compliance) {
        this.kinds = Require.nonNull("kinds", kinds);
        plants = Require.nonNull("plantSpecies", plantSpecies).length;
        // the checks in this order, so that a bad input gets the same message whatever else is wrong
        components = StateArrays.components(plants, firstComponent, plantX, plantY, plantZ, componentKind, geometry);
        this.plantSpecies = plantSpecies.clone();
        this.firstComponent = firstComponent.clone();
        levels = new PlantLevels(lodEdges, plantSpecies, plantX, plantY, plantZ);
        lod = levels.bands;
        StateArrays.checkAscending(firstComponent, plants);
        kind = StateArrays.kinds(kinds, componentKind);
        this.geometry = geometry;
        byte[] plantResponse = new byte[plants];
        plantCompliance = new float[plants];
        StateArrays.variation(response, compliance, plantResponse, plantCompliance);
        runs = new SpringRuns(kinds, kind, this.firstComponent, plantCompliance);
        dev = runs.compDev;
        scattered = new ScatteredState(plants, components);
        plantVersion = new long[plants];
        springs = new PlantSprings(kinds, runs, scattered, plantVersion, plantResponse);
        ranges = new RangeUpdate(kinds, levels, runs, scattered, springs, kind, this.firstComponent, plantVersion);
        resetToRest(0, plants);
        java.util.Arrays.fill(springs.live, false);
    }

    /**
     * Lets the species with a recovery time leave trails: a push past their threshold flattens a plant,
     * which then recovers over that time ({@link Trails}; {@code org.jecosys.plant.TrailDef}). Species
     * with recovery 0 move exactly as before, bit for bit; with 0 everywhere nothing changes. Build
     * time, before the first update; allocates.
     *
     * @param recovery  per species, the recovery time, seconds, in [0, 3600]
     * @param flattenAt per species, the equilibrium bend (a fraction of the bend limit) that flattens,
     *                  in [0.1, 0.95]
     * @throws IllegalArgumentException when an array does not hold one value per species or a value is
     *                                  out of range
     */
    public void useTrails(double[] recovery, double[] flattenAt) {
        if (recovery.length != lod.species()) {
            throw new IllegalArgumentException("recovery must hold one value per species (" + lod.species()
                    + "), got " + recovery.length);
        }
        trails = Trails.of(recovery, flattenAt, plantSpecies);
        springs.trails = trails;
    }

    /**
     * {@inheritDoc} ({@link #useTrails}). Any thread between updates; no allocation.
     */
    @Override
    public float flattening(int p) {
        return trails == null ? 0f : trails.flattening(p);
    }

    /**
     * The smallest wind speed that can flatten plant p ({@link #useTrails}): the speed of a push whose
     * equilibrium bend reaches its species' threshold, less 0.1% for rounding; a push slower than this
     * never flattens it. Infinite when its species leaves no trails. Any thread; no allocation.
     *
     * @param p plant index
     * @return m/s, &gt; 0
     */
    public double flatteningSpeed(int p) {
        if (trails == null || !trails.on(p)) {
            return Double.POSITIVE_INFINITY;
        }
        return 0.999 * runs.speedFor(runs.plantRun[p], trails.flattenAt(p));
    }

    /** The kinds. */
    public SpringKinds kinds() {
        return kinds;
    }

    /** Number of plants. */
    public int plantCount() {
        return plants;
    }

    /** Number of components. */
    public int componentCount() {
        return components;
    }

    /** First component of plant p; {@code firstComponent(plantCount())} is the component count. */
    public int firstComponent(int p) {
        return firstComponent[p];
    }

    /**
     * Scales every species' level-of-detail distances (a LOD bias: 2 keeps detail twice as far).
     * Between updates only. No allocation.
     *
     * @param scale in [0.01, 100]
     */
    public void setLodScale(double scale) {
        lod.setScale(scale);
    }

    /** The level-of-detail distance scale. */
    public double lodScale() {
        return lod.scale();
    }

    /**
     * Where level l of species s ends, metres, with the LOD scale applied: a plant is at level l when
     * its distance to the eye is at least {@code lodEdge(s, l - 1)} and below {@code lodEdge(s, l)}.
     * Any thread between updates; no allocation.
     *
     * @param species species index
     * @param l       level, below the species' last
     * @return the distance, metres
     */
    public double lodEdge(int species, int l) {
        return lod.edge(species, l);
    }

    /**
     * Replaces the level-of-detail distances of one species (the viewer's sliders). Between updates
     * only; allocates a copy.
     *
     * @param species      species index
     * @param maxDistances ascending distances where each level but the last ends, metres, &gt; 0
     * @throws IllegalArgumentException when the count is not the species' levels - 1 or the
     *                                  distances do not ascend
     */
    public void setLodDistances(int species, double[] maxDistances) {
        lod.setEdges(species, maxDistances);
    }

    /**
     * Puts plants {@code first .. end-1} and their components back at rest: D = v = 0 (hence pose 0
     * and the rest heading), no remembered force, as a state that the next CONSTRAINT update
     * continues from (the plants lean into the wind from upright). Outputs already written elsewhere
     * (a frame) are not touched: write them again with {@link #copyOutputs}. No allocation.
     *
     * @param first first plant reset
     * @param end   one past the last plant reset; {@code first <= end}
     */
    public void resetToRest(int first, int end) {
        springs.restRange(first, end);
    }

    /**
     * Puts the visible plants of {@code first .. end-1} ({@code step}'s visibility) at the equilibrium
     * of {@code step}'s wind, at zero velocity, and makes it the force their next update starts from:
     * the state of a field that has been in this wind for ever (the simulation calls it with the wind
     * at t = 0 before its first step). Every component of a plant is set, whatever its level of
     * detail; other plants are not touched. The step's mode and outputs are not used. Any thread that
     * owns the range (as {@link #animate}); no allocation.
     *
     * @param first first plant
     * @param end   end of the range (exclusive)
     * @param step  the wind (m/s) and visibility per plant
     * @return plants settled
     */
    public int settle(int first, int end, AnimationStep step) {
        return springs.settleVisible(first, end, step);
    }

    /** Largest wind component the spring takes, m/s: far beyond any real wind, and |u|^2 stays finite. */
    public static final float MAX_WIND = 1e9f;

    /**
     * Advances plants {@code first .. end-1} by one step of the length last given to
     * {@link SpringKinds#prepare} (paper §4.2.2). Only plants with {@code visible[p]} are updated (the others
     * keep their last state), and of those only the components that their level of detail draws.
     * The level of every plant in the range is recomputed from the eye.
     *
     * <ul>
     * <li>CONSTRAINT: the spring of {@link SpringKinds}, driven from the force at the previous update
     * to the force of wind {@code (windX[p], windZ[p])} (m/s) now; a plant that did not follow the
     * wind starts at the equilibrium of that wind (see "Start" in the class comment);</li>
     * <li>RANDOM: each updated component takes a random deviation in a disc of radius 0.3 length
     * (paper Table 7's S2), from the step's random source;</li>
     * <li>STATIC: nothing moves (see {@link #resetToRest}).</li>
     * </ul>
     *
     * <p>Each plant updated gets a new {@link #version}. The outputs (pose coordinate and azimuth) are
     * a function of D: {@link #poseCoordinate}, {@link #azimuth}, {@link #copyOutputs}, or a frame's
     * {@link BendGeometry}. No allocation.
     *
     * @param first first plant of the range
     * @param end   end of the range (exclusive)
     * @param step  the step's inputs (read only)
     * @return components updated
     */
    public int animate(int first, int end, AnimationStep step) {
        return ranges.animate(first, end, step);
    }

    /** The plants' levels of detail (this package's tests). */
    PlantLevels levels() {
        return levels;
    }

    /**
     * The version of plant p's state: it changes whenever the plant's deviations may have changed
     * (an update by {@link #animate}, {@link #resetToRest}), so equal versions mean equal outputs.
     */
    public long version(int p) {
        return plantVersion[p];
    }

    /**
     * Writes the pose coordinates and azimuths of components {@code first .. end-1}, computed from
     * their current deviations, into the dest arrays (same indices). Any thread that owns the range
     * (as {@link #animate}). No allocation.
     */
    public void copyOutputs(int first, int end, float[] poseDest, float[] azimuthDest) {
        geometry.outputs(first, end, dev, poseDest, azimuthDest); // the arithmetic of poseCoordinate, azimuth
    }

    /** Copies the levels of plants {@code first .. end-1} into dest (same indices). */
    public void copyLevels(int first, int end, byte[] dest) {
        levels.copy(first, end, dest);
    }

    /** Deviation X of component c, metres. */
    public float deviationX(int c) {
        return SpringRuns.unpackX(dev[c]);
    }

    /** Deviation Z of component c, metres. */
    public float deviationZ(int c) {
        return SpringRuns.unpackZ(dev[c]);
    }

    /** Velocity X of component c, m/s. */
    public float velocityX(int c) {
        int p = plantOf(c);
        return scattered.scattered[p] ? scattered.velX[c] : runs.velX(runs.runOf(p, c));
    }

    /** Velocity Z of component c, m/s. */
    public float velocityZ(int c) {
        int p = plantOf(c);
        return scattered.scattered[p] ? scattered.velZ[c] : runs.velZ(runs.runOf(p, c));
    }

    /**
     * Pose coordinate of component c, in [0, K - 1], computed from its deviation (scalar, the same
     * operations as the output loops of {@link #animate}, hence the same bits). No allocation.
     */
    public float poseCoordinate(int c) {
        return geometry.poseCoordinate(c, SpringRuns.unpackX(dev[c]), SpringRuns.unpackZ(dev[c]));
    }

    /**
     * Bend azimuth of component c, radians in [-pi, pi] (local +X to (cos a, 0, sin a)), computed from
     * its deviation (as {@link #poseCoordinate}). No allocation.
     */
    public float azimuth(int c) {
        return geometry.azimuth(c, SpringRuns.unpackX(dev[c]), SpringRuns.unpackZ(dev[c]));
    }

    /**
     * {@return the constants that map each component's deviation to its pose coordinate and azimuth}
     * (immutable; the published frames compute their outputs through it)
     */
    public BendGeometry geometry() {
        return geometry;
    }

    /**
     * Copies the deviations D of components {@code first .. end-1} into {@code dest}, one bulk copy: the
     * render states of a published frame. {@code dest} is a view of little-endian bytes, one long per
     * component at its absolute index, which those bytes hold as two floats, X then Z, metres
     * ({@code ByteBuffer.order(ByteOrder.LITTLE_ENDIAN).asLongBuffer()}). Any thread that owns the
     * range (as {@link #animate}). No allocation.
     *
     * @param first first component
     * @param end   end of the range (exclusive)
     * @param dest  receives the deviations ({@code end} longs at least), little-endian
     * @throws IllegalArgumentException when dest is not little-endian
     */
    public void copyDeviations(int first, int end, java.nio.LongBuffer dest) {
        if (dest.order() != java.nio.ByteOrder.LITTLE_ENDIAN) {
            throw new IllegalArgumentException("dest must be a view of little-endian bytes");
        }
        dest.put(first, dev, first, end - first);
    }

    /** Kind of component c. */
    public int kind(int c) {
        return kind[c];
    }

    /** Bend of component c beyond its rest shape, radians: pose coordinate x maxBend / (K - 1). */
    public float bend(int c) {
        int k = kind[c];
        return poseCoordinate(c) / kinds.poseScale[k];
    }

    /**
     * Force on component c at the plant's last update, N, X part: {@code 0.5 rho dragArea |u| u_x}.
     */
    public double forceX(int c) {
        return 0.5 * org.jecosys.field.DragLaw.AIR_DENSITY * kinds.dragArea(kind[c])
                * springs.pressX[plantOf(c)];
    }

    /** Force on component c at the plant's last update, N, Z part. */
    public double forceZ(int c) {
        return 0.5 * org.jecosys.field.DragLaw.AIR_DENSITY * kinds.dragArea(kind[c])
                * springs.pressZ[plantOf(c)];
    }

    /** The plant of component c (binary search; not for per-frame use on every component). */
    public int plantOf(int c) {
        return StateArrays.plantOf(firstComponent, plants, c);
    }

    /** Level of detail plant p was last animated at. */
    public int level(int p) {
        return levels.level(p);
    }

    /**
     * A 64-bit FNV-1a hash of the raw float bits of D, v, pose and azimuth of every component, in
     * component order, then of every plant's flattening when a species leaves trails: equal states
     * give equal hashes. One thread, no range running. No allocation.
     */
    public long stateHash() {
        return StateHash.of(this, runs, scattered, trails);
    }
}
