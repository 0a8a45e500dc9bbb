package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.Progress;
import org.jecosys.scene.SceneFiles;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The showcase meadow (scenes/meadow.xml) reads as a natural meadow (issue 25): every species is
 * clumped at small scale, pooled Clark–Evans ratio at most 1 in 4 m windows (real grassland is
 * clumped; footprints alone gave 1.05–1.33), and its plants differ in height, s.d. at least 20% of the
 * mean (height: the highest skeleton point at rest, see {@link MeadowPattern}); the world is the same
 * whatever the thread count. The world is built once for the class.
 */
class MeadowNatureTest {
    static final List<String> SPECIES = List.of("grassA", "grassS", "grassD", "flowerB", "flowerC");
    static final double WINDOW = 4;
    /** Largest pooled Clark–Evans ratio of the tussocks (issue 41). */
    static final double TUSSOCK_R = 0.9;
    static SimulationDef def;
    static World world;

    @BeforeAll
    static void build() throws Exception {
        def = SceneFiles.parse(Path.of("scenes/meadow.xml")).simulationDef();
        world = World.build(def, Path.of("scenes"), 4, Progress.NONE);
    }

    static int index(String id) {
        for (int s = 0; s < world.plants().species().size(); s++) {
            if (world.plants().species().get(s).def().id().equals(id)) {
                return s;
            }
        }
        throw new IllegalArgumentException("the meadow has no species '" + id + "'");
    }

    @Test
    void everySpeciesIsClumpedAtSmallScale() {
        List<String> even = new ArrayList<>();
        for (String id : SPECIES) {
            MeadowPattern.ClarkEvans ce = MeadowPattern.clarkEvans(world, index(id), WINDOW);
            System.out.printf("meadow %-8s Clark-Evans R in %.0f m windows: pooled %.3f, median %.3f, over %d "
                    + "windows of >= %d plants (%d plants)%n", id, WINDOW, ce.pooled(), ce.median(), ce.windows(),
                    MeadowPattern.MIN_PLANTS, ce.plants());
            assertTrue(ce.windows() >= 5, id + ": too few windows to judge: " + ce.windows());
            if (!(ce.pooled() <= 1.0)) {
                even.add(id + " R " + ce.pooled());
            }
        }
        assertEquals(List.of(), even, "species spaced more evenly than random");
    }

    @Test
    void plantHeightsVaryWithinEverySpecies() {
        List<String> uniform = new ArrayList<>();
        for (String id : SPECIES) {
            double[] h = MeadowPattern.heights(world, index(id));
            double[] ms = MeadowPattern.meanSd(h);
            System.out.printf("meadow %-8s height at rest: mean %.3f m, s.d. %.3f m (%.1f%% of the mean), %d plants%n",
                    id, ms[0], ms[1], 100 * ms[1] / ms[0], h.length);
            if (!(ms[1] >= 0.2 * ms[0])) {
                uniform.add(id + " s.d. " + ms[1] / ms[0]);
            }
        }
        assertEquals(List.of(), uniform, "species whose heights spread less than 20% of the mean");
    }

    /**
     * Issue 41's anatomy: at least 30% of the grass tufts (plants of a species without petals) carry a
     * seed head (a component carried by a culm, a stalk on the ground) that stands above the tuft's
     * highest leaf at rest, and every flower (a species with petals) carries leaves on its stalk, on a
     * point between its base and its tip.
     */
    @Test
    void grassesCarrySeedHeadsAboveTheirLeavesAndFlowersLeavesUpTheirStalks() {
        int tufts = 0;
        int headed = 0;
        int flowers = 0;
        int leafy = 0;
        for (int p = 0; p < world.plantCount(); p++) {
            org.jecosys.plant.SpeciesModel m = world.plants().species().get(world.plantSpecies(p));
            int v = world.plantVariant(p);
            boolean flower = false;
            double leafTop = 0;
            double headTop = 0;
            boolean stalkLeaf = false;
            for (int s = 0; s < m.slotCount(); s++) {
                org.jecosys.plant.ComponentType type = m.def().components().get(m.slotComponent(s)).type();
                int parent = m.slotParent(s);
                flower |= type == org.jecosys.plant.ComponentType.PETAL;
                if (parent < 0 && type == org.jecosys.plant.ComponentType.LEAF) {
                    leafTop = Math.max(leafTop, MeadowPattern.slotTop(m, s, v));
                }
                if (parent >= 0 && m.slotParent(parent) < 0
                        && m.def().components().get(m.slotComponent(parent)).type() == org.jecosys.plant.ComponentType.STALK) {
                    headTop = Math.max(headTop, MeadowPattern.slotTop(m, s, v));
                    int tip = m.def().components().get(m.slotComponent(parent)).segments();
                    stalkLeaf |= type == org.jecosys.plant.ComponentType.LEAF && m.slotAttachPoint(s) > 0
                            && m.slotAttachPoint(s) < tip;
                }
            }
            if (flower) {
                flowers++;
                leafy += stalkLeaf ? 1 : 0;
            } else {
                tufts++;
                headed += headTop > leafTop ? 1 : 0;
            }
        }
        System.out.printf("meadow anatomy: %d of %d grass tufts (%.1f%%) carry a seed head above their leaves; "
                + "%d of %d flowers carry leaves up their stalks%n", headed, tufts, 100.0 * headed / tufts, leafy,
                flowers);
        assertTrue(headed >= 0.3 * tufts, headed + " of " + tufts + " grass tufts carry seed heads");
        assertTrue(flowers > 1000, "the meadow has flowers: " + flowers);
        assertEquals(flowers, leafy, "every flower carries leaves up its stalk");
    }

    /**
     * Issue 41's wild structure: the visible tussocks (grass plants within 0.3 m of each other taken as
     * one, at their mean position) are clumped, not spaced like a crop: pooled Clark–Evans ratio at most
     * 0.9 in 4 m windows; and the valley, where the tall grass grows, has open gaps: 10–30% of its 1 m
     * cells hold no tall grass (valley: the cells whose water level, the map the plants were sorted by,
     * reaches the tall grass's minWater).
     */
    @Test
    void tussocksClumpAndTheValleyHasGaps() throws Exception {
        java.util.Set<Integer> grasses = java.util.Set.of(index("grassA"), index("grassS"), index("grassD"));
        float[][] t = MeadowPattern.tussocks(world, grasses, 0.3);
        MeadowPattern.ClarkEvans ce = MeadowPattern.clarkEvans(t[0], t[1], world, WINDOW);
        var terrain = org.jecosys.terrain.Terrain.build(def.terrain(), Path.of("scenes"), 2, Progress.NONE);
        var hf = terrain.heightfield();
        double minWater = 0;
        for (var d : def.distributions()) {
            if (d.species().equals("grassA")) {
                minWater = d.minWater();
            }
        }
        int cx = (int) Math.floor(hf.sizeX());
        int cz = (int) Math.floor(hf.sizeZ());
        boolean[] tall = new boolean[cx * cz];
        int grassA = index("grassA");
        for (int p = 0; p < world.plantCount(); p++) {
            if (world.plantSpecies(p) == grassA) {
                int a = (int) Math.floor(world.plantX(p) - hf.minX());
                int b = (int) Math.floor(world.plantZ(p) - hf.minZ());
                if (a >= 0 && b >= 0 && a < cx && b < cz) {
                    tall[b * cx + a] = true;
                }
            }
        }
        int valley = 0;
        int empty = 0;
        for (int b = 1; b < cz - 1; b++) {
            for (int a = 1; a < cx - 1; a++) {
                if (terrain.water().sample(hf.minX() + a + 0.5, hf.minZ() + b + 0.5) >= minWater) {
                    valley++;
                    empty += tall[b * cx + a] ? 0 : 1;
                }
            }
        }
        System.out.printf("meadow tussocks (grass within 0.3 m as one): %d, Clark-Evans R in %.0f m windows pooled "
                + "%.3f, median %.3f over %d windows; valley 1 m cells without tall grass: %d of %d (%.1f%%)%n",
                t[0].length, WINDOW, ce.pooled(), ce.median(), ce.windows(), empty, valley, 100.0 * empty / valley);
        assertTrue(ce.pooled() <= TUSSOCK_R, "tussocks clumped: R " + ce.pooled());
        assertTrue(valley > 500, "the valley is found: " + valley + " cells");
        double share = (double) empty / valley;
        assertTrue(share >= 0.1 && share <= 0.3, "valley cells without tall grass: " + share);
    }

    @Test
    void theMeadowIsTheSameWhateverTheThreads() throws Exception {
        World one = World.build(def, Path.of("scenes"), 1, Progress.NONE);
        World two = World.build(def, Path.of("scenes"), 2, Progress.NONE);
        String d1 = PaperScenesUnchangedTest.digest(one);
        assertEquals(d1, PaperScenesUnchangedTest.digest(two), "1 and 2 threads");
        assertEquals(d1, PaperScenesUnchangedTest.digest(world), "1 and 4 threads");
        assertEquals(36_433, one.plantCount(), "the meadow keeps its plant count");
    }
}
