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
