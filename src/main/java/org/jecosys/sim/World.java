package org.jecosys.sim;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.Progress;
import org.jecosys.plant.PlantModel;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.terrain.CompetitiveDistributor;
import org.jecosys.terrain.PlantLayout;
import org.jecosys.terrain.Terrain;
import org.jecosys.terrain.TerrainDistributor;

/**
 * The static part of a simulation: terrain, pre-computed plant models (paper §4.1), where each
 * plant stands (paper §4.3) and the flat index of every plant component. Component {@code c} of
 * the whole world belongs to plant {@link #componentPlant(int)} and is slot
 * {@link #componentSlot(int)} of that plant's {@link SpeciesModel}; the components of plant p are
 * {@code firstComponent(p) .. firstComponent(p) + componentsOf(p) - 1}, in slot order.
 *
 * <p>Immutable after {@link #build}; every accessor may be called from any thread and none
 * allocates.
 */
public final class World {
    private final Terrain terrain;
    private final PlantModel plants;
    private final PlantLayout layout;
    private final float[] x;
    private final float[] y;
    private final float[] z;
    private final float[] restAzimuth;
    private final int[] species;
    private final int[] variant;
    private final int[] firstComponent;
    private final int[] componentPlant;
    private final short[] componentSlot;
    private final int[] componentParent;

    private long terrainNanos;
    private long distributionNanos;

    private World(Terrain terrain, PlantModel plants, PlantLayout layout) {
        this.terrain = terrain;
        this.plants = plants;
        this.layout = layout;
        int n = layout.count();
        x = layout.copyX();
        y = layout.copyY();
        z = layout.copyZ();
        restAzimuth = layout.copyAzimuths();
        species = layout.copySpecies();
        variant = new int[n];
        firstComponent = new int[n + 1];
        long total = 0;
        for (int p = 0; p < n; p++) {
            SpeciesModel sm = plants.species().get(species[p]);
            variant[p] = sm.variantFor(layout.variantSeed(p));
            firstComponent[p] = (int) total;
            total += sm.slotCount();
            if (total > Integer.MAX_VALUE - 8) {
                throw new IllegalArgumentException("the scene has more than " + (Integer.MAX_VALUE - 8)
                        + " components");
            }
        }
        firstComponent[n] = (int) total;
        componentPlant = new int[(int) total];
        componentSlot = new short[(int) total];
        componentParent = new int[(int) total];
        for (int p = 0; p < n; p++) {
            SpeciesModel sm = plants.species().get(species[p]);
            for (int s = 0; s < sm.slotCount(); s++) {
                int c = firstComponent[p] + s;
                componentPlant[c] = p;
                componentSlot[c] = (short) s;
                int parent = sm.slotParent(s);
                componentParent[c] = parent < 0 ? -1 : firstComponent[p] + parent;
            }
        }
    }

    /**
     * Builds the terrain, pre-computes every species and distributes the plants with the
     * competitive distributor (paper §4.3). Deterministic for the def's seed whatever {@code threads}.
     *
     * @param def      what to build
     * @param baseDir  folder that relative image paths in the def resolve against
     * @param threads  worker threads for generation, &gt;= 1
     * @param progress receives progress of the long steps
     * @throws IOException when a heightmap or resource image cannot be read
     */
    public static World build(SimulationDef def, Path baseDir, int threads, Progress progress) throws IOException {
        return build(def, baseDir, threads, progress, new CompetitiveDistributor());
    }

    /** {@link #build(SimulationDef, Path, int, Progress)} with another {@link TerrainDistributor}. */
    public static World build(SimulationDef def, Path baseDir, int threads, Progress progress,
                              TerrainDistributor distributor) throws IOException {
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be >= 1, got " + threads);
        }
        long t0 = System.nanoTime();
        Terrain terrain = Terrain.build(def.terrain(), baseDir, threads, progress);
        long t1 = System.nanoTime();
        PlantModel plants = PlantModel.build(def.species(), def.seed(), org.jecosys.plant.GravityBend.EARTH_GRAVITY,
                progress);
        List<String> ids = new ArrayList<>();
        for (SpeciesDef s : def.species()) {
            ids.add(s.id());
        }
        long t2 = System.nanoTime();
        PlantLayout layout = distributor.distribute(terrain, ids, def.distributions(), def.placements(), def.seed(),
                threads, progress);
        long t3 = System.nanoTime();
        World w = new World(terrain, plants, layout);
        w.terrainNanos = t1 - t0;
        w.distributionNanos = t3 - t2;
        return w;
    }

    /**
     * One line on what building took (paper §4.1: pose tables are pre-computed at load), e.g.
     * "terrain 12 ms, pose tables of 3 species 2.5 ms, distribution of 80 plants 9 ms".
     */
    public String buildSummary() {
        return String.format(java.util.Locale.ROOT, "terrain %.0f ms, pose tables of %d species %.1f ms, "
                        + "distribution of %d plants %.0f ms", terrainNanos / 1e6, plants.species().size(),
                plants.buildMillis(), layout.count(), distributionNanos / 1e6);
    }

    /** The terrain and its resource maps (after nothing was consumed). */
    public Terrain terrain() {
        return terrain;
    }

    /** The pre-computed species models, in the def's species order. */
    public PlantModel plants() {
        return plants;
    }

    /** Where the plants stand, with the distribution's warnings and counts. */
    public PlantLayout layout() {
        return layout;
    }

    /** Number of plants. */
    public int plantCount() {
        return x.length;
    }

    /** Number of components of all plants. */
    public int componentCount() {
        return componentPlant.length;
    }

    /** Plant X, metres. */
    public float plantX(int p) {
        return x[p];
    }

    /** Plant base height (terrain height at its position), metres. */
    public float plantY(int p) {
        return y[p];
    }

    /** Plant Z, metres. */
    public float plantZ(int p) {
        return z[p];
    }

    /** Rest azimuth of the plant, radians. */
    public float plantRestAzimuth(int p) {
        return restAzimuth[p];
    }

    /** Index of the plant's species in the def's species list. */
    public int plantSpecies(int p) {
        return species[p];
    }

    /** The plant's shape variant in its species model. */
    public int plantVariant(int p) {
        return variant[p];
    }

    /** Index of the plant's first component. */
    public int firstComponent(int p) {
        return firstComponent[p];
    }

    /** Number of components (slots) of the plant. */
    public int componentsOf(int p) {
        return firstComponent[p + 1] - firstComponent[p];
    }

    /** The plant a component belongs to. */
    public int componentPlant(int c) {
        return componentPlant[c];
    }

    /** The component's slot in its plant's species model. */
    public int componentSlot(int c) {
        return componentSlot[c];
    }

    /** The component at whose tip this one sits, as a world component index, or -1 for the ground. */
    public int componentParent(int c) {
        return componentParent[c];
    }
}
