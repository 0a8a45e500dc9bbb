package org.jecosys.anim;

/**
 * The CONSTRAINT update of one plant for {@link AnimationState} (paper §4.2.2; see "Start" and
 * "Update order" there): per plant the force {@code P = |u| u} of its last update, whether its
 * state follows the wind, its response variant, and the update that drives its spring runs
 * ({@link SpringRuns}) from the force of the last update to that of the wind now, through its
 * flattening when its species leaves trails ({@link Trails}); and the resets that put plants at rest
 * or at the equilibrium of a wind. A caller touches only its own plants,
 * so disjoint plant ranges may run at once. Built once (allocates); nothing else allocates.
 */
final class PlantSprings {
    /** Largest wind component the spring takes, m/s ({@link AnimationState#MAX_WIND}). */
    private static final float MAX_WIND = AnimationState.MAX_WIND;

    private final SpringKinds kinds;
    private final SpringRuns runs;
    private final ScatteredState scattered;
    /** Per plant, incremented whenever its deviations may have changed (shared with the state). */
    private final long[] version;
    /** Per plant its response variant (a row of the spring coefficients). */
    private final byte[] response;
    /** Per plant, whether its state follows the wind (see "Start" in {@link AnimationState}). */
    final boolean[] live;
    /** Per plant, the force P of its last update, m^2/s^2. */
    final float[] pressX;
    final float[] pressZ;
    /** The trails of the plants whose species leave them, or null. */
    Trails trails;

    PlantSprings(SpringKinds kinds, SpringRuns runs, ScatteredState scattered, long[] version, byte[] response) {
        this.kinds = kinds;
        this.runs = runs;
        this.scattered = scattered;
        this.version = version;
        this.response = response;
        int plants = response.length;
        live = new boolean[plants];
        pressX = new float[plants];
        pressZ = new float[plants];
    }

    /**
     * A wind component made safe for the spring: NaN (from a user force field) becomes 0 and the
     * magnitude is capped at {@link AnimationState#MAX_WIND} m/s, so that {@code |u| u} stays finite
     * in float.
     */
    static float finiteWind(float u) {
        // Math.max(-MAX_WIND, Math.min(MAX_WIND, u)) for a number, -0 kept, without the intrinsics'
        // handling of NaN and signed zeros (NaN is out already)
        return u == u ? u > MAX_WIND ? MAX_WIND : u < -MAX_WIND ? -MAX_WIND : u : 0f;
    }

    /** Puts plant p at rest with no remembered force, as a state that follows the wind. */
    void rest(int p) {
        pressX[p] = 0;
        pressZ[p] = 0;
        live[p] = true;
        scattered.scattered[p] = false;
        version[p]++;
    }

    /**
     * Puts plants {@code first .. end-1} and their spring runs at rest, with no remembered force and no
     * flattening, as a state that follows the wind ({@link AnimationState#resetToRest}).
     */
    void restRange(int first, int end) {
        for (int p = first; p < end; p++) {
            rest(p);
        }
        runs.rest(runs.plantRun[first], runs.plantRun[end]);
        if (trails != null) {
            trails.clear(first, end);
        }
    }

    /**
     * Puts the visible plants of {@code first .. end-1} at the equilibrium of the step's wind, remembered
     * as their force ({@link AnimationState#settle}); other plants are not touched.
     *
     * @return plants settled
     */
    int settleVisible(int first, int end, AnimationStep step) {
        int settled = 0;
        for (int p = first; p < end; p++) {
            if (step.visible[p]) {
                settle(p, step.windX[p], step.windZ[p]);
                settled++;
            }
        }
        return settled;
    }

    /** Puts plant p at the equilibrium of wind (ux, uz), m/s, remembered as its force; it then follows the wind. */
    void settle(int p, float ux, float uz) {
        ux = finiteWind(ux);
        uz = finiteWind(uz);
        float speed = (float) Math.sqrt(ux * ux + uz * uz);
        float px = speed * ux;
        float pz = speed * uz;
        SpringRuns sr = runs;
        for (int r = sr.plantRun[p], re = sr.plantRun[p + 1]; r < re; r++) {
            sr.settle(r, px, pz);
        }
        pressX[p] = px;
        pressZ[p] = pz;
        live[p] = true;
        scattered.scattered[p] = false;
        version[p]++;
    }

    /**
     * The CONSTRAINT update of the visible plants of {@code [first, end)}, each at the level of detail
     * {@code levels} holds for it, with the step's wind (and pushes, for a species that leaves trails):
     * a new version for each, then {@link #springRuns}, written out here for a plant that is not
     * flattened (all of them while no trail is being left) so that the JIT compiles it into this loop:
     * as a method of its own it is too large to be inlined, and a call per plant cost more than its
     * arithmetic. No allocation.
     *
     * @return components advanced
     */
    int update(int first, int end, PlantLevels levels, AnimationStep step) {
        boolean[] visible = step.visible;
        float[] windX = step.windX;
        float[] windZ = step.windZ;
        float[] pushX = step.pushX;
        float[] pushZ = step.pushZ;
        Trails tr = trails;
        SpringRuns sr = runs;
        float[] coef = kinds.coef;
        // the arrays in locals: the JIT then checks their bounds once for the loop, not per plant
        // after each (rare) call the loop makes
        long[] ver = version;
        boolean[] follows = live;
        float[] p0X = pressX;
        float[] p0Z = pressZ;
        byte[] variants = response;
        int[] plantRun = sr.plantRun;
        int[] mask = sr.mask;
        int[] springClass = sr.springClass;
        int advanced = 0;
        for (int p = first; p < end; p++) {
            if (!visible[p]) {
                continue;
            }
            ver[p]++;
            int bit = 1 << levels.level(p);
            int trail = tr == null ? Trails.NONE : tr.mode(p);
            if (trail == Trails.FLATTENED
                    || trail == Trails.UPRIGHT && pushX != null && (pushX[p] != 0 || pushZ[p] != 0)) {
                advanced += flattenedRuns(p, bit, step);
                continue;
            }
            // springRuns(p, bit, ux, uz, 0, 0, 0, 0), term for term
            float ux = windX[p];
            float uz = windZ[p];
            if (!follows[p]) {
                settle(p, ux, uz);
            }
            ux = finiteWind(ux);
            uz = finiteWind(uz);
            float speed = (float) Math.sqrt(ux * ux + uz * uz);
            float p1x = speed * ux;
            float p1z = speed * uz;
            float p0x = p0X[p];
            float p0z = p0Z[p];
            int variant = variants[p];
            for (int r = plantRun[p], re = plantRun[p + 1]; r < re; r++) {
                if ((mask[r] & bit) != 0) {
                    sr.advance(r, coef, SpringKinds.row(springClass[r], variant) * SpringKinds.STRIDE, p0x, p0z,
                            p1x, p1z);
                    advanced += sr.size(r);
                }
            }
            p0X[p] = p1x;
            p0Z[p] = p1z;
        }
        return advanced;
    }

    /**
     * CONSTRAINT update of plant p at level-of-detail bit {@code bit}: a plant that does not follow the
     * wind is first settled at the equilibrium of wind {@code (ux, uz)} (m/s); then each of its spring
     * runs drawn at that level is advanced from the plant's force at its last update to the force of
     * that wind with its coefficient row (spring class and the plant's response variant), toward rest
     * points flattened by L0 at the start of the step and L1 at its end ({@link Trails}; all four 0:
     * the elastic update, bit for bit); the plant then remembers the new force.
     *
     * @return components advanced
     */
    private int springRuns(int p, int bit, float ux, float uz, float l0x, float l0z, float l1x, float l1z) {
        if (!live[p]) {
            settle(p, ux, uz);
        }
        ux = finiteWind(ux);
        uz = finiteWind(uz);
        float speed = (float) Math.sqrt(ux * ux + uz * uz);
        float p1x = speed * ux;
        float p1z = speed * uz;
        float p0x = pressX[p];
        float p0z = pressZ[p];
        boolean flat = l0x != 0 || l0z != 0 || l1x != 0 || l1z != 0;
        int variant = response[p];
        int advanced = 0;
        SpringRuns sr = runs;
        float[] coef = kinds.coef;
        for (int r = sr.plantRun[p], re = sr.plantRun[p + 1]; r < re; r++) {
            if ((sr.mask[r] & bit) == 0) {
                continue;
            }
            int o = SpringKinds.row(sr.springClass[r], variant) * SpringKinds.STRIDE;
            if (flat) {
                sr.advanceFlattened(r, coef, o, p0x, p0z, p1x, p1z, l0x, l0z, l1x, l1z);
            } else {
                sr.advance(r, coef, o, p0x, p0z, p1x, p1z);
            }
            advanced += sr.size(r);
        }
        pressX[p] = p1x;
        pressZ[p] = p1z;
        return advanced;
    }

    /**
     * {@link #springRuns} for a plant whose species leaves trails ({@link Trails}) and that is flattened
     * or pushed this step ({@link #update} takes the others itself): the push of the flows
     * that flatten ({@link AnimationStep#pushes}) may flatten it at the step's end time; the flattening
     * at the plant's last update and at that time enter the runs' rest points; while both are 0 the
     * runs advance exactly as without trails.
     *
     * @return components advanced
     */
    private int flattenedRuns(int p, int bit, AnimationStep step) {
        float ux = step.windX[p];
        float uz = step.windZ[p];
        Trails tr = trails;
        boolean pushed = step.pushX != null && (step.pushX[p] != 0 || step.pushZ[p] != 0);
        float l0x = tr.nowX[p];
        float l0z = tr.nowZ[p];
        tr.at(p, step.time);
        if (!live[p]) {
            settle(p, ux, uz);
            tr.settle(p, runs, pressX[p], pressZ[p]);
            l0x = tr.nowX[p];
            l0z = tr.nowZ[p];
        }
        if (pushed) {
            tr.push(p, step.time, finiteWind(step.pushX[p]), finiteWind(step.pushZ[p]), runs);
        }
        return springRuns(p, bit, ux, uz, l0x, l0z, tr.nowX[p], tr.nowZ[p]);
    }
}
