package org.jecosys.terrain;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.jecosys.math.Progress;
import org.junit.jupiter.api.Test;

class CompetitiveDistributorTest {
    private static final List<String> SPECIES = List.of("A", "B", "C");
    private static final TerrainDistributor DISTRIBUTOR = new CompetitiveDistributor();

    /** A 40 m meadow with hills, water in the valleys and noisy nutrients (like the paper's scenes). */
    static Terrain meadow(long seed) throws IOException {
        TerrainDef def = new TerrainDef(40, 40, 129, 4, 0.5, seed, null,
                new ResourceMapDef(ResourceMapDef.Source.VALLEYS, 64, 1, 1, null),
                new ResourceMapDef(ResourceMapDef.Source.NOISE, 64, 1, 8, null));
        return Terrain.build(def, ImageSource.NONE, 1, Progress.NONE);
    }

    /** Grass tuft: footprint 0.3 m, tolerant. */
    static DistributionDef tuft(int count) {
        return DistributionDef.builder("A").count(count).density(0).water(0.1, 1).maxSlope(0.6).altitude(-100, 100)
                .footprint(0.3).waterUse(0.2).nutrientUse(0.1).build();
    }

    /** Yellow flower: footprint 0.1 m, likes nutrients. */
    static DistributionDef yellow(int count) {
        return DistributionDef.builder("B").count(count).density(0).nutrients(0.3, 1).maxSlope(0.5).altitude(-100, 100)
                .footprint(0.1).waterUse(0.1).nutrientUse(0.3).build();
    }

    /** Purple flower: footprint 0.15 m, likes it moist and low. */
    static DistributionDef purple(int count) {
        return DistributionDef.builder("C").count(count).density(0).water(0.4, 1).maxSlope(0.5).altitude(-100, 3)
                .footprint(0.15).waterUse(0.3).nutrientUse(0.1).build();
    }

    @Test
    void sceneC1CountsAreExact() throws IOException {
        Terrain t = meadow(1);
        List<DistributionDef> defs = List.of(tuft(50), yellow(15), purple(15));
        PlantLayout l = DISTRIBUTOR.distribute(t, SPECIES, defs, List.of(), 4, 1, Progress.NONE);
        assertEquals(80, l.count());
        assertEquals(List.of(), l.warnings());
        assertSpeciesCounts(l, 50, 15, 15);
        checkInvariants(t, defs, l);
    }

    @Test
    void sceneC3CountsAreExact() throws IOException {
        Terrain t = meadow(2);
        List<DistributionDef> defs = List.of(yellow(100), purple(100));
        PlantLayout l = DISTRIBUTOR.distribute(t, SPECIES, defs, List.of(), 5, 2, Progress.NONE);
        assertEquals(List.of(), l.warnings());
        assertSpeciesCounts(l, 0, 100, 100);
        checkInvariants(t, defs, l);
    }

    @Test
    void everyPlantStandsOnTheSurfaceWithinItsPreferencesAndOffOthersGround() throws IOException {
        Terrain t = meadow(3);
        List<DistributionDef> defs = List.of(tuft(1500), yellow(800), purple(800));
        AtomicLong last = new AtomicLong(-1);
        PlantLayout l = DISTRIBUTOR.distribute(t, SPECIES, defs, List.of(), 6, 2, (step, done, total) -> {
            assertEquals("distribution", step);
            assertTrue(done >= last.get() && done <= total);
            last.set(done);
        });
        assertEquals(3100, last.get());
        assertSpeciesCounts(l, 1500, 800, 800);
        checkInvariants(t, defs, l);
    }

    @Test
    void sameSeedSamePlacementWithOneAndTwoThreads() throws IOException {
        Terrain t = meadow(4);
        DistributionDef lightTuft = DistributionDef.builder("A").count(1500).density(0).water(0.1, 1).maxSlope(0.6)
                .altitude(-100, 100).footprint(0.3).waterUse(0.05).nutrientUse(0.05).build();
        List<DistributionDef> defs = List.of(lightTuft, yellow(1500), purple(1000));
        PlantLayout one = DISTRIBUTOR.distribute(t, SPECIES, defs, List.of(new PlacementDef("B", 1, 2, 0.5)), 77, 1, Progress.NONE);
        PlantLayout two = DISTRIBUTOR.distribute(t, SPECIES, defs, List.of(new PlacementDef("B", 1, 2, 0.5)), 77, 2, Progress.NONE);
        assertEquals(4001, one.count(), one.warnings().toString());
        assertEquals(one.count(), two.count());
        assertArrayEquals(one.copyX(), two.copyX());
        assertArrayEquals(one.copyY(), two.copyY());
        assertArrayEquals(one.copyZ(), two.copyZ());
        assertArrayEquals(one.copySpecies(), two.copySpecies());
        assertArrayEquals(one.copyAzimuths(), two.copyAzimuths());
        assertArrayEquals(one.copyVariantSeeds(), two.copyVariantSeeds());
        assertEquals(one.warnings(), two.warnings());
        PlantLayout other = DISTRIBUTOR.distribute(t, SPECIES, defs, List.of(), 78, 2, Progress.NONE);
        assertTrue(other.x(0) != one.x(1) || other.z(0) != one.z(1));
    }

    @Test
    void speciesMatchingNowhereGetsNoPlantsAndAWarning() throws IOException {
        Terrain t = meadow(5);
        DistributionDef alpine = DistributionDef.builder("C").count(40).density(0).maxSlope(0.5).altitude(500, 600)
                .footprint(0.1).waterUse(0.1).nutrientUse(0.1).build();
        DistributionDef byDensity = DistributionDef.builder("B").density(2).maxSlope(0.5).altitude(500, 600)
                .footprint(0.1).waterUse(0.1).nutrientUse(0.1).build();
        PlantLayout l = DISTRIBUTOR.distribute(t, SPECIES, List.of(tuft(30), alpine, byDensity), List.of(), 1, 1,
                Progress.NONE);
        assertSpeciesCounts(l, 30, 0, 0);
        assertEquals(2, l.warnings().size(), l.warnings().toString());
        assertTrue(l.warnings().get(0).contains("'C'") && l.warnings().get(0).contains("matches nowhere"));
        assertTrue(l.warnings().get(1).contains("'B'") && l.warnings().get(1).contains("matches nowhere"));
        assertEquals(0, l.placed(1));
    }

    @Test
    void densityMultipliesTheSuitableArea() {
        Terrain flat = new Terrain(Heightfield.of(40, 40, 2, new float[4]), ResourceMap.uniform(40, 40, 8, 1),
                ResourceMap.uniform(40, 40, 8, 1));
        DistributionDef d = DistributionDef.builder("A").density(0.5).maxSlope(0.5).altitude(-1, 1).waterUse(0.1)
                .nutrientUse(0.1).build();
        PlantLayout l = DISTRIBUTOR.distribute(flat, SPECIES, List.of(d), List.of(), 3, 2, Progress.NONE);
        assertEquals(800, l.target(0));
        assertEquals(800, l.count());
        assertEquals(List.of(), l.warnings());
    }

    @Test
    void impossibleCountPlacesWhatFitsAndWarnsOfTheShortfall() {
        Terrain small = new Terrain(Heightfield.of(10, 10, 2, new float[4]), ResourceMap.uniform(10, 10, 8, 1),
                ResourceMap.uniform(10, 10, 8, 1));
        DistributionDef big = DistributionDef.builder("A").count(500).density(0).maxSlope(0.5).altitude(-1, 1)
                .footprint(1.0).waterUse(0).nutrientUse(0).build();
        PlantLayout l = DISTRIBUTOR.distribute(small, SPECIES, List.of(big), List.of(), 3, 1, Progress.NONE);
        assertTrue(l.count() > 10 && l.count() < 40, "count " + l.count());
        assertEquals(1, l.warnings().size());
        assertTrue(l.warnings().get(0).contains("shortfall " + (500 - l.count())), l.warnings().get(0));
        checkInvariants(small, List.of(big), l);
    }

    @Test
    void consumedResourcesAreNoLongerAvailableToTheOtherSpecies() {
        // 10 m square, water 1 in 2.5 m cells; each plant drinks its footprint dry; nobody grows below 0.9
        Terrain t = new Terrain(Heightfield.of(10, 10, 2, new float[4]), ResourceMap.uniform(10, 10, 4, 1),
                ResourceMap.uniform(10, 10, 4, 1));
        DistributionDef a = DistributionDef.builder("A").count(1000).density(0).water(0.9, 1).maxSlope(0.5)
                .altitude(-1, 1).footprint(0.3).waterUse(1).nutrientUse(0).build();
        DistributionDef b = DistributionDef.builder("B").count(1000).density(0).water(0.9, 1).maxSlope(0.5)
                .altitude(-1, 1).footprint(0.3).waterUse(1).nutrientUse(0).build();
        PlantLayout alone = DISTRIBUTOR.distribute(t, SPECIES, List.of(b), List.of(), 9, 1, Progress.NONE);
        PlantLayout both = DISTRIBUTOR.distribute(t, SPECIES, List.of(a, b), List.of(), 9, 1, Progress.NONE);
        assertTrue(both.placed(1) < alone.placed(0), both.placed(1) + " vs " + alone.placed(0) + " " + both.placed(0));
        assertTrue(both.placed(0) > 0.3 * (both.placed(0) + both.placed(1)), "A took " + both.placed(0));
        assertTrue(both.placed(1) > 0.3 * (both.placed(0) + both.placed(1)), "B took " + both.placed(1));
        // the water ran out long before the ground did (random packing would fit about 190)
        assertTrue(both.count() < 100, "count " + both.count());
        checkInvariants(t, List.of(a, b), both);
    }

    @Test
    void handPlacementsComeFirstTakeGroundAndConsume() throws IOException {
        Terrain t = meadow(6);
        List<PlacementDef> hand = List.of(new PlacementDef("C", 0, 0, -1), new PlacementDef("A", 5, 5, 6));
        List<DistributionDef> defs = List.of(tuft(400));
        PlantLayout l = DISTRIBUTOR.distribute(t, SPECIES, defs, hand, 2, 1, Progress.NONE);
        assertEquals(402, l.count());
        assertEquals(-1, l.distribution(0));
        assertEquals(2, l.species(0));
        assertEquals(0, l.x(0), 0);
        assertEquals(t.heightfield().height(0, 0), l.y(0), 1e-4);
        assertEquals(2 * Math.PI - 1, l.azimuth(0), 1e-6);
        assertEquals(CompetitiveDistributor.PLACEMENT_FOOTPRINT, l.footprint(0), 1e-6);
        assertEquals(0.3, l.footprint(1), 1e-6);
        assertTrue(l.remainingWater().footprintLevel(0, 0, 0.25) < t.water().footprintLevel(0, 0, 0.25));
        checkInvariants(t, defs, l);
    }

    @Test
    void badArgumentsFailFast() throws IOException {
        Terrain t = meadow(7);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> DISTRIBUTOR.distribute(t, List.of("A"), List.of(yellow(3)), List.of(), 1, 1, Progress.NONE));
        assertTrue(e.getMessage().contains("distributions[0]") && e.getMessage().contains("'B'"));
        e = assertThrows(IllegalArgumentException.class,
                () -> DISTRIBUTOR.distribute(t, SPECIES, List.of(), List.of(), 1, 0, Progress.NONE));
        assertTrue(e.getMessage().contains("workers"));
        e = assertThrows(IllegalArgumentException.class, () -> DISTRIBUTOR.distribute(t, SPECIES, List.of(),
                List.of(new PlacementDef("A", 30, 0, 0)), 1, 1, Progress.NONE));
        assertTrue(e.getMessage().contains("placements[0]"));
    }

    private static void assertSpeciesCounts(PlantLayout l, int... expected) {
        int[] counts = new int[SPECIES.size()];
        for (int i = 0; i < l.count(); i++) {
            counts[l.species(i)]++;
        }
        assertArrayEquals(expected, counts);
    }

    /**
     * Inside the terrain, on its surface, within preferences (re-derived by replaying the placements
     * on fresh copies of the initial maps), no overlapping footprints, resources never below zero.
     */
    static void checkInvariants(Terrain t, List<DistributionDef> defs, PlantLayout l) {
        Heightfield hf = t.heightfield();
        ResourceMap water = t.water().copy();
        ResourceMap nutrients = t.nutrients().copy();
        for (int i = 0; i < l.count(); i++) {
            double x = l.x(i);
            double z = l.z(i);
            double r = l.footprint(i);
            assertTrue(hf.contains(x, z), "plant " + i + " outside");
            assertEquals(hf.height(x, z), l.y(i), 1e-4 + 1e-6 * Math.abs(l.y(i)), "plant " + i + " off the surface");
            assertTrue(l.azimuth(i) >= 0 && l.azimuth(i) < 2 * Math.PI + 1e-6);
            double w = water.footprintLevel(x, z, r);
            double n = nutrients.footprintLevel(x, z, r);
            assertEquals(w, l.waterAtPlacement(i), 1e-6, "plant " + i + " water at placement");
            assertEquals(n, l.nutrientsAtPlacement(i), 1e-6, "plant " + i + " nutrients at placement");
            int d = l.distribution(i);
            if (d >= 0) {
                DistributionDef def = defs.get(d);
                assertEquals(def.species(), SPECIES.get(l.species(i)));
                assertEquals(def.footprint(), r, 1e-6);
                assertTrue(w >= def.minWater() - 1e-9 && w <= def.maxWater() + 1e-9, "plant " + i + " water " + w);
                assertTrue(n >= def.minNutrients() - 1e-9 && n <= def.maxNutrients() + 1e-9, "plant " + i + " nutrients " + n);
                assertTrue(hf.slope(x, z) <= def.maxSlope() + 1e-9, "plant " + i + " slope");
                assertTrue(l.y(i) >= def.minAltitude() - 1e-4 && l.y(i) <= def.maxAltitude() + 1e-4, "plant " + i + " altitude");
                water.consume(x, z, r, def.waterUse());
                nutrients.consume(x, z, r, def.nutrientUse());
                assertTrue(water.min() >= 0 && nutrients.min() >= 0);
            }
        }
        assertTrue(l.remainingWater().min() >= 0);
        assertTrue(l.remainingNutrients().min() >= 0);
        // footprints do not overlap (bucketed check)
        double cell = 1.0;
        java.util.Map<Long, List<Integer>> buckets = new java.util.HashMap<>();
        for (int i = 0; i < l.count(); i++) {
            long key = ((long) Math.floor(l.x(i) / cell) << 32) ^ (Math.floor(l.z(i) / cell) < 0 ? 0 : 0)
                    ^ ((long) Math.floor(l.z(i) / cell) & 0xFFFFFFFFL);
            buckets.computeIfAbsent(key, k -> new java.util.ArrayList<>()).add(i);
        }
        for (int i = 0; i < l.count(); i++) {
            long bx = (long) Math.floor(l.x(i) / cell);
            long bz = (long) Math.floor(l.z(i) / cell);
            for (long dx = -1; dx <= 1; dx++) {
                for (long dz = -1; dz <= 1; dz++) {
                    List<Integer> near = buckets.get(((bx + dx) << 32) ^ ((bz + dz) & 0xFFFFFFFFL));
                    if (near == null) {
                        continue;
                    }
                    for (int j : near) {
                        if (j <= i) {
                            continue;
                        }
                        double ddx = l.x(i) - l.x(j);
                        double ddz = l.z(i) - l.z(j);
                        double s = l.footprint(i) + l.footprint(j);
                        if (l.distribution(i) >= 0 || l.distribution(j) >= 0) {
                            assertTrue(ddx * ddx + ddz * ddz >= s * s * (1 - 1e-5), "plants " + i + " and " + j + " overlap");
                        }
                    }
                }
            }
        }
    }
}
