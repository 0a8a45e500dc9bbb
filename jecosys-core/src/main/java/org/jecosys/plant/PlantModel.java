package org.jecosys.plant;

import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.Progress;
import org.jecosys.math.Require;
import org.jecosys.math.Rng;

/**
 * The pre-computation step of a scene's plants (paper §4.1): builds one {@link SpeciesModel} per
 * species and reports the total time (the scene loader prints it; DESIGN.md budget: under 200 ms
 * for every shipped species). Each species' variation seed is
 * {@code Rng.mix(seed + id.hashCode())}, so a species' shapes do not depend on the order of the
 * list. Immutable after {@link #build}; any thread.
 */
public final class PlantModel {
    private final List<SpeciesModel> species;
    private final long buildNanos;

    private PlantModel(List<SpeciesModel> species, long buildNanos) {
        this.species = species;
        this.buildNanos = buildNanos;
    }

    /**
     * Builds every species. Build time; allocates; calls {@code progress} once per species on this
     * thread with step {@code "plants"}.
     *
     * @param defs     the species, at least one
     * @param seed     scene seed
     * @param gravity  m/s^2, in [0, 100]
     * @param progress progress listener ({@link Progress#NONE} for none)
     */
    public static PlantModel build(List<SpeciesDef> defs, long seed, double gravity, Progress progress) {
        Require.nonNull("defs", defs);
        Require.nonNull("progress", progress);
        if (defs.isEmpty()) {
            throw new IllegalArgumentException("defs must not be empty");
        }
        long t0 = System.nanoTime();
        List<SpeciesModel> out = new ArrayList<>(defs.size());
        for (int i = 0; i < defs.size(); i++) {
            SpeciesDef d = Require.nonNull("defs[" + i + "]", defs.get(i));
            out.add(SpeciesModel.build(d, speciesSeed(seed, d), gravity));
            progress.report("plants", i + 1, defs.size());
        }
        return new PlantModel(List.copyOf(out), System.nanoTime() - t0);
    }

    /** The variation seed of {@code species} in a scene with seed {@code seed}. Pure. */
    public static long speciesSeed(long seed, SpeciesDef species) {
        return Rng.mix(seed + species.id().hashCode());
    }

    /** The built species, in the order given. */
    public List<SpeciesModel> species() {
        return species;
    }

    /** Total wall time of {@link #build}, nanoseconds. */
    public long buildNanos() {
        return buildNanos;
    }

    /** Total wall time of {@link #build}, milliseconds. */
    public double buildMillis() {
        return buildNanos / 1e6;
    }
}
