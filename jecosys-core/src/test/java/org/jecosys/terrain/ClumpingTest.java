package org.jecosys.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import org.jecosys.math.Progress;
import org.junit.jupiter.api.Test;

/** Clumping in the competitive distributor: patches from above, exact counts, the old layout at strength 0. */
class ClumpingTest {
    private static final List<String> SPECIES = List.of("A", "B", "C");
    private static final TerrainDistributor DISTRIBUTOR = new CompetitiveDistributor();
    private static final double SIZE = 40;

    private static Terrain flat() {
        return new Terrain(Heightfield.of(SIZE, SIZE, 2, new float[4]), ResourceMap.uniform(SIZE, SIZE, 8, 1),
                ResourceMap.uniform(SIZE, SIZE, 8, 1));
    }

    private static DistributionDef grass(double clumpSize, double strength) {
        return DistributionDef.builder("A").count(2000).footprint(0.1).waterUse(0).nutrientUse(0)
                .clump(clumpSize, strength).build();
    }

    /** Variance of plant counts over the 1 m cells of the terrain. */
    private static double cellVariance(PlantLayout l) {
        int n = (int) SIZE;
        int[] cells = new int[n * n];
        for (int i = 0; i < l.count(); i++) {
            int cx = Math.min(n - 1, (int) Math.floor(l.x(i) + SIZE / 2));
            int cz = Math.min(n - 1, (int) Math.floor(l.z(i) + SIZE / 2));
            cells[cz * n + cx]++;
        }
        double mean = (double) l.count() / cells.length;
        double v = 0;
        for (int c : cells) {
            v += (c - mean) * (c - mean);
        }
        return v / cells.length;
    }

    @Test
    void clumpedCoverageVariesAtLeastTwiceAsMuchAsAUniformLayout() {
        PlantLayout uniform = DISTRIBUTOR.distribute(flat(), SPECIES, List.of(grass(1.5, 0)), List.of(), 21, 2,
                Progress.NONE);
        PlantLayout clumped = DISTRIBUTOR.distribute(flat(), SPECIES, List.of(grass(1.5, 1)), List.of(), 21, 2,
                Progress.NONE);
        assertEquals(2000, uniform.count());
        assertEquals(2000, clumped.count(), "clumping keeps the exact count");
        assertEquals(List.of(), clumped.warnings());
        int cells = (int) (SIZE * SIZE);
        // a uniform random layout of the same count: binomial counts per cell
        double binomial = 2000.0 / cells * (1 - 1.0 / cells);
        double vu = cellVariance(uniform);
        double vc = cellVariance(clumped);
        assertTrue(vu < 1.2 * binomial, "strength 0 is uniform: " + vu + " vs " + binomial);
        assertTrue(vc >= 2 * binomial, "clumped variance " + vc + " vs uniform random " + binomial);
        assertTrue(vc >= 2 * vu, "clumped variance " + vc + " vs the unclumped layout " + vu);
        // half strength lies in between
        PlantLayout half = DISTRIBUTOR.distribute(flat(), SPECIES, List.of(grass(1.5, 0.5)), List.of(), 21, 2,
                Progress.NONE);
        double vh = cellVariance(half);
        assertTrue(vh > vu && vh < vc, vu + " < " + vh + " < " + vc);
    }

    @Test
    void strengthZeroIsTheOldLayoutWhateverTheClumpSize() throws IOException {
        Terrain t = CompetitiveDistributorTest.meadow(3);
        DistributionDef old = CompetitiveDistributorTest.tuft(300);
        DistributionDef sized = old.toBuilder().clump(7, 0).build();
        assertEquals(DistributionDef.DEFAULT_CLUMP_STRENGTH, old.clumpStrength());
        PlantLayout a = DISTRIBUTOR.distribute(t, SPECIES, List.of(old, CompetitiveDistributorTest.yellow(80)),
                List.of(), 5, 1, Progress.NONE);
        PlantLayout b = DISTRIBUTOR.distribute(t, SPECIES, List.of(sized, CompetitiveDistributorTest.yellow(80)),
                List.of(), 5, 3, Progress.NONE);
        assertSameLayout(a, b);
    }

    @Test
    void clumpedLayoutIsDeterministicForTheSeedWhateverTheThreads() throws IOException {
        Terrain t = CompetitiveDistributorTest.meadow(4);
        List<DistributionDef> defs = List.of(CompetitiveDistributorTest.tuft(400).toBuilder().clump(2, 0.9).build(),
                CompetitiveDistributorTest.yellow(100).toBuilder().clump(1, 1).build());
        PlantLayout one = DISTRIBUTOR.distribute(t, SPECIES, defs, List.of(), 8, 1, Progress.NONE);
        PlantLayout four = DISTRIBUTOR.distribute(t, SPECIES, defs, List.of(), 8, 4, Progress.NONE);
        assertSameLayout(one, four);
        PlantLayout other = DISTRIBUTOR.distribute(t, SPECIES, defs, List.of(), 9, 1, Progress.NONE);
        assertNotEquals(one.x(0), other.x(0));
    }

    @Test
    void badClumpValuesAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> grass(1, 1.01));
        assertThrows(IllegalArgumentException.class, () -> grass(1, -0.1));
        assertThrows(IllegalArgumentException.class, () -> grass(0, 0.5));
        assertThrows(IllegalArgumentException.class, () -> grass(Double.NaN, 0.5));
    }

    private static void assertSameLayout(PlantLayout a, PlantLayout b) {
        assertEquals(a.count(), b.count());
        for (int i = 0; i < a.count(); i++) {
            assertEquals(a.x(i), b.x(i));
            assertEquals(a.z(i), b.z(i));
            assertEquals(a.azimuth(i), b.azimuth(i));
            assertEquals(a.species(i), b.species(i));
            assertEquals(a.variantSeed(i), b.variantSeed(i));
        }
    }
}
