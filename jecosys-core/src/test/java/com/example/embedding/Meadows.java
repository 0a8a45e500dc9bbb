package com.example.embedding;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.anim.AnimationView;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.ComponentType;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.plant.SpeciesLibrary;
import org.jecosys.plant.VariationDef;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.SimulationDef;
import org.jecosys.sim.World;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.terrain.PlacementDef;
import org.jecosys.terrain.TerrainDef;
import org.jecosys.wind.FlowDef;

/**
 * A small meadow built in code, as a game outside the library would build it: only public API, the
 * Def builders, no scene file. The terrain is {@link TerrainDef#flat()}: 40 m by 40 m, centred on the
 * origin, at height 0.
 */
final class Meadows {
    static final String SPECIES = "tuft";

    private Meadows() {
    }

    /** A grass tuft of 5 leaves, two shape variants, the paper's three levels of detail. */
    static SpeciesDef tuft() {
        ComponentDef leaf = ComponentDef.builder("leaf", ComponentType.LEAF).count(5).segments(4).length(0.4)
                .baseWidth(0.006).tipWidth(0.0015).curvature(0.3).tilt(0.25).mass(4e-4).stiffness(0.2)
                .dragArea(0.002).lodSegments(4, 2, 2).build();
        return SpeciesDef.builder(SPECIES).name("tuft").maxBend(1.2).lods(SpeciesLibrary.table3Lods())
                .variation(VariationDef.builder().variants(2).length(0.1).width(0.1).curvature(0.2).tilt(0.1).build())
                        .component(leaf).build();
    }

    /**
     * The def: the tuft, hand placements, flows, 60 Hz, two animation workers, and a force field fine
     * enough that every plant has its own leaf and no distance LOD (the wind is then evaluated at each
     * plant, paper §3: a coarser tree evaluates it at the centroid of the plants of a node).
     */
    static SimulationDef def(List<PlacementDef> placements, List<DistributionDef> distributions, List<FlowDef> flows) {
        return new SimulationDef(TerrainDef.flat(), List.of(tuft()), distributions, placements, flows,
                ForceFieldDef.builder().maxObjectsPerNode(1).maxDepth(10).lodDistances().build(),
                new AnimationDef(AnimationMode.CONSTRAINT, 1.0 / 60, 8, 4, 2, 1), 7);
    }

    /** Tufts placed by hand at (x, z) pairs. */
    static List<PlacementDef> at(double... xz) {
        PlacementDef[] out = new PlacementDef[xz.length / 2];
        for (int i = 0; i < out.length; i++) {
            out[i] = new PlacementDef(SPECIES, xz[2 * i], xz[2 * i + 1], 0.3 * i);
        }
        return List.of(out);
    }

    static World world(SimulationDef def) throws IOException {
        return World.build(def, Path.of("."), 1, Progress.NONE);
    }

    /** High above the south edge, looking down over the whole terrain. */
    static ViewCamera overview() {
        ViewCamera camera = new ViewCamera();
        camera.setPosition(0, 30, 38);
        camera.setOrientation(0, -0.75);
        return camera;
    }

    /** The world plant standing nearest (x, z) (the world orders plants spatially, not as placed). */
    static int plantAt(World w, double x, double z) {
        int best = -1;
        double bestD = Double.POSITIVE_INFINITY;
        for (int p = 0; p < w.plantCount(); p++) {
            double d = Math.hypot(w.plantX(p) - x, w.plantZ(p) - z);
            if (d < bestD) {
                bestD = d;
                best = p;
            }
        }
        return best;
    }

    /** The largest deviation magnitude (metres) of plant p's components. */
    static double deviation(Simulation sim, int p) {
        AnimationView s = sim.inspect().state();
        double max = 0;
        for (int c = s.firstComponent(p); c < s.firstComponent(p + 1); c++) {
            max = Math.max(max, Math.hypot(s.deviationX(c), s.deviationZ(c)));
        }
        return max;
    }

    /** Steps {@code seconds} of game time in 60 Hz frames. */
    static void run(Simulation sim, ViewCamera camera, double seconds) {
        for (int i = 0; i < Math.round(seconds * 60); i++) {
            sim.step(1.0 / 60, camera);
        }
    }
}
