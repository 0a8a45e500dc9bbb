package org.jecosys.bench;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.Progress;
import org.jecosys.plant.PlantModel;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.World;
import org.jecosys.terrain.CompetitiveDistributor;
import org.jecosys.terrain.PlantLayout;
import org.jecosys.terrain.Terrain;

/**
 * Pre-computation costs (paper section 4.1 and 4.3): pose tables of every species in the shipped
 * scenes, and the terrain and competitive distribution of scenes/large.xml (40,000 tufts, 1M
 * components) with 1 and 2 threads.
 */
final class PrecomputeSection implements Section {
    private final Path scenes;

    PrecomputeSection(Path scenes) {
        this.scenes = scenes;
    }

    @Override
    public String name() {
        return "pre-computation (pose tables, distribution)";
    }

    @Override
    public void run(Mode mode, Report report) throws Exception {
        int runs = mode == Mode.SMOKE ? 2 : mode == Mode.QUICK ? 7 : 15;
        List<SpeciesDef> all = new ArrayList<>();
        for (String f : new String[] {"c1.xml", "rose.xml", "meadow.xml"}) {
            for (SpeciesDef s : SceneFiles.parse(scenes.resolve(f)).species()) {
                if (all.stream().noneMatch(o -> o.equals(s))) {
                    all.add(s);
                }
            }
        }
        double[] poseMs = new double[runs];
        for (int r = 0; r < runs; r++) {
            poseMs[r] = PlantModel.build(all, 1, org.jecosys.plant.GravityBend.EARTH_GRAVITY, Progress.NONE)
                    .buildMillis();
        }
        Table t = new Table("precompute", "Pre-computation",
                List.of("what", "size", "threads", "median ms", "target ms"));
        t.row("pose tables, meshes and variants of every species in scenes/", all.size() + " species", 1,
                Stats.median(poseMs), 200.0);
        String big = mode == Mode.SMOKE ? "c1.xml" : "large.xml";
        SceneDef scene = SceneFiles.parse(scenes.resolve(big));
        Terrain terrain = Terrain.build(scene.terrain(), scenes, 2, Progress.NONE);
        List<String> ids = new ArrayList<>();
        for (SpeciesDef s : scene.species()) {
            ids.add(s.id());
        }
        for (int threads = 1; threads <= 2; threads++) {
            double[] ms = new double[Math.max(2, runs / 2)];
            int placed = 0;
            for (int r = 0; r < ms.length; r++) {
                long t0 = System.nanoTime();
                PlantLayout layout = new CompetitiveDistributor().distribute(terrain, ids, scene.distributions(),
                        scene.placements(), scene.seed(), threads, Progress.NONE);
                ms[r] = (System.nanoTime() - t0) / 1e6;
                placed = layout.count();
            }
            t.row("competitive distribution of scenes/" + big, placed + " plants", threads, Stats.median(ms),
                    3000.0);
        }
        long t0 = System.nanoTime();
        World world = World.build(scene.simulationDef(), scenes, 2, Progress.NONE);
        t.row("whole world of scenes/" + big + " (terrain, species, distribution)",
                world.componentCount() + " components", 2, (System.nanoTime() - t0) / 1e6, null);
        report.add(t.note("Targets from the issues: all pose tables under 200 ms; about 40,000 tufts (1M components) "
                + "distributed in at most 3 s."));
    }
}
