package org.jecosys.render;

import java.nio.IntBuffer;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.Camera;
import org.jecosys.plant.LodChooser;
import org.jecosys.plant.LodDef;
import org.jecosys.plant.Primitive;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.World;
import org.joml.FrustumIntersection;
import org.joml.Matrix4f;

/**
 * The GL-free half of plant rendering: per frame, which plants are drawn, at which level of detail,
 * in which instanced draw (one <em>list</em> per species and level, paper §4.1 and Table 3), and how
 * many primitives that submits. Pure functions of the world, the camera and the LOD settings, tested
 * without a GL context.
 *
 * <ul>
 * <li><b>Culling</b>: a plant is drawn when its bounding sphere (centre at its base, radius
 * {@link #radius(int)} of its species: every pose and attachment fits) intersects the view
 * frustum.</li>
 * <li><b>Level of detail</b>: distance = |eye - plant base| (metres); level and fade from the
 * species' {@link LodChooser}. A plant inside a transition band (fade &gt; 0) is put in both
 * lists, level L and L + 1; the shader keeps complementary screen-door (dither) pixels of the two so
 * the switch is gradual and never pops ({@code plant.frag}).</li>
 * <li><b>Counters</b>: triangles and lines submitted = sum over lists of instances × that level's
 * primitive count.</li>
 * </ul>
 *
 * <p>Render thread (or any single thread); {@link #update} and {@link #writeInstances} allocate
 * nothing. Lists are stored in preallocated arrays sized for
 * every plant at every level.
 */
public final class PlantBatches {
    private final World world;
    private final int species;
    private final int[] listBase;      // first list of species s (lists = species x levels)
    private final int[] levels;
    private final int[] slots;
    private final float[] radius;
    private final double[][] edges;
    private final LodChooser[] choosers;
    private final int[] listSpecies;   // per list: its species
    private final int[] primitives;    // per list
    private final boolean[] lines;     // per list
    private final int[] listStart;     // per list: offset into plants[]
    private final int[] listCount;
    private final int[] plants;
    private final int[] keeps;          // per list entry: the packed dither window of its level
    private final int[] instanceOffset; // per list: first instance record in the packed stream
    private final int[] componentOffset; // per list: first component record
    private final FrustumIntersection frustum = new FrustumIntersection();
    private final Matrix4f viewProj = new Matrix4f();
    private double bandWidth;
    private long triangles;
    private long lineCount;
    private int instances;
    private int components;
    private int firstListed;
    private int endListed;

    /**
     * Batches for a world. Build time; allocates the lists for every plant at every level.
     *
     * @param world     the plants
     * @param bandWidth LOD transition band, metres, in [0, smallest gap between LOD edges]
     */
    public PlantBatches(World world, double bandWidth) {
        this.world = world;
        List<SpeciesModel> models = world.plants().species();
        species = models.size();
        listBase = new int[species + 1];
        levels = new int[species];
        slots = new int[species];
        radius = new float[species];
        edges = new double[species][];
        choosers = new LodChooser[species];
        int[] perSpecies = new int[species];
        for (int p = 0; p < world.plantCount(); p++) {
            perSpecies[world.plantSpecies(p)]++;
        }
        int lists = 0;
        for (int s = 0; s < species; s++) {
            SpeciesModel m = models.get(s);
            listBase[s] = lists;
            levels[s] = m.levels();
            slots[s] = m.slotCount();
            radius[s] = boundingRadius(m);
            lists += m.levels();
        }
        listBase[species] = lists;
        primitives = new int[lists];
        listSpecies = new int[lists];
        lines = new boolean[lists];
        listStart = new int[lists + 1];
        listCount = new int[lists];
        instanceOffset = new int[lists];
        componentOffset = new int[lists];
        int at = 0;
        for (int s = 0; s < species; s++) {
            SpeciesModel m = models.get(s);
            for (int l = 0; l < m.levels(); l++) {
                int li = listBase[s] + l;
                primitives[li] = m.primitiveCount(l);
                listSpecies[li] = s;
                lines[li] = m.mesh(l).primitive() == Primitive.LINES;
                listStart[li] = at;
                at += perSpecies[s];
            }
        }
        listStart[lists] = at;
        plants = new int[at];
        keeps = new int[at];
        this.bandWidth = bandWidth;
        for (int s = 0; s < species; s++) {
            List<LodDef> lods = models.get(s).def().lods();
            double[] e = new double[lods.size() - 1];
            for (int l = 0; l < e.length; l++) {
                e[l] = lods.get(l).maxDistance();
            }
            setLodDistances(s, e);
        }
    }

    /**
     * A conservative bounding radius of a species' plant about its base, metres: the largest base
     * offset plus the lengths of every component type (an upper bound of any attachment chain) plus
     * the widths. Pure; build time.
     */
    static float boundingRadius(SpeciesModel m) {
        double r = 0;
        double base = 0;
        for (int s = 0; s < m.slotCount(); s++) {
            base = Math.max(base, Math.hypot(m.slotBaseX(s), m.slotBaseZ(s)));
        }
        for (int c = 0; c < m.componentCount(); c++) {
            double longest = 0;
            for (int v = 0; v < m.component(c).variants(); v++) {
                longest = Math.max(longest, m.component(c).poseTable(v).length());
            }
            r += longest + Math.max(m.component(c).def().baseWidth(), m.component(c).def().tipWidth());
        }
        return (float) (r + base);
    }

    /**
     * Sets the LOD edges of a species (the {@code maxDistance} of each level but the last, ascending,
     * metres) — the viewer's "edit LOD distances". Allocates; not per frame.
     *
     * @param species      species index, in [0, speciesCount())
     * @param maxDistances {@code levels(species) - 1} ascending distances, metres, &gt; 0
     * @throws IllegalArgumentException when the count is wrong or the distances do not ascend
     */
    public void setLodDistances(int species, double[] maxDistances) {
        if (maxDistances.length != levels[species] - 1) {
            throw new IllegalArgumentException("species " + species + " has " + levels[species] + " levels, so "
                    + (levels[species] - 1) + " distances, got " + maxDistances.length);
        }
        List<LodDef> lods = new ArrayList<>();
        for (int l = 0; l < maxDistances.length; l++) {
            lods.add(new LodDef(maxDistances[l], Primitive.TRIANGLES));
        }
        lods.add(new LodDef(Double.POSITIVE_INFINITY, Primitive.LINES));
        double gap = Double.POSITIVE_INFINITY;
        double prev = 0;
        for (double e : maxDistances) {
            gap = Math.min(gap, e - prev);
            prev = e;
        }
        choosers[species] = new LodChooser(lods, Math.min(bandWidth, gap));
        edges[species] = maxDistances.clone();
    }

    /**
     * Sets the transition band width of every species. Allocates; not per frame.
     *
     * @param bandWidth metres, &gt;= 0; clamped to each species' smallest gap between LOD edges
     */
    public void setBandWidth(double bandWidth) {
        this.bandWidth = bandWidth;
        for (int s = 0; s < species; s++) {
            setLodDistances(s, edges[s]);
        }
    }

    /**
     * Recomputes the lists for a camera: culling, level choice, dithering membership and counters.
     * No allocation.
     *
     * @param camera the viewer: its frustum culls, its eye sets the distances
     */
    public void update(Camera camera) {
        camera.viewProjection(viewProj);
        frustum.set(viewProj, false);
        int lists = listBase[species];
        for (int li = 0; li < lists; li++) {
            listCount[li] = 0;
        }
        double ex = camera.x();
        double ey = camera.y();
        double ez = camera.z();
        firstListed = Integer.MAX_VALUE;
        endListed = 0;
        for (int p = 0, n = world.plantCount(); p < n; p++) {
            int s = world.plantSpecies(p);
            float x = world.plantX(p);
            float y = world.plantY(p);
            float z = world.plantZ(p);
            if (!frustum.testSphere(x, y, z, radius[s])) {
                continue;
            }
            double dx = x - ex;
            double dy = y - ey;
            double dz = z - ez;
            double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
            LodChooser ch = choosers[s];
            int l = ch.level(d);
            add(listBase[s] + l, p, keep(s, l, levels[s], d));
            if (ch.fade(d) > 0) {
                add(listBase[s] + l + 1, p, keep(s, l + 1, levels[s], d));
            }
            firstListed = Math.min(firstListed, world.firstComponent(p));
            endListed = Math.max(endListed, world.firstComponent(p) + world.componentsOf(p));
        }
        if (endListed == 0) {
            firstListed = 0;
        }
        triangles = 0;
        lineCount = 0;
        instances = 0;
        components = 0;
        for (int s = 0; s < species; s++) {
            for (int li = listBase[s]; li < listBase[s + 1]; li++) {
                instanceOffset[li] = instances;
                componentOffset[li] = components;
                int n = listCount[li];
                instances += n;
                components += n * slots[s];
                if (lines[li]) {
                    lineCount += (long) n * primitives[li];
                } else {
                    triangles += (long) n * primitives[li];
                }
            }
        }
    }

    private void add(int list, int plant, int keep) {
        int at = listStart[list] + listCount[list]++;
        plants[at] = plant;
        keeps[at] = keep;
    }

    /**
     * The packed dither window of level {@code l} for a plant of species s at distance d, metres:
     * level l keeps the bayer thresholds in {@code [handOver, received)} (both /255), where handOver
     * is the share already given to level l + 1 and received the share taken over from level l - 1;
     * packed as {@code 256 handOver + received}. Neighbouring levels' windows tile [0, 255]. No
     * allocation.
     */
    int keep(int s, int l, int levels, double d) {
        double band = choosers[s].bandWidth();
        double handOver = l < levels - 1 ? fade(d, edges[s][l], band) : 0;
        double received = l > 0 ? (d >= edges[s][l - 1] ? 1 : fade(d, edges[s][l - 1], band)) : 1;
        return 256 * (int) Math.round(handOver * 255) + (int) Math.round(received * 255);
    }

    /** Fade across the band ending at {@code edge}: 0 before it, 1 at and beyond the edge. */
    static double fade(double d, double edge, double band) {
        if (band <= 0) {
            return d >= edge ? 1 : 0;
        }
        return Math.max(0, Math.min(1, (d - (edge - band)) / band));
    }

    /**
     * Writes the instance record of every listed plant for the last {@link #update}, list after list
     * in {@link #instanceOffset} order: two ints, the plant's first component and its level's dither
     * window ({@link #keep}). Writes from {@code dest}'s position 0 and flips it. No allocation.
     *
     * @param dest at least {@code 2 * maxInstances()} ints
     * @return the number of records written
     */
    public int writeInstances(IntBuffer dest) {
        dest.clear();
        for (int li = 0, lists = listBase[species]; li < lists; li++) {
            for (int i = 0, n = listCount[li], st = listStart[li]; i < n; i++) {
                dest.put(world.firstComponent(plants[st + i])).put(keeps[st + i]);
            }
        }
        dest.flip();
        return dest.limit() / 2;
    }

    /** {@return the packed dither window of the {@code i}-th plant of a list, as {@link #writeInstances} writes it} */
    public int keepOf(int list, int i) {
        return keeps[listStart[list] + i];
    }

    /** {@return the lowest component index of any plant listed by the last {@link #update} (0 when none)} */
    public int firstListedComponent() {
        return firstListed;
    }

    /** {@return one past the highest component index of any plant listed by the last {@link #update} (0 when none)} */
    public int endListedComponent() {
        return endListed;
    }

    /** {@return the number of species} */
    public int speciesCount() {
        return species;
    }

    /**
     * {@return the number of levels of detail of species {@code s}}
     *
     * @param s species index, in [0, speciesCount())
     */
    public int levels(int s) {
        return levels[s];
    }

    /**
     * {@return the index of the list of (species, level)}
     *
     * @param s     species index, in [0, speciesCount())
     * @param level level of detail, in [0, levels(s))
     */
    public int list(int s, int level) {
        return listBase[s] + level;
    }

    /** {@return the number of lists (sum of every species' levels)} */
    public int listCount() {
        return listBase[species];
    }

    /**
     * {@return the number of plants in a list after the last {@link #update}}
     *
     * @param list list index, in [0, listCount())
     */
    public int count(int list) {
        return listCount[list];
    }

    /**
     * {@return the {@code i}-th plant of a list, a world plant index}
     *
     * @param list list index, in [0, listCount())
     * @param i    in [0, count(list))
     */
    public int plant(int list, int i) {
        return plants[listStart[list] + i];
    }

    /**
     * {@return the first instance record of the list in the {@link #writeInstances} stream}
     *
     * @param list list index, in [0, listCount())
     */
    public int instanceOffset(int list) {
        return instanceOffset[list];
    }

    /**
     * {@return the first component record of the list: the list's plants' components follow each
     * other, plant after plant, slot after slot, list after list}
     *
     * @param list list index, in [0, listCount())
     */
    public int componentOffset(int list) {
        return componentOffset[list];
    }

    /**
     * {@return whether the list draws lines (else triangles)}
     *
     * @param list list index, in [0, listCount())
     */
    public boolean lines(int list) {
        return lines[list];
    }

    /**
     * {@return the number of primitives of one plant of the list}
     *
     * @param list list index, in [0, listCount())
     */
    public int primitivesPerPlant(int list) {
        return primitives[list];
    }

    /**
     * {@return the bounding radius of species {@code s} about a plant's base, metres}
     *
     * @param s species index, in [0, speciesCount())
     */
    public float radius(int s) {
        return radius[s];
    }

    /**
     * {@return LOD edge {@code l} of species {@code s}: where level l ends, metres}
     *
     * @param s species index, in [0, speciesCount())
     * @param l edge index, in [0, levels(s) - 1)
     */
    public double edge(int s, int l) {
        return edges[s][l];
    }

    /**
     * {@return the level chooser of species {@code s}}
     *
     * @param s species index, in [0, speciesCount())
     */
    public LodChooser chooser(int s) {
        return choosers[s];
    }

    /**
     * {@return the transition band width of species {@code s}, metres}
     *
     * @param s species index, in [0, speciesCount())
     */
    public double bandWidth(int s) {
        return choosers[s].bandWidth();
    }

    /** {@return the number of triangles submitted by the last {@link #update}} */
    public long triangles() {
        return triangles;
    }

    /** {@return the number of lines submitted by the last {@link #update}} */
    public long lineCount() {
        return lineCount;
    }

    /** {@return the number of instances (plant draws, a plant in a band counting twice) of the last {@link #update}} */
    public int instances() {
        return instances;
    }

    /** {@return the number of component pairs of the last {@link #update}} */
    public int components() {
        return components;
    }

    /** {@return the upper bound of {@link #instances()}: every plant at every level} */
    public int maxInstances() {
        return plants.length;
    }

    /** {@return the upper bound of {@link #components()}} */
    public long maxComponents() {
        long n = 0;
        for (int s = 0; s < species; s++) {
            for (int li = listBase[s]; li < listBase[s + 1]; li++) {
                n += (long) (listStart[li + 1] - listStart[li]) * slots[s];
            }
        }
        return n;
    }

    /**
     * {@return the species a list draws}
     *
     * @param list list index, in [0, listCount())
     */
    public int speciesOf(int list) {
        return listSpecies[list];
    }

    /**
     * {@return the components per plant (slots) of a species}
     *
     * @param s species index
     */
    public int slots(int s) {
        return slots[s];
    }
}
