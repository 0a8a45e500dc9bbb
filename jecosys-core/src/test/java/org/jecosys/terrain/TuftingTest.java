package org.jecosys.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import org.jecosys.math.Progress;
import org.junit.jupiter.api.Test;

/**
 * Tufts in the competitive distributor ({@link DistributionDef#tuftCount()}, issue 25): plants gather in
 * small groups, so the layout is clumped at small scale (Clark–Evans ratio below 1) where footprints
 * alone space it more evenly than random; counts stay exact; one candidate per centre is the old
 * layout bit for bit; deterministic whatever the threads.
 */
class TuftingTest {
    private static final List<String> SPECIES = List.of("A", "B", "C");
    private static final TerrainDistributor DISTRIBUTOR = new CompetitiveDistributor();
    private static final double SIZE = 30;

    private static Terrain flat() {
        return new Terrain(Heightfield.of(SIZE, SIZE, 2, new float[4]), ResourceMap.uniform(SIZE, SIZE, 8, 1),
                ResourceMap.uniform(SIZE, SIZE, 8, 1));
    }

    private static DistributionDef grass(double tuftSize, int tuftCount) {
        return DistributionDef.builder("A").count(4000).footprint(0.05).waterUse(0).nutrientUse(0)
                .tufts(tuftSize, tuftCount).build();
    }

    /**
     * Clark–Evans ratio of the plants at least 2 m inside the terrain: their mean nearest-neighbour
     * distance (to any plant) over 0.5 / sqrt(density), density = all plants over the terrain's area.
     */
    static double clarkEvans(PlantLayout l) {
        double sum = 0;
        int n = 0;
        for (int i = 0; i < l.count(); i++) {
            if (Math.abs(l.x(i)) > SIZE / 2 - 2 || Math.abs(l.z(i)) > SIZE / 2 - 2) {
                continue;
            }
            double best = Double.POSITIVE_INFINITY;
            for (int j = 0; j < l.count(); j++) {
                if (j != i) {
                    best = Math.min(best, Math.hypot(l.x(j) - l.x(i), l.z(j) - l.z(i)));
                }
            }
            sum += best;
            n++;
        }
        return sum / n / (0.5 / Math.sqrt(l.count() / (SIZE * SIZE)));
    }

    @Test
    void tuftsClumpTheLayoutAtSmallScale() {
        PlantLayout even = DISTRIBUTOR.distribute(flat(), SPECIES, List.of(grass(0.1, 1)), List.of(), 3, 2,
                Progress.NONE);
        PlantLayout tufted = DISTRIBUTOR.distribute(flat(), SPECIES, List.of(grass(0.1, 4)), List.of(), 3, 2,
                Progress.NONE);
        assertEquals(4000, even.count());
        assertEquals(4000, tufted.count(), "tufts keep the exact count");
        assertEquals(List.of(), tufted.warnings());
        double re = clarkEvans(even);
        double rt = clarkEvans(tufted);
        System.out.printf("Clark-Evans R: untufted %.3f, tufts of 4 (s.d. 0.1 m) %.3f%n", re, rt);
        assertTrue(re >= 0.95, "footprints alone space the plants about as evenly as random or more: " + re);
        assertTrue(rt <= 0.75, "tufted layout is clumped: R " + rt);
    }

    @Test
    void oneCandidatePerCentreIsTheOldLayoutWhateverTheTuftSize() throws IOException {
        Terrain t = CompetitiveDistributorTest.meadow(3);
        DistributionDef old = CompetitiveDistributorTest.tuft(300).toBuilder().clump(2, 0.5).build();
        DistributionDef sized = old.toBuilder().tufts(3, 1).build();
        assertEquals(DistributionDef.DEFAULT_TUFT_COUNT, old.tuftCount());
        PlantLayout a = DISTRIBUTOR.distribute(t, SPECIES, List.of(old, CompetitiveDistributorTest.yellow(80)),
                List.of(), 5, 1, Progress.NONE);
        PlantLayout b = DISTRIBUTOR.distribute(t, SPECIES, List.of(sized, CompetitiveDistributorTest.yellow(80)),
                List.of(), 5, 3, Progress.NONE);
        assertSameLayout(a, b);
    }

    @Test
    void tuftedLayoutIsDeterministicForTheSeedWhateverTheThreads() throws IOException {
        Terrain t = CompetitiveDistributorTest.meadow(4);
        List<DistributionDef> defs = List.of(
                CompetitiveDistributorTest.tuft(400).toBuilder().footprint(0.05).clump(2, 0.9).tufts(0.1, 5).build(),
                CompetitiveDistributorTest.yellow(100).toBuilder().tufts(0.2, 3).build());
        assertSameForOneAndFourThreads(t, defs, 500);
    }

    /** The layout of {@code defs} (seed 8) on 1 and 4 threads: the same, with {@code count} plants. */
    private static void assertSameForOneAndFourThreads(Terrain t, List<DistributionDef> defs, int count)
            throws IOException {
        PlantLayout one = DISTRIBUTOR.distribute(t, SPECIES, defs, List.of(), 8, 1, Progress.NONE);
        PlantLayout four = DISTRIBUTOR.distribute(t, SPECIES, defs, List.of(), 8, 4, Progress.NONE);
        assertSameLayout(one, four);
        assertEquals(count, one.count());
    }

    /** Tufts of 9 on a flat square, each split into 3 bunches on a 0.2 m ring, spread 5 mm round them. */
    private static DistributionDef ringed(int bunches, double ring) {
        return DistributionDef.builder("A").count(1800).footprint(0.002).waterUse(0).nutrientUse(0)
                .tufts(DistributionDef.MIN_TUFT_SIZE, 9).bunches(ring, bunches).build();
    }

    /**
     * Issue 41's hollow crowns: each tuft's plants stand in bunches on the ring round its centre. The
     * plants joined within 5 cm are the bunches; a bunch's nearest bunch is its sibling on the ring, a
     * chord of the 0.2 m ring between 2 x 0.2 sin(60 deg - 12 deg) and 2 x 0.2 sin(60 deg + 12 deg) (the
     * spacing moved by at most a tenth), widened by the bunches' spread; the bunches differ in size
     * (each plant joins one at random); and one bunch is the tufted layout bit for bit, whatever the ring.
     */
    @Test
    void bunchesStandOnTheirTuftsRingAndDifferInSize() {
        PlantLayout l = DISTRIBUTOR.distribute(flat(), SPECIES, List.of(ringed(3, 0.2)), List.of(), 11, 2,
                Progress.NONE);
        assertEquals(1800, l.count());
        float[] x = new float[l.count()];
        float[] z = new float[l.count()];
        for (int i = 0; i < l.count(); i++) {
            x[i] = l.x(i);
            z[i] = l.z(i);
        }
        double[][] b = PointGroups.join(x, z, x.length, 0.05);
        int n = b[0].length;
        int onRing = 0;
        int counted = 0;
        java.util.Set<Integer> sizes = new java.util.TreeSet<>();
        for (int i = 0; i < n; i++) {
            sizes.add((int) b[2][i]);
            if (Math.abs(b[0][i]) > SIZE / 2 - 1 || Math.abs(b[1][i]) > SIZE / 2 - 1) {
                continue;
            }
            double best = Double.POSITIVE_INFINITY;
            for (int j = 0; j < n; j++) {
                if (j != i) {
                    best = Math.min(best, Math.hypot(b[0][j] - b[0][i], b[1][j] - b[1][i]));
                }
            }
            counted++;
            onRing += best >= 2 * 0.2 * Math.sin(Math.toRadians(48)) - 0.02
                    && best <= 2 * 0.2 * Math.sin(Math.toRadians(72)) + 0.02 ? 1 : 0;
        }
        System.out.printf("bunches: %d of %d plants (sizes %s); %d of %d have their nearest bunch at the ring's "
                + "chord%n", n, l.count(), sizes, onRing, counted);
        // 200 tufts of 9 plants over 900 m^2: another tuft's bunch is rarely the nearest
        assertTrue(onRing >= 0.8 * counted, onRing + " of " + counted + " bunches have a sibling at the chord");
        assertTrue(sizes.size() >= 4, "bunches of uneven size: " + sizes);
        PlantLayout one = DISTRIBUTOR.distribute(flat(), SPECIES, List.of(ringed(1, 0.7)), List.of(), 11, 2,
                Progress.NONE);
        PlantLayout plain = DISTRIBUTOR.distribute(flat(), SPECIES, List.of(ringed(1, 0).toBuilder()
                .bunches(DistributionDef.DEFAULT_TUFT_RING, DistributionDef.DEFAULT_TUFT_BUNCHES).build()),
                List.of(), 11, 1, Progress.NONE);
        assertSameLayout(plain, one);
    }

    @Test
    void bunchedLayoutIsDeterministicForTheSeedWhateverTheThreads() throws IOException {
        Terrain t = CompetitiveDistributorTest.meadow(4);
        List<DistributionDef> defs = List.of(
                CompetitiveDistributorTest.tuft(400).toBuilder().footprint(0.005).clump(2, 0.5).tufts(0.01, 9)
                        .bunches(0.19, 3).build(),
                CompetitiveDistributorTest.yellow(100).toBuilder().tufts(0.02, 4).bunches(0.2, 2).build());
        assertSameForOneAndFourThreads(t, defs, 500);
    }

    @Test
    void badBunchValuesAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> ringed(0, 0.2));
        assertThrows(IllegalArgumentException.class, () -> ringed(DistributionDef.MAX_TUFT_BUNCHES + 1, 0.2));
        assertThrows(IllegalArgumentException.class, () -> ringed(3, -0.1));
        assertThrows(IllegalArgumentException.class, () -> ringed(3, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> ringed(3, DistributionDef.MAX_TUFT_SIZE * 2));
    }

    @Test
    void badTuftValuesAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> grass(0.1, 0));
        assertThrows(IllegalArgumentException.class, () -> grass(0.1, DistributionDef.MAX_TUFT_COUNT + 1));
        assertThrows(IllegalArgumentException.class, () -> grass(0, 3));
        assertThrows(IllegalArgumentException.class, () -> grass(Double.NaN, 3));
        assertThrows(IllegalArgumentException.class, () -> grass(DistributionDef.MAX_TUFT_SIZE * 2, 3));
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
