package org.jecosys.sim;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.Progress;
import org.jecosys.math.Require;
import org.jecosys.plant.ComponentFactories;
import org.jecosys.plant.PlantModel;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.terrain.CompetitiveDistributor;
import org.jecosys.terrain.PlantLayout;
import org.jecosys.terrain.ImageSource;
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

    /** World plant p is plant order[p] of the layout. */
    private final int[] order;
    /** {@link #bendGeometry()}, once built. */
    private volatile org.jecosys.anim.BendGeometry bendGeometry;
    private long terrainNanos;
    private long distributionNanos;

    private World(Terrain terrain, PlantModel plants, PlantLayout layout) {
        this.terrain = terrain;
        this.plants = plants;
        this.layout = layout;
        int n = layout.count();
        order = SpatialOrder.of(layout, terrain);
        x = new float[n];
        y = new float[n];
        z = new float[n];
        restAzimuth = new float[n];
        species = new int[n];
        for (int p = 0; p < n; p++) {
            int l = order[p];
            x[p] = layout.x(l);
            y[p] = layout.y(l);
            z[p] = layout.z(l);
            restAzimuth[p] = layout.azimuth(l);
            species[p] = layout.species(l);
        }
        variant = new int[n];
        firstComponent = new int[n + 1];
        long total = 0;
        for (int p = 0; p < n; p++) {
            SpeciesModel sm = plants.species().get(species[p]);
            variant[p] = sm.variantFor(layout.variantSeed(order[p]));
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
     * competitive distributor (paper §4.3). Deterministic for the def's seed whatever {@code workers}.
     *
     * @param def      what to build
     * @param baseDir  folder that relative image paths in the def resolve against; images must lie
     *                 in its tree ({@link ImageSource#folder})
     * @param workers  worker threads for generation, &gt;= 1
     * @param progress receives progress of the long steps
     * @return the world
     * @throws IOException when a heightmap or resource image cannot be read
     */
    public static World build(SimulationDef def, Path baseDir, int workers, Progress progress) throws IOException {
        return build(def, baseDir, workers, progress, new CompetitiveDistributor());
    }

    /**
     * {@link #build(SimulationDef, Path, int, Progress)} with another {@link TerrainDistributor}.
     *
     * @param def         what to build
     * @param baseDir     folder that relative image paths in the def resolve against
     * @param workers     worker threads for generation, &gt;= 1
     * @param progress    receives progress of the long steps
     * @param distributor places the plants ({@code new CompetitiveDistributor()} for the paper's)
     * @return the world
     * @throws IOException when a heightmap or resource image cannot be read
     */
    public static World build(SimulationDef def, Path baseDir, int workers, Progress progress,
                              TerrainDistributor distributor) throws IOException {
        return build(def, baseDir, workers, progress, distributor, ComponentFactories.NONE);
    }

    /**
     * {@link #build(SimulationDef, Path, int, Progress)} with another {@link TerrainDistributor} and
     * user plant components: the component types {@code components} names are supplied by their
     * {@link org.jecosys.plant.ComponentFactory} instead of the built-in model (extension points,
     * see docs/ARCHITECTURE.md, "Extension points"; paper §4.1, §4.3, §5.1). The way to give a
     * species built in code a component of the
     * game's own; then {@code Simulation.of(world, def, workers)}. Build time; allocates; calls the
     * distributor and the factories on this thread.
     *
     * @param def         what to build
     * @param baseDir     folder that relative image paths in the def resolve against
     * @param workers     worker threads for generation, &gt;= 1
     * @param progress    receives progress of the long steps
     * @param distributor places the plants ({@code new CompetitiveDistributor()} for the paper's)
     * @param components  user components ({@link ComponentFactories#NONE} for none)
     * @return the world
     * @throws IOException              when a heightmap or resource image cannot be read
     * @throws IllegalArgumentException on a null argument, fewer than 1 worker, or a factory that
     *                                  names an unknown species or component or returns a component
     *                                  that does not match its species
     */
    public static World build(SimulationDef def, Path baseDir, int workers, Progress progress,
                              TerrainDistributor distributor, ComponentFactories components) throws IOException {
        Require.nonNull("baseDir", baseDir);
        return build(def, ImageSource.folder(baseDir), workers, progress, distributor, components);
    }

    /**
     * {@link #build(SimulationDef, Path, int, Progress)} with the images the def names read from
     * {@code images} (for example the bytes a loaded scene was checked with,
     * {@code org.jecosys.scene.Scene#images()}, or a game's assets).
     *
     * @param def      what to build
     * @param images   where the heightmap, resource and texture images the def names come from
     * @param workers  worker threads for generation, &gt;= 1
     * @param progress receives progress of the long steps
     * @return the world
     * @throws IOException when a heightmap or resource image cannot be read or decoded
     */
    public static World build(SimulationDef def, ImageSource images, int workers, Progress progress) throws IOException {
        return build(def, images, workers, progress, new CompetitiveDistributor(), ComponentFactories.NONE);
    }

    /**
     * The full form of the builds above: images from {@code images}, plants placed by
     * {@code distributor}, user components from {@code components}. Build time; allocates.
     *
     * @param def         what to build
     * @param images      where the heightmap, resource and texture images the def names come from
     * @param workers     worker threads for generation, &gt;= 1
     * @param progress    receives progress of the long steps
     * @param distributor places the plants ({@code new CompetitiveDistributor()} for the paper's)
     * @param components  user components ({@link ComponentFactories#NONE} for none)
     * @return the world
     * @throws IOException              when a heightmap or resource image cannot be read or decoded
     * @throws IllegalArgumentException on a null argument, fewer than 1 worker, no species, or a
     *                                  factory that names an unknown species or component or returns a
     *                                  component that does not match its species
     */
    public static World build(SimulationDef def, ImageSource images, int workers, Progress progress,
                              TerrainDistributor distributor, ComponentFactories components) throws IOException {
        Require.nonNull("def", def);
        Require.nonNull("images", images);
        Require.nonNull("progress", progress);
        Require.nonNull("distributor", distributor);
        Require.nonNull("components", components);
        if (workers < 1) {
            throw new IllegalArgumentException("workers must be >= 1, got " + workers);
        }
        long t0 = System.nanoTime();
        Terrain terrain = Terrain.build(def.terrain(), images, workers, progress);
        long t1 = System.nanoTime();
        PlantModel plants = PlantModel.build(def.species(), def.seed(), org.jecosys.plant.GravityBend.EARTH_GRAVITY,
                progress, components).withTextures(org.jecosys.plant.PlantTextures.load(def.species(), images::read));
        List<String> ids = new ArrayList<>();
        for (SpeciesDef s : def.species()) {
            ids.add(s.id());
        }
        long t2 = System.nanoTime();
        PlantLayout layout = distributor.distribute(terrain, ids, def.distributions(), def.placements(), def.seed(),
                workers, progress);
        long t3 = System.nanoTime();
        World w = new World(terrain, plants, layout);
        w.terrainNanos = t1 - t0;
        w.distributionNanos = t3 - t2;
        return w;
    }

    /**
     * The world of one tile of an open world ({@link OpenWorld}): the tile's plants, placed already
     * ({@code TilePlacer}), over {@code ground}, a heightfield sampled over the tile's square (centred
     * on it). The plants keep their world coordinates; the layout holds no resource maps (uniform ones
     * of level 1) and no distribution counts. Build time; allocates; any thread.
     *
     * @param plants the pre-computed species models, shared by every tile
     * @param tile   the tile's plants
     * @param ground the ground under the tile
     * @return the tile's world
     */
    static World tile(PlantModel plants, org.jecosys.world.TilePlants tile, org.jecosys.terrain.Heightfield ground) {
        PlantLayout.Builder b = new PlantLayout.Builder();
        int n = tile.count();
        for (int k = 0; k < n; k++) {
            b.add(tile.x()[k], tile.y()[k], tile.z()[k], tile.azimuth()[k], 0f, 1, 1, tile.species()[k], -1,
                    tile.variantSeed()[k]);
        }
        org.jecosys.terrain.ResourceMap full = org.jecosys.terrain.ResourceMap.uniform(ground.sizeX(), ground.sizeZ(), 2, 1);
        PlantLayout layout = b.build(new int[0], new int[0], List.of(), full, full);
        return new World(new Terrain(ground, full, full), plants, layout);
    }

    /**
     * One line on what building took (paper §4.1: pose tables are pre-computed at load), e.g.
     * "terrain 12 ms, pose tables of 3 species 2.5 ms, distribution of 80 plants 9 ms".
     *
     * @return the summary (allocates)
     */
    public String buildSummary() {
        return String.format(java.util.Locale.ROOT, "terrain %.0f ms, pose tables of %d species %.1f ms, "
                        + "distribution of %d plants %.0f ms", terrainNanos / 1e6, plants.species().size(),
                plants.buildMillis(), layout.count(), distributionNanos / 1e6);
    }

    /** {@return the terrain and its resource maps (before any plant consumed)} */
    public Terrain terrain() {
        return terrain;
    }

    /** {@return the pre-computed species models, in the def's species order} */
    public PlantModel plants() {
        return plants;
    }

    /**
     * Where the plants stand, in placement order, with the distribution's warnings and counts; world
     * plant p is layout plant {@link #layoutIndex(int) layoutIndex(p)}.
     *
     * @return the layout
     */
    public PlantLayout layout() {
        return layout;
    }

    /**
     * {@return the index in {@link #layout()} of world plant p (world plants are in spatial order)}
     *
     * @param p world plant index, in [0, plantCount())
     */
    public int layoutIndex(int p) {
        return order[p];
    }

    /** {@return the number of plants} */
    public int plantCount() {
        return x.length;
    }

    /** {@return the number of components of all plants} */
    public int componentCount() {
        return componentPlant.length;
    }

    /**
     * {@return the bend geometry of every component (immutable; built on the first call, then the same
     * object)}: what maps a component's deviation to its pose coordinate and azimuth, for the frames of
     * a simulation of this world and for renderers. Any thread; allocates on the first call only.
     */
    public org.jecosys.anim.BendGeometry bendGeometry() {
        org.jecosys.anim.BendGeometry g = bendGeometry;
        return g != null ? g : bendGeometry(null, null, null);
    }

    /**
     * {@link #bendGeometry()}, built on the first call from a simulation's kinds and its components'
     * kinds (null: from the world's species). Any thread.
     */
    synchronized org.jecosys.anim.BendGeometry bendGeometry(org.jecosys.anim.SpringKinds kinds, int[] first,
                                                            int[] kind) {
        if (bendGeometry == null) {
            bendGeometry = kinds != null ? AnimationStates.geometry(this, kinds, first, kind)
                    : AnimationStates.geometry(this);
        }
        return bendGeometry;
    }

    /**
     * {@return the plant's X, metres}
     *
     * @param p world plant index, in [0, plantCount())
     */
    public float plantX(int p) {
        return x[p];
    }

    /**
     * {@return the plant's base height (terrain height at its position), metres}
     *
     * @param p world plant index, in [0, plantCount())
     */
    public float plantY(int p) {
        return y[p];
    }

    /**
     * {@return the plant's Z, metres}
     *
     * @param p world plant index, in [0, plantCount())
     */
    public float plantZ(int p) {
        return z[p];
    }

    /**
     * {@return the rest azimuth of the plant, radians}
     *
     * @param p world plant index, in [0, plantCount())
     */
    public float plantRestAzimuth(int p) {
        return restAzimuth[p];
    }

    /**
     * {@return the index of the plant's species in the def's species list}
     *
     * @param p world plant index, in [0, plantCount())
     */
    public int plantSpecies(int p) {
        return species[p];
    }

    /**
     * {@return the plant of species {@code s} with the most plants of that species within
     * {@code radius} metres of it (horizontally), the middle of the species' densest patch; ties go
     * to the lowest index; -1 when the species has no plant}. For tools that place a camera (the
     * gallery, look tests). Each plant's neighbours are sought in the 3 x 3 cells around it of a grid
     * of cells a little wider than {@code radius} (the plants of the meadow's grass, counted pair by
     * pair, took the gallery 15 s), so it takes time about linear in the species' plants for a radius
     * much smaller than the terrain; allocates that grid; any thread.
     *
     * @param s      index of the species in the def's species list
     * @param radius metres, &gt; 0
     */
    public int densestPlant(int s, double radius) {
        Require.positive("radius", radius);
        int count = 0;
        for (int p = 0; p < species.length; p++) {
            if (species[p] == s) {
                count++;
            }
        }
        if (count == 0) {
            return -1;
        }
        int[] members = new int[count];
        double minX = Double.POSITIVE_INFINITY;
        double minZ = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double maxZ = Double.NEGATIVE_INFINITY;
        for (int p = 0, i = 0; p < species.length; p++) {
            if (species[p] == s) {
                members[i++] = p;
                minX = Math.min(minX, x[p]);
                maxX = Math.max(maxX, x[p]);
                minZ = Math.min(minZ, z[p]);
                maxZ = Math.max(maxZ, z[p]);
            }
        }
        // cells wider than the radius by a margin far above rounding: a plant within the radius lies in
        // one of the 3 x 3 cells around; at most 2^22 cells (wider cells are as correct, only slower)
        double cell = Math.max(radius * 1.001, Math.sqrt((maxX - minX) * (maxZ - minZ) / (1 << 22)));
        int columns = (int) ((maxX - minX) / cell) + 1;
        int rows = (int) ((maxZ - minZ) / cell) + 1;
        int[] cellOf = new int[count];
        int[] start = new int[columns * rows + 1];
        for (int i = 0; i < count; i++) {
            int p = members[i];
            int cx = Math.min(columns - 1, (int) ((x[p] - minX) / cell));
            int cz = Math.min(rows - 1, (int) ((z[p] - minZ) / cell));
            cellOf[i] = cz * columns + cx;
            start[cellOf[i] + 1]++;
        }
        for (int c = 0; c < columns * rows; c++) {
            start[c + 1] += start[c];
        }
        int[] sorted = new int[count];
        int[] fill = java.util.Arrays.copyOf(start, columns * rows);
        for (int i = 0; i < count; i++) {
            sorted[fill[cellOf[i]]++] = members[i];
        }
        int best = -1;
        int most = -1;
        for (int i = 0; i < count; i++) {
            int p = members[i];
            int cx = cellOf[i] % columns;
            int cz = cellOf[i] / columns;
            int n = 0;
            for (int rz = Math.max(0, cz - 1); rz <= Math.min(rows - 1, cz + 1); rz++) {
                for (int rx = Math.max(0, cx - 1); rx <= Math.min(columns - 1, cx + 1); rx++) {
                    int c = rz * columns + rx;
                    for (int k = start[c]; k < start[c + 1]; k++) {
                        int q = sorted[k];
                        if (Math.hypot(plantX(p) - plantX(q), plantZ(p) - plantZ(q)) < radius) {
                            n++;
                        }
                    }
                }
            }
            if (n > most) {
                most = n;
                best = p;
            }
        }
        return best;
    }

    /**
     * {@return the plant's shape variant in its species model}
     *
     * @param p world plant index, in [0, plantCount())
     */
    public int plantVariant(int p) {
        return variant[p];
    }

    /**
     * {@return the index of the plant's first component}
     *
     * @param p world plant index, in [0, plantCount()]; {@code plantCount()} gives componentCount()
     */
    public int firstComponent(int p) {
        return firstComponent[p];
    }

    /**
     * {@return the number of components (slots) of the plant}
     *
     * @param p world plant index, in [0, plantCount())
     */
    public int componentsOf(int p) {
        return firstComponent[p + 1] - firstComponent[p];
    }

    /**
     * {@return the world plant a component belongs to}
     *
     * @param c component index, in [0, componentCount())
     */
    public int componentPlant(int c) {
        return componentPlant[c];
    }

    /**
     * {@return the component's slot in its plant's species model}
     *
     * @param c component index, in [0, componentCount())
     */
    public int componentSlot(int c) {
        return componentSlot[c];
    }

    /**
     * {@return the component at whose tip this one sits, as a world component index, or -1 for the ground}
     *
     * @param c component index, in [0, componentCount())
     */
    public int componentParent(int c) {
        return componentParent[c];
    }
}
