package org.jecosys.terrain;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.Progress;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Placement cost follows the scene's size whatever the mix of footprints (issue 36, fault 4). The work
 * is measured by the footprint search's own counter (buckets and discs looked at), not by a clock: one
 * distribution with a 100 m footprint and {@code count="0"} beside 100,000 plants once put every plant
 * in one bucket (400,000 plants: 498 s instead of 2 s); now it costs them nothing, and a few large
 * plants among many small ones cost a bounded number of visits per candidate. The work never exceeds
 * {@link PlacementWork}'s bound, which the scene check budgets.
 */
@Tag("reliability")
class PlacementScaleReliabilityTest {
    private static final List<String> SPECIES = List.of("grass", "tree");
    /** Plants of the dense distribution: enough that a quadratic search shows by orders of magnitude. */
    private static final int PLANTS = 100_000;
    private static TerrainDef def;
    private static Terrain terrain;

    @BeforeAll
    static void terrain() throws IOException {
        def = new TerrainDef(100, 100, 2, 0, 0.5, 1, null, ResourceMapDef.UNIFORM_FULL, ResourceMapDef.UNIFORM_FULL);
        terrain = Terrain.build(def, ImageSource.NONE, 1, Progress.NONE);
    }

    private static DistributionDef grass(int count) {
        return DistributionDef.builder("grass").count(count).density(0).maxSlope(1.5).altitude(-100, 100)
                .footprint(0.05).waterUse(0).nutrientUse(0).build();
    }

    private static DistributionDef tree(int count, double footprint) {
        return DistributionDef.builder("tree").count(count).density(0).maxSlope(1.5).altitude(-100, 100)
                .footprint(footprint).waterUse(0).nutrientUse(0).build();
    }

    private static PlantLayout place(List<DistributionDef> defs) {
        return new CompetitiveDistributor().distribute(terrain, SPECIES, defs, List.of(), 7, 2, Progress.NONE);
    }

    /** Σ candidates x search per candidate: the search's share of the bound. */
    private static double searchBound(List<DistributionDef> defs) {
        PlacementWork w = PlacementWork.estimate(def, defs, List.of());
        double s = 0;
        for (int d = 0; d < defs.size(); d++) {
            s += w.candidates(d) * w.searchPerCandidate(d);
        }
        return s;
    }

    @Test
    void a100MetreFootprintWithCountZeroCostsTheOtherPlantsNothing() {
        List<DistributionDef> alone = List.of(grass(PLANTS));
        List<DistributionDef> beside = new ArrayList<>(alone);
        beside.add(tree(0, 100));
        PlantLayout a = place(alone);
        PlantLayout b = place(beside);
        assertEquals(PLANTS, a.count());
        assertArrayEquals(a.copyX(), b.copyX(), "the same plants, in the same order");
        assertArrayEquals(a.copyZ(), b.copyZ());
        assertArrayEquals(a.copyVariantSeeds(), b.copyVariantSeeds());
        assertTrue(b.occupancyVisits() <= 2 * a.occupancyVisits(), "with the 100 m distribution "
                + b.occupancyVisits() + " visits, without " + a.occupancyVisits());
        assertTrue(a.occupancyVisits() <= 30L * PLANTS, "a few buckets and discs per plant: " + a.occupancyVisits());
        assertTrue(b.occupancyVisits() <= searchBound(beside), "within the bound the check budgets");
    }

    @Test
    void aFewLargePlantsAmongManySmallOnesCostABoundedNumberOfVisits() {
        List<DistributionDef> alone = List.of(grass(PLANTS));
        List<DistributionDef> mixed = List.of(grass(PLANTS), tree(40, 3));
        PlantLayout a = place(alone);
        PlantLayout m = place(mixed);
        assertEquals(PLANTS, m.placed(0), String.join("; ", m.warnings()));
        assertTrue(m.placed(1) >= 1, "a tree grows");
        // the grass soon leaves no 3 m of free ground, so the trees spend all their candidates, each
        // looking at the grass buckets its disc spans: a bounded extra, not a multiple of the grass's
        // own work (one grid sized by the trees cost over 100 times as much)
        assertTrue(m.occupancyVisits() <= 3 * a.occupancyVisits(), "with 40 trees " + m.occupancyVisits()
                + " visits, without " + a.occupancyVisits());
        assertTrue(m.occupancyVisits() <= searchBound(mixed), "within the bound the check budgets");
    }

    @Test
    void theBoundSeesNoWorkForACountOfZeroAndFollowsThePlantCount() {
        PlacementWork small = PlacementWork.estimate(def, List.of(grass(PLANTS / 10)), List.of());
        PlacementWork large = PlacementWork.estimate(def, List.of(grass(PLANTS)), List.of());
        PlacementWork beside = PlacementWork.estimate(def, List.of(grass(PLANTS), tree(0, 100)), List.of());
        assertEquals(0, beside.candidates(1));
        assertEquals(large.searchPerCandidate(0), beside.searchPerCandidate(0), "the empty class is not searched");
        // a mask and one more distribution in the acceptance order: a few percent, not a multiple
        assertTrue(beside.total() <= 1.05 * large.total(), beside.total() + " vs " + large.total());
        // per plant, ten times the plants cost no more: the work is linear in the plants, not quadratic
        // (a sparse class even bounds higher per plant: its coarser buckets may hold more discs)
        double perPlantSmall = small.total() / (PLANTS / 10);
        double perPlantLarge = large.total() / PLANTS;
        assertTrue(perPlantLarge <= perPlantSmall, perPlantLarge + " units per plant vs " + perPlantSmall);
    }
}
