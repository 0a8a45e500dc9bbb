package org.jecosys.anim;

/**
 * The step of a range of plants for {@link AnimationState#animate} (see "Update order" and "Threads"
 * there): each plant's level of detail from the step's views ({@link PlantLevels}; one level per
 * species for the whole range when the step's box round it lies in one band of each,
 * {@link PlantLevels#uniform}), then by the step's mode: RANDOM gives each drawn component of a
 * visible plant a random deviation of its own ({@link ScatteredState}), CONSTRAINT advances the spring
 * runs of the visible plants ({@link PlantSprings#update}), STATIC moves nothing. A plant that is not
 * visible stops following the wind. A caller touches only the plants of its range and their
 * components, so disjoint ranges may run at once. Built once with the state (allocates); a step
 * allocates nothing but, once, the step's table of one level per species.
 */
final class RangeUpdate {
    private final SpringKinds kinds;
    private final PlantLevels levels;
    private final SpringRuns runs;
    private final ScatteredState scattered;
    private final PlantSprings springs;
    /** Per component its kind (shared with the state, read only). */
    private final short[] kind;
    /** Per plant its first component, plus the total at the end (shared with the state, read only). */
    private final int[] firstComponent;
    /** Per plant, incremented whenever its deviations may have changed (shared with the state). */
    private final long[] plantVersion;

    RangeUpdate(SpringKinds kinds, PlantLevels levels, SpringRuns runs, ScatteredState scattered,
                PlantSprings springs, short[] kind, int[] firstComponent, long[] plantVersion) {
        this.kinds = kinds;
        this.levels = levels;
        this.runs = runs;
        this.scattered = scattered;
        this.springs = springs;
        this.kind = kind;
        this.firstComponent = firstComponent;
        this.plantVersion = plantVersion;
    }

    /**
     * Advances plants {@code first .. end-1} by one step ({@link AnimationState#animate}, which
     * documents the modes). No allocation.
     *
     * @return components updated
     */
    int animate(int first, int end, AnimationStep step) {
        final AnimationMode mode = step.mode;
        final boolean[] visible = step.visible;
        final double eyeX = step.eyeX;
        final double eyeY = step.eyeY;
        final double eyeZ = step.eyeZ;
        final int views = step.views;
        // one view (or only the eye): its level-of-detail metric once, not per plant
        final double scale2 = views == 0 ? 1 : step.viewScale2[0];
        final double fixed2 = views == 0 ? -1 : step.viewFixed2[0];
        // a range whose plants all take one level per species (step.bounds): no distance per plant
        byte[] table = null;
        if (views <= 1 && step.bounds != null) {
            if (step.speciesLevel == null || step.speciesLevel.length != levels.species()) {
                step.speciesLevel = new byte[levels.species()];
            }
            if (levels.uniform(step.bounds, step.boundsAt, eyeX, eyeY, eyeZ, scale2, fixed2, step.speciesLevel)) {
                table = step.speciesLevel;
            }
        }
        int updated = 0;
        for (int p = first; p < end; p++) {
            int l = table != null ? levels.assign(p, table)
                    : views <= 1 ? levels.update(p, eyeX, eyeY, eyeZ, scale2, fixed2) : levels.update(p, step);
            if (!visible[p]) {
                springs.live[p] = false; // its state stops following the wind: it starts afresh when seen again
                continue;
            }
            if (mode != AnimationMode.RANDOM) {
                continue; // STATIC: nothing moves; CONSTRAINT: below
            }
            plantVersion[p]++;
            updated += scattered.randomise(p, firstComponent[p], firstComponent[p + 1], 1 << l, runs, kind,
                    kinds.lodMask, kinds.length, step.rng);
            springs.live[p] = false;
        }
        if (mode == AnimationMode.CONSTRAINT) {
            updated = springs.update(first, end, levels, step);
        }
        return updated;
    }
}
