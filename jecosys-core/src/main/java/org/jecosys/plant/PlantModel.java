package org.jecosys.plant;

import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.Progress;
import org.jecosys.math.Require;
import org.jecosys.math.Rng;

/**
 * The pre-computation step of a scene's plants (paper §4.1): builds one {@link SpeciesModel} per
 * species and reports the total time (the scene loader prints it; the budget is under 200 ms for
 * all the shipped species together). Each species' variation seed is
 * {@code Rng.mix(seed + id.hashCode())}, so a species' shapes do not depend on the order of the
 * list. Immutable after {@link #build}; any thread.
 */
public final class PlantModel {
    private final List<SpeciesModel> species;
    private final long buildNanos;
    private final PlantTextures textures;

    private PlantModel(List<SpeciesModel> species, long buildNanos, PlantTextures textures) {
        this.species = species;
        this.buildNanos = buildNanos;
        this.textures = textures;
    }

    /**
     * These species with the images their components name (a renderer draws them on the components).
     * Build time; allocates the new model (the species are shared).
     *
     * @param textures the prepared images ({@link PlantTextures#load}), {@link PlantTextures#NONE} for none
     * @return a model with the same species and these textures
     */
    public PlantModel withTextures(PlantTextures textures) {
        return new PlantModel(species, buildNanos, Require.nonNull("textures", textures));
    }

    /** {@return the images drawn on components; {@link PlantTextures#NONE} when none is named or loaded} */
    public PlantTextures textures() {
        return textures;
    }

    /**
     * Builds every species. Build time; allocates; calls {@code progress} once per species on this
     * thread with step {@code "plants"}.
     *
     * @param defs     the species, at least one
     * @param seed     scene seed
     * @param gravity  m/s^2, in [0, 100]
     * @param progress progress listener ({@link Progress#NONE} for none)
     * @return the built species and the build time
     * @throws IllegalArgumentException when defs is empty or holds null, or gravity is out of range
     */
    public static PlantModel build(List<SpeciesDef> defs, long seed, double gravity, Progress progress) {
        return build(defs, seed, gravity, progress, ComponentFactories.NONE);
    }

    /**
     * Builds every species, with the user components of {@code components} in place of the built-in
     * ones they name ({@link SpeciesModel#withComponents}; an extension point, see
     * docs/ARCHITECTURE.md, "Extension points"; paper §5.1).
     * Build time; allocates; calls {@code progress} once per species on this thread with step
     * {@code "plants"}; calls the factories on this thread.
     *
     * @param defs       the species, at least one
     * @param seed       scene seed
     * @param gravity    m/s^2, in [0, 100]
     * @param progress   progress listener ({@link Progress#NONE} for none)
     * @param components user components ({@link ComponentFactories#NONE} for none)
     * @return the built species and the build time
     * @throws IllegalArgumentException when defs is empty or holds null, gravity is out of range, a
     *                                  factory names a species or component that does not exist, or a
     *                                  user component does not match its species
     */
    public static PlantModel build(List<SpeciesDef> defs, long seed, double gravity, Progress progress,
                                   ComponentFactories components) {
        Require.nonNull("defs", defs);
        Require.nonNull("progress", progress);
        Require.nonNull("components", components);
        if (defs.isEmpty()) {
            throw new IllegalArgumentException("defs must not be empty");
        }
        for (String id : components.speciesIds()) {
            boolean known = false;
            for (SpeciesDef d : defs) {
                known |= d != null && d.id().equals(id);
            }
            if (!known) {
                throw new IllegalArgumentException("component factories name species '" + id
                        + "', which is not among the species to build");
            }
        }
        long t0 = System.nanoTime();
        List<SpeciesModel> out = new ArrayList<>(defs.size());
        for (int i = 0; i < defs.size(); i++) {
            SpeciesDef d = Require.elementNonNull("defs", i, defs.get(i));
            out.add(SpeciesModel.build(d, speciesSeed(seed, d), gravity).withComponents(components));
            progress.report("plants", i + 1, defs.size());
        }
        return new PlantModel(List.copyOf(out), System.nanoTime() - t0, PlantTextures.NONE);
    }

    /**
     * The variation seed of {@code species} in a scene with seed {@code seed}. Pure.
     *
     * @param seed    the scene seed
     * @param species the species; only its id is read
     * @return {@code Rng.mix(seed + species.id().hashCode())}
     */
    public static long speciesSeed(long seed, SpeciesDef species) {
        return Rng.mix(seed + species.id().hashCode());
    }

    /** {@return the built species, in the order given (unmodifiable)} */
    public List<SpeciesModel> species() {
        return species;
    }

    /**
     * {@return how many component types, over all species, are drawn from glTF files ({@link MeshDef})}
     * Any thread; no allocation.
     */
    public int meshComponents() {
        int n = 0;
        for (SpeciesModel m : species) {
            for (int c = 0; c < m.componentCount(); c++) {
                n += m.component(c).def().mesh() != null ? 1 : 0;
            }
        }
        return n;
    }

    /** {@return the total wall time of {@link #build}, nanoseconds} */
    public long buildNanos() {
        return buildNanos;
    }

    /** {@return the total wall time of {@link #build}, milliseconds} */
    public double buildMillis() {
        return buildNanos / 1e6;
    }
}
