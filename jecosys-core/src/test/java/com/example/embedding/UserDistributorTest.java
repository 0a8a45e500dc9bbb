package com.example.embedding;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import org.jecosys.math.Progress;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.SimulationDef;
import org.jecosys.sim.World;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.terrain.PlacementDef;
import org.jecosys.terrain.PlantLayout;
import org.jecosys.terrain.Terrain;
import org.jecosys.terrain.TerrainDistributor;
import org.jecosys.wind.FlowDef;
import org.junit.jupiter.api.Test;

/** A game's own placement rule (paper §4.3's extension point) populates a running simulation. */
class UserDistributorTest {
    /** Hand placements first, then each distribution's count of plants in a row along X at z = 2 d. */
    static final class RowDistributor implements TerrainDistributor {
        @Override
        public PlantLayout distribute(Terrain terrain, List<String> speciesIds, List<DistributionDef> distributions,
                                      List<PlacementDef> placements, long seed, int workers, Progress progress) {
            PlantLayout.Builder b = new PlantLayout.Builder();
            for (PlacementDef p : placements) {
                add(b, terrain, p.x(), p.z(), speciesIds.indexOf(p.species()), -1, seed + b.size());
            }
            int[] placed = new int[distributions.size()];
            for (int d = 0; d < distributions.size(); d++) {
                DistributionDef dist = distributions.get(d);
                int n = dist.count();
                for (int i = 0; i < n; i++) {
                    add(b, terrain, -15 + 30.0 * i / Math.max(1, n - 1), 2 * d, speciesIds.indexOf(dist.species()), d,
                            seed + b.size());
                }
                placed[d] = n;
                progress.report("distribution", d + 1, distributions.size());
            }
            return b.build(placed, placed.clone(), List.of(), terrain.water(), terrain.nutrients());
        }

        private static void add(PlantLayout.Builder b, Terrain t, double x, double z, int species, int dist,
                                long seed) {
            float y = (float) t.heightfield().height(x, z);
            b.add((float) x, y, (float) z, 0, 0.2f, 1, 1, species, dist, seed);
        }
    }

    @Test
    void plantsPlacedByAUserDistributorAnimate() throws Exception {
        SimulationDef def = Meadows.def(Meadows.at(-5, -8),
                List.of(DistributionDef.builder(Meadows.SPECIES).count(7).build()),
                List.of(FlowDef.uniform("breeze", 2.5, 0)));
        World world = World.build(def, Path.of("."), 2, Progress.NONE, new RowDistributor());
        assertEquals(8, world.plantCount());
        TreeSet<Double> row = new TreeSet<>();
        for (int p = 0; p < world.plantCount(); p++) {
            if (world.plantZ(p) == 0) {
                row.add((double) world.plantX(p));
            }
        }
        assertEquals(List.of(-15.0, -10.0, -5.0, 0.0, 5.0, 10.0, 15.0), new ArrayList<>(row));
        int hand = Meadows.plantAt(world, -5, -8);
        assertEquals(-5, world.plantX(hand), 0);
        assertEquals(-8, world.plantZ(hand), 0);

        World competitive = Meadows.world(def);
        int onTheRow = 0;
        for (int p = 0; p < competitive.plantCount(); p++) {
            onTheRow += competitive.plantZ(p) == 0 ? 1 : 0;
        }
        assertTrue(onTheRow < 7, "the paper's distributor places them elsewhere: the user's one was used");

        try (Simulation sim = Simulation.of(world, def, 0)) {
            double[] start = new double[world.plantCount()];
            for (int p = 0; p < start.length; p++) {
                start[p] = Meadows.deviation(sim, p);
            }
            Meadows.run(sim, Meadows.overview(), 1);
            for (int p = 0; p < world.plantCount(); p++) {
                assertTrue(sim.inspect().plantVisible(p));
                assertEquals(2.5, sim.inspect().windX(p), 1e-6);
                assertTrue(Meadows.deviation(sim, p) > 1e-3, "plant " + p + " at (" + world.plantX(p) + ", "
                        + world.plantZ(p) + ") bends in the wind");
                assertEquals(start[p], Meadows.deviation(sim, p), 1e-5 * start[p], "plant " + p + " starts at the "
                        + "equilibrium of its steady wind and stays there");
            }
        }
    }
}
