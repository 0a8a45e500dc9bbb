package org.jecosys.anim;

import org.jecosys.math.Require;

/**
 * The animated state of every plant component in flat arrays indexed by component (paper §4.2;
 * structure of arrays, no object per component or plant), and its updater. Per component:
 * deviation D and velocity v (2D, ground plane,
 * x = X, z = Z); its outputs, the continuous pose coordinate and the bend azimuth, are a pure
 * function of D and the component's constants, written by {@link #animate} into the caller's arrays
 * (the simulation's back frame) and computed on demand by the accessors. Per plant: the force input
 * of the last update and the level of detail. Sized at construction; nothing grows.
 *
 * <h2>Bend</h2>
 * A component's rest shape (pose 0) leans toward its rest heading h (plant rest azimuth + slot
 * azimuth) by its rest lean {@code l} (the horizontal tip offset of pose 0): the lean vector is
 * {@code L = l (cos h, sin h)} in (X, Z), the heading convention of {@code Frame}: the pose table's
 * local +X goes to world {@code (cos a, 0, sin a)}, i.e. angles turn from +X toward +Z. The deviation
 * moves the tip's horizontal position to {@code T = L + D}:
 * <ul>
 * <li>azimuth = direction of T ({@code atan2(Tz, Tx)}): at D = 0 it is the rest heading, so a
 * component at rest keeps its heading and never flips at zero wind;</li>
 * <li>the extra bend is {@code max(0, |T| - l)} metres, computed as {@code (2 L.D + |D|^2) / (|T| + l)}
 * (exactly 0 at D = 0), mapped to the pose coordinate as {@code PoseMapping.poseCoordinate} does:
 * {@code min(K - 1, atan(extra / length) (K - 1) / maxBend)}. A wind against the lean first turns
 * the component (azimuth) and then bends it the other way: its tip follows D to first order.</li>
 * </ul>
 * Arc tangents use a polynomial with error below 5e-7 rad, in the branch-free forms of
 * {@code Trig.poseAngle} and {@code Trig.azimuth} (the arc tangent of the extra bend is taken as
 * {@code atan2(num, (|T| + l) length)} with {@code num = max(0, 2 L.D + |D|^2)}, one division).
 * The output loops and the scalar forms live in {@code BendOutputs}; the spring runs and their step
 * in {@code SpringRuns}.
 *
 * <h2>Update order</h2>
 * At construction the components of each plant are cut into <em>spring runs</em>: maximal runs of
 * consecutive components with the same spring coefficients ({@link SpringKinds#springClass}: the
 * shape variants of one component type share them, so a 25-leaf tuft is one run) and the same
 * level-of-detail mask. {@link #animate} first advances D and v over segments of contiguous runs of
 * one class, across plants: the homogeneous part of eq. 5's map in one loop that C2 vectorises, then
 * each run's force terms (computed once per run from the plant's force), added in the same order as
 * the fused formula, so the bits do not depend on how runs are grouped. It then computes the outputs
 * in a second, branch-free loop over contiguous component ranges, also vectorised. A range may
 * also cover components that were not advanced (a short gap of invisible plants, components outside
 * the level of detail): their outputs are recomputed from their unchanged D and come out
 * bit-identical; components outside every range copy their outputs from the caller's previous ones.
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
    private final float[] plantX;
    private final float[] plantY;
    private final float[] plantZ;
    private final LodBands lod;

    private final short[] kind;
    /*
     * Spring runs (see SpringRuns; the arrays are its own, held here to be read in place). runForce
     * holds, per run, the force terms of its last update.
     */
    private final int[] runStart;
    private final int[] runClass;
    private final int[] runMask;
    private final int[] plantRun;
    private final float[] runForce;
    private final float[] leanX;
    private final float[] leanZ;
    // per-component copies of the kind constants the output loop needs (no gather there)
    private final float[] compLean;
    private final float[] compLength;
    private final float[] compScale;
    private final float[] compPoseMax;
    final float[] devX;
    final float[] devZ;
    final float[] velX;
    final float[] velZ;
    final float[] pressX;
    final float[] pressZ;
    final byte[] level;
    /** Per plant, incremented whenever its deviations may have changed (an update, a reset). */
    private final long[] plantVersion;

    /**
     * State at rest for a set of plants. Build time; allocates. Arrays are copied.
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
        this.kinds = Require.nonNull("kinds", kinds);
        plants = Require.nonNull("plantSpecies", plantSpecies).length;
        if (firstComponent.length != plants + 1 || plantX.length != plants || plantY.length != plants
                || plantZ.length != plants) {
            throw new IllegalArgumentException("firstComponent must hold plants + 1 = " + (plants + 1)
                    + " values and plantX/Y/Z plants = " + plants);
        }
        components = componentKind.length;
        if (restHeading.length != components || firstComponent[plants] != components) {
            throw new IllegalArgumentException("restHeading and firstComponent[plants] must match the "
                    + components + " components");
        }
        this.plantSpecies = plantSpecies.clone();
        this.firstComponent = firstComponent.clone();
        this.plantX = plantX.clone();
        this.plantY = plantY.clone();
        this.plantZ = plantZ.clone();
        this.lod = new LodBands(lodEdges);
        for (int p = 0; p < plants; p++) {
            Require.range("plantSpecies[" + p + "]", plantSpecies[p], 0, lod.species() - 1);
            if (firstComponent[p + 1] < firstComponent[p]) {
                throw new IllegalArgumentException("firstComponent must not decrease, at plant " + p);
            }
        }
        kind = new short[components];
        leanX = new float[components];
        leanZ = new float[components];
        compLean = new float[components];
        compLength = new float[components];
        compScale = new float[components];
        compPoseMax = new float[components];
        for (int c = 0; c < components; c++) {
            int k = Require.range("componentKind[" + c + "]", componentKind[c], 0, kinds.count() - 1);
            kind[c] = (short) k;
            double h = restHeading[c];
            leanX[c] = (float) (kinds.leanMag[k] * Math.cos(h));
            leanZ[c] = (float) (kinds.leanMag[k] * Math.sin(h));
            compLean[c] = kinds.leanMag[k];
            compLength[c] = kinds.length[k];
            compScale[c] = kinds.poseScale[k];
            compPoseMax[c] = kinds.poseMax[k];
        }
        SpringRuns springRuns = new SpringRuns(kinds, kind, this.firstComponent);
        runStart = springRuns.start;
        runClass = springRuns.springClass;
        runMask = springRuns.mask;
        plantRun = springRuns.plantRun;
        runForce = new float[springRuns.count() * SpringRuns.FORCE_STRIDE];
        devX = new float[components];
        devZ = new float[components];
        velX = new float[components];
        velZ = new float[components];
        pressX = new float[plants];
        pressZ = new float[plants];
        level = new byte[plants];
        plantVersion = new long[plants];
        resetToRest(0, plants);
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
     * Puts plants {@code first .. end-1} and their components back at rest: D = v = 0 (hence pose 0
     * and the rest heading), no remembered force. Outputs already written elsewhere (a frame) are not
     * touched: write them again with {@link #copyOutputs}. No allocation.
     *
     * @param first first plant reset
     * @param end   one past the last plant reset; {@code first <= end}
     */
    public void resetToRest(int first, int end) {
        for (int p = first; p < end; p++) {
            pressX[p] = 0;
            pressZ[p] = 0;
            plantVersion[p]++;
        }
        for (int c = firstComponent[first], e = firstComponent[end]; c < e; c++) {
            devX[c] = 0;
            devZ[c] = 0;
            velX[c] = 0;
            velZ[c] = 0;
        }
    }

    /**
     * Advances plants {@code first .. end-1} by one step of the length last given to
     * {@link SpringKinds#prepare} (paper §4.2.2) and, if {@code step} has output arrays, writes the
     * outputs of all their components. Only plants with {@code visible[p]} are updated (the others
     * keep their last state), and of those only the components that their level of detail draws.
     * The level of every plant in the range is recomputed from the eye.
     *
     * <ul>
     * <li>CONSTRAINT: the spring of {@link SpringKinds}, driven from the force at the previous update
     * to the force of wind {@code (windX[p], windZ[p])} (m/s) now;</li>
     * <li>RANDOM: each updated component takes a random deviation in a disc of radius 0.3 length
     * (paper Table 7's S2), from the step's random source;</li>
     * <li>STATIC: nothing moves (see {@link #resetToRest}).</li>
     * </ul>
     *
     * <p>Outputs ({@link AnimationStep#outputs}): for every component c of the range,
     * {@code poseOut[c]} and {@code azimuthOut[c]} receive its pose coordinate and azimuth
     * ({@link #poseCoordinate}, {@link #azimuth}), bit for bit. They are computed for the updated
     * plants (and short gaps between them); the other components' D did not change, so their outputs
     * are copied from {@code poseBefore} and {@code azimuthBefore}, which must hold the outputs of the
     * state before this call (for example the frame published last), but only for plants whose
     * outputs in {@code poseOut} are stale: {@code outVersion[p]} says which {@link #version} of plant
     * p the output arrays hold, and is brought up to date here. Without output arrays
     * ({@link AnimationStep#noOutputs}) no output is written: the outputs are a function of D (see
     * {@link #poseCoordinate}, {@link #copyOutputs}). No allocation.
     *
     * @param first first plant of the range
     * @param end   end of the range (exclusive)
     * @param step  the step's inputs; also holds this call's bookkeeping, so it must not be given to
     *              another call running at the same time
     * @return components updated
     */
    public int animate(int first, int end, AnimationStep step) {
        final boolean out = step.hasOutputs();
        final StepCursor cursor = step.cursor;
        final AnimationMode mode = step.mode;
        final boolean[] visible = step.visible;
        final double eyeX = step.eyeX;
        final double eyeY = step.eyeY;
        final double eyeZ = step.eyeZ;
        cursor.begin(first);
        int updated = 0;
        for (int p = first; p < end; p++) {
            int l = updateLevel(p, eyeX, eyeY, eyeZ);
            if (!visible[p] || mode == AnimationMode.STATIC) {
                continue;
            }
            int bit = 1 << l;
            plantVersion[p]++;
            int c0 = firstComponent[p];
            int c1 = firstComponent[p + 1];
            if (mode == AnimationMode.RANDOM) {
                updated += SpringRuns.randomise(c0, c1, bit, kind, kinds.lodMask, kinds.length, step.rng, devX, devZ,
                        velX, velZ);
            } else {
                updated += queueSpringRuns(p, bit, step.windX[p], step.windZ[p], cursor);
            }
            if (out) {
                cursor.queueOutputs(this, step, p, c0, c1);
            }
        }
        cursor.advanceSegment(this);
        if (out) {
            cursor.finishOutputs(this, step, end);
        }
        return updated;
    }

    /**
     * Recomputes plant p's level of detail from its squared distance (m^2) to the eye (world
     * metres), stores it and returns it.
     */
    private int updateLevel(int p, double eyeX, double eyeY, double eyeZ) {
        double dx = plantX[p] - eyeX;
        double dy = plantY[p] - eyeY;
        double dz = plantZ[p] - eyeZ;
        double d2 = dx * dx + dy * dy + dz * dz;
        int l = lod.level(plantSpecies[p], d2);
        level[p] = (byte) l;
        return l;
    }

    /**
     * CONSTRAINT update of plant p at level-of-detail bit {@code bit}: each of its spring runs drawn
     * at that level gets its force terms ({@link SpringRuns#setForce}) from the plant's force at its
     * last update to the force of wind {@code (ux, uz)} (m/s) now, and is queued on the cursor to be
     * advanced (in segments, see the class comment); the plant then remembers the new force.
     *
     * @return components queued
     */
    private int queueSpringRuns(int p, int bit, float ux, float uz, StepCursor cursor) {
        float speed = (float) Math.sqrt(ux * ux + uz * uz);
        float p1x = speed * ux;
        float p1z = speed * uz;
        float p0x = pressX[p];
        float p0z = pressZ[p];
        int queued = 0;
        for (int r = plantRun[p], re = plantRun[p + 1]; r < re; r++) {
            if ((runMask[r] & bit) == 0) {
                continue;
            }
            int cls = runClass[r];
            SpringRuns.setForce(r, cls, kinds.coef, runForce, p0x, p0z, p1x, p1z);
            queued += runStart[r + 1] - runStart[r];
            cursor.queueRun(this, r, cls, runStart);
        }
        pressX[p] = p1x;
        pressZ[p] = p1z;
        return queued;
    }

    /** Advances runs {@code r0 .. r1-1} (contiguous, all of spring class cls): {@link SpringRuns#spring}. */
    void spring(int r0, int r1, int cls) {
        SpringRuns.spring(r0, r1, cls, kinds.coef, runStart, runForce, devX, devZ, velX, velZ);
    }

    /**
     * Brings the stale outputs of plants [done, p0) up to date from before, computes the outputs of
     * plant p0's first component to component c1 (a plant boundary); returns the plant that starts at
     * c1. The output arrays are the step's.
     */
    int writeOutputs(int done, int p0, int c1, AnimationStep step) {
        copyStale(done, p0, step);
        outputs(firstComponent[p0], c1, step.poseOut, step.azimuthOut);
        int p = p0;
        for (; p < plants && firstComponent[p] < c1; p++) {
            step.outVersion[p] = plantVersion[p];
        }
        return p;
    }

    /** Copies the outputs of plants [p0, p1) whose outVersion is stale from before (runs of them at once). */
    void copyStale(int p0, int p1, AnimationStep step) {
        BendOutputs.copyStale(p0, p1, firstComponent, plantVersion, step.poseOut, step.azimuthOut, step.poseBefore,
                step.azimuthBefore, step.outVersion);
    }

    /**
     * The version of plant p's state: it changes whenever the plant's deviations may have changed
     * (an update by {@link #animate}, {@link #resetToRest}), so equal versions mean equal outputs.
     */
    public long version(int p) {
        return plantVersion[p];
    }

    /**
     * Pose coordinate and azimuth of components {@code c0 .. c1-1} from their deviations (see the
     * class comment) into {@code pose} and {@code azimuth} (indexed by component):
     * {@link BendOutputs#outputs}, the same arithmetic as {@link #poseCoordinate} and {@link #azimuth}.
     */
    private void outputs(int c0, int c1, float[] pose, float[] azimuth) {
        BendOutputs.outputs(c0, c1, devX, devZ, leanX, leanZ, compLean, compLength, compScale, compPoseMax, pose,
                azimuth);
    }

    /**
     * Writes the pose coordinates and azimuths of components {@code first .. end-1}, computed from
     * their current deviations, into the dest arrays (same indices). Any thread that owns the range
     * (as {@link #animate}). No allocation.
     */
    public void copyOutputs(int first, int end, float[] poseDest, float[] azimuthDest) {
        outputs(first, end, poseDest, azimuthDest);
    }

    /** Copies the levels of plants {@code first .. end-1} into dest (same indices). */
    public void copyLevels(int first, int end, byte[] dest) {
        System.arraycopy(level, first, dest, first, end - first);
    }

    /** Deviation X of component c, metres. */
    public float deviationX(int c) {
        return devX[c];
    }

    /** Deviation Z of component c, metres. */
    public float deviationZ(int c) {
        return devZ[c];
    }

    /** Velocity X of component c, m/s. */
    public float velocityX(int c) {
        return velX[c];
    }

    /** Velocity Z of component c, m/s. */
    public float velocityZ(int c) {
        return velZ[c];
    }

    /**
     * Pose coordinate of component c, in [0, K - 1], computed from its deviation (scalar, the same
     * operations as the output loops of {@link #animate}, hence the same bits). No allocation.
     */
    public float poseCoordinate(int c) {
        return BendOutputs.poseCoordinate(c, devX, devZ, leanX, leanZ, compLean, compLength, compScale, compPoseMax);
    }

    /**
     * Bend azimuth of component c, radians in [-pi, pi] (local +X to (cos a, 0, sin a)), computed from
     * its deviation (as {@link #poseCoordinate}). No allocation.
     */
    public float azimuth(int c) {
        return BendOutputs.azimuth(c, devX, devZ, leanX, leanZ);
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
                * pressX[plantOf(c)];
    }

    /** Force on component c at the plant's last update, N, Z part. */
    public double forceZ(int c) {
        return 0.5 * org.jecosys.field.DragLaw.AIR_DENSITY * kinds.dragArea(kind[c])
                * pressZ[plantOf(c)];
    }

    /** The plant of component c (binary search; not for per-frame use on every component). */
    public int plantOf(int c) {
        int lo = 0;
        int hi = plants - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (firstComponent[mid] <= c) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo;
    }

    /** Level of detail plant p was last animated at. */
    public int level(int p) {
        return level[p];
    }

    /**
     * A 64-bit FNV-1a hash of the raw float bits of D, v, pose and azimuth of every component, in
     * component order: equal states give equal hashes. One thread, no range running. No allocation.
     */
    public long stateHash() {
        long h = 0xcbf29ce484222325L;
        for (int c = 0; c < components; c++) {
            h = mix(h, Float.floatToRawIntBits(devX[c]));
            h = mix(h, Float.floatToRawIntBits(devZ[c]));
            h = mix(h, Float.floatToRawIntBits(velX[c]));
            h = mix(h, Float.floatToRawIntBits(velZ[c]));
            h = mix(h, Float.floatToRawIntBits(poseCoordinate(c)));
            h = mix(h, Float.floatToRawIntBits(azimuth(c)));
        }
        return h;
    }

    private static long mix(long h, int bits) {
        for (int i = 0; i < 4; i++) {
            h ^= (bits >>> (8 * i)) & 0xff;
            h *= 0x100000001b3L;
        }
        return h;
    }
}
