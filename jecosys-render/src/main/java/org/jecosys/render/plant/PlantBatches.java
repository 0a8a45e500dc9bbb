package org.jecosys.render.plant;

import java.nio.IntBuffer;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.plant.Primitive;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;

/**
 * The GL-free half of plant rendering: per frame, which plants are drawn, at which level of detail,
 * in which instanced draw (one <em>list</em> per species and level, paper §4.1 and Table 3), and how
 * many primitives that submits. It follows the frame's one visibility and level decision
 * ({@link Frame#drawLevel}, {@link Frame#drawKeep}, made by the simulation's workers with the same
 * bands the animation used, see {@link org.jecosys.sim.DrawDecision}) without deciding anything
 * itself: a plant in a transition band is put in both lists, level L and L + 1, each with its share of
 * the screen-door dither thresholds ({@code plant.frag}), so the switch is gradual and never pops.
 * Within a list the plants drawn whole (outside any band, window {@link #WHOLE}) come first and the
 * plants in a band after them, each group in plant order: the renderer draws the first group with
 * programs that have no dither test, which keeps early depth testing on in the rasteriser (a shader
 * that may discard loses it on llvmpipe), and only those in a band with the dither test
 * ({@link #whole}). With {@link #setCoreless}, the whole plants that have no core where they stand
 * open the whole group ({@link #coreless}), the others following, each in plant order. Counters:
 * triangles and lines submitted = sum over lists of instances × that level's primitive count.
 *
 * <p>Render thread (or any single thread); {@link #update} and {@link #writeInstances} allocate
 * nothing. Lists are stored in preallocated arrays sized for every plant at every level.
 */
public final class PlantBatches {
    private final World world;
    private final int species;
    private final int[] listBase;      // first list of species s (lists = species x levels)
    private final int[] levels;
    private final int[] slots;
    private final int[] listSpecies;   // per list: its species
    private final int[] primitives;    // per list
    private final boolean[] lines;     // per list
    private final int[] listStart;     // per list: offset into plants[]
    private final int[] listCount;
    private final int[] plants;
    private final int[] keeps;          // per list entry: the packed dither window of its level
    private final int[] whole;          // per list: plants drawn whole, listed first
    private final int[] banded;         // per list: plants in a band, filled from the list's end
    private final int[] instanceOffset; // per list: first instance record in the packed stream
    private final int[] componentOffset; // per list: first component record
    private long triangles;
    private long lineCount;
    private int instances;
    private int components;
    private final ComponentRuns runs;
    /** The dither window of a plant drawn whole at its level: keep every fragment, [0, 1). */
    public static final int WHOLE = 0xFF;
    /** Gaps between listed plants' components up to this many are uploaded rather than split. */
    public static final int GAP = 64;
    /** Whether a plant in a band is drawn whole at one level instead of dithered (see {@link #setWholePlants}). */
    private boolean wholePlants;
    /** Where whole plants with no core are listed apart ({@link #setCoreless}); null: nowhere. */
    private CoreReach coreReach;
    private float eyeX;
    private float eyeZ;
    private final int[] coreless;       // per list: whole plants without a core, listed first
    private int[] corePlants;           // per list entry: whole plants with a core, while listing
    private int[] coreKeeps;

    /**
     * Batches for a world. Build time; allocates the lists for every plant at every level.
     *
     * @param world the plants
     */
    public PlantBatches(World world) {
        this.world = world;
        List<SpeciesModel> models = world.plants().species();
        species = models.size();
        listBase = new int[species + 1];
        levels = new int[species];
        slots = new int[species];
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
            lists += m.levels();
        }
        listBase[species] = lists;
        primitives = new int[lists];
        listSpecies = new int[lists];
        lines = new boolean[lists];
        listStart = new int[lists + 1];
        listCount = new int[lists];
        whole = new int[lists];
        coreless = new int[lists];
        banded = new int[lists];
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
        runs = new ComponentRuns(world.plantCount());
    }

    /**
     * Builds the lists from {@code frame}'s decision: every plant it draws, at its level, and at the
     * next level too when it is in a transition band. No allocation.
     *
     * @param frame a frame of this world, decided ({@link Frame#drawLevel})
     * @throws IllegalArgumentException when the frame's plant count is not the world's
     */
    public void update(Frame frame) {
        begin(frame);
        for (int p = 0, n = world.plantCount(); p < n; p++) {
            int l = frame.drawLevel(p);
            if (l >= 0) {
                list(p, l, frame.drawKeep(p));
            }
        }
        finish();
    }

    /**
     * Builds the lists from a decision made for another camera than the frame's own
     * ({@link org.jecosys.sim.ViewDecision}): per plant its level (-1: not drawn) and packed dither
     * windows. No allocation.
     *
     * @param frame  a frame of this world (its states are drawn)
     * @param levels per plant, the level to draw it at, or -1
     * @param keeps  per plant, the packed dither windows (as {@link Frame#drawKeep})
     * @throws IllegalArgumentException when the frame's plant count is not the world's
     */
    public void update(Frame frame, byte[] levels, int[] keeps) {
        begin(frame);
        for (int p = 0, n = world.plantCount(); p < n; p++) {
            int l = levels[p];
            if (l >= 0) {
                list(p, l, keeps[p]);
            }
        }
        finish();
    }

    private void begin(Frame frame) {
        if (frame.plantCount() != world.plantCount()) {
            throw new IllegalArgumentException("frame has " + frame.plantCount() + " plants, the world "
                    + world.plantCount());
        }
        int lists = listBase[species];
        for (int li = 0; li < lists; li++) {
            whole[li] = 0;
            coreless[li] = 0;
            banded[li] = 0;
        }
        runs.clear();
    }

    /** Lists plant p at level l (and at l + 1 in a band), and its components in the upload ranges. */
    private void list(int p, int l, int keep) {
        int c0 = world.firstComponent(p);
        int c1 = c0 + world.componentsOf(p);
        runs.add(c0, c1);
        int s = world.plantSpecies(p);
        int next = keep >>> 16 != 0 && l + 1 < levels[s] ? keep >>> 16 : 0;
        if (wholePlants && (keep & 0xFFFF) != WHOLE) {
            // the plant's own threshold picks the one window (of the two complementary ones) it falls in
            float t = DitherWindows.threshold(p);
            if (DitherWindows.inWindow(keep & 0xFFFF, t)) {
                add(listBase[s] + l, p, WHOLE);
            } else if (next != 0 && DitherWindows.inWindow(next, t)) {
                add(listBase[s] + l + 1, p, WHOLE);
            }
            return;
        }
        add(listBase[s] + l, p, keep & 0xFFFF);
        if (next != 0) {
            add(listBase[s] + l + 1, p, next);
        }
    }

    /**
     * Chooses how plants in a level-switch or thinning band are drawn: dithered per pixel over both
     * levels (false, the default: the screen-door thresholds of {@code plant.frag}, which multisampling
     * turns into partial coverage), or each whole at one of them (true), the level whose window holds
     * the plant's own fixed threshold, so that a band shows no pixel pattern on a target without
     * samples: the share of plants at each level is the window's share, a plant keeps its level while
     * its window holds its threshold, and a thinned-out plant leaves whole. Render thread; no allocation.
     *
     * @param whole true for whole plants
     */
    public void setWholePlants(boolean whole) {
        wholePlants = whole;
    }

    private void finish() {
        int lists = listBase[species];
        for (int li = 0; li < lists; li++) {
            gather(li);
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
        if (keep == WHOLE && coreReach != null) {
            float dx = world.plantX(plant) - eyeX;
            float dz = world.plantZ(plant) - eyeZ;
            boolean none = dx * dx + dz * dz >= coreReach.beyondSq(list);
            int at = listStart[list] + (none ? coreless[list]++ : whole[list]++);
            (none ? plants : corePlants)[at] = plant;
            (none ? keeps : coreKeeps)[at] = keep;
            return;
        }
        int at = keep == WHOLE ? listStart[list] + whole[list]++ : listStart[list + 1] - 1 - banded[list]++;
        plants[at] = plant;
        keeps[at] = keep;
    }

    /**
     * Lists the whole plants (outside any band) that have no core where they stand first in their lists,
     * as {@code reach} tells for the eye at ({@code x}, {@code z}), from the next {@link #update} on
     * (null: no such split): the core's pass of a multisampled target leaves them out ({@link #coreless}).
     * Render thread; allocates a list-sized array at the first call.
     */
    void setCoreless(CoreReach reach, float x, float z) {
        if (reach != null && corePlants == null) {
            corePlants = new int[plants.length];
            coreKeeps = new int[plants.length];
        }
        coreReach = reach;
        eyeX = x;
        eyeZ = z;
    }

    /**
     * {@return how many of a list's plants, its first ones, are drawn whole and have no core where they
     * stand (0 unless {@link #setCoreless} is set): a part of {@link #whole}}
     *
     * @param list list index, in [0, listCount())
     */
    public int coreless(int list) {
        return coreless[list];
    }

    /** Moves a list's banded plants (at the end of its room, last first) to follow its whole ones, in order. */
    private void gather(int list) {
        if (coreReach != null) {
            // the whole plants with a core follow those without
            int st = listStart[list];
            System.arraycopy(corePlants, st, plants, st + coreless[list], whole[list]);
            System.arraycopy(coreKeeps, st, keeps, st + coreless[list], whole[list]);
            whole[list] += coreless[list];
        }
        int n = banded[list];
        int end = listStart[list + 1];
        for (int i = end - n, j = end - 1; i < j; i++, j--) {
            int t = plants[i];
            plants[i] = plants[j];
            plants[j] = t;
            t = keeps[i];
            keeps[i] = keeps[j];
            keeps[j] = t;
        }
        int to = listStart[list] + whole[list];
        System.arraycopy(plants, end - n, plants, to, n);
        System.arraycopy(keeps, end - n, keeps, to, n);
        listCount[list] = whole[list] + n;
    }


    /**
     * Writes the instance record of every listed plant for the last {@link #update}, list after list
     * in {@link #instanceOffset} order: two ints, the plant's first component and its level's dither
     * window ({@link Frame#drawKeep}). Writes from {@code dest}'s position 0 and flips it. No allocation.
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

    /**
     * {@return how many of a list's plants, its first ones, are drawn whole (dither window
     * {@link #WHOLE}); the rest, up to {@link #count}, are in a transition band}
     *
     * @param list list index, in [0, listCount())
     */
    public int whole(int list) {
        return whole[list];
    }

    /**
     * {@return the packed dither window of the {@code i}-th plant of a list, as {@link #writeInstances}
     * writes it}
     *
     * @param list list index, in [0, listCount())
     * @param i    position in the list, in [0, count(list))
     */
    public int keepOf(int list, int i) {
        return keeps[listStart[list] + i];
    }

    /** {@return the component ranges that hold the plants listed by the last {@link #update}} */
    public ComponentRuns runs() {
        return runs;
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
