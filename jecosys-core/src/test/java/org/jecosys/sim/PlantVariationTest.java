package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.ComponentType;
import org.jecosys.plant.LodDef;
import org.jecosys.plant.Primitive;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.plant.VariationDef;
import org.jecosys.terrain.PlacementDef;
import org.jecosys.terrain.TerrainDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.junit.jupiter.api.Test;

/**
 * Plants of a species vary in stiffness and response time (seeded, {@link VariationDef}): in one steady
 * wind their equilibrium deviations spread by the stiffness variation, and released together they
 * come back at rates spread by the response-time variation; without variation they are identical.
 */
class PlantVariationTest {
    static final double TAU = 0.4;
    static final double STIFFNESS_VARIATION = 0.3;
    static final double RESPONSE_VARIATION = 0.5;

    static SimulationDef def(VariationDef variation) {
        ComponentDef stalk = ComponentDef.builder("stalk", ComponentType.STALK).segments(4).length(0.4)
                .baseWidth(0.004).mass(0.003).stiffness(0.5).responseTime(TAU).dragArea(0.002).lodSegments(4).build();
        SpeciesDef s = SpeciesDef.builder("s").maxBend(1.2).variation(variation)
                .lod(new LodDef(Double.POSITIVE_INFINITY, Primitive.TRIANGLES)).component(stalk).build();
        List<PlacementDef> plants = new ArrayList<>();
        for (int i = 0; i < 64; i++) {
            plants.add(new PlacementDef("s", -8 + 2 * (i % 8), -8 + 2 * (i / 8), 0));
        }
        FlowDef wind = FlowDef.builder("w", FlowKind.UNIFORM).strength(4).duration(1).build();
        return new SimulationDef(TerrainDef.flat(), List.of(s), List.of(), plants, List.of(wind),
                ForceFieldDef.builder().maxObjectsPerNode(4).maxDepth(6).lodDistances().build(),
                        new AnimationDef(AnimationMode.CONSTRAINT, 1.0 / 60, 8, 4,
                1, 1), 5);
    }

    /** Per plant: |D| in the wind (t = 1 s) and its share left one tau after the wind stops. */
    static double[][] run(VariationDef variation) throws Exception {
        try (Simulation sim = Simulation.create(def(variation), Path.of("."), 1, Progress.NONE)) {
            ViewCamera cam = new ViewCamera();
            cam.setPosition(0, 20, 12);
            cam.setOrientation(0, -1.1);
            int n = sim.plantCount();
            double[][] out = new double[2][n];
            for (int i = 0; i < 60; i++) {
                sim.stepFixed(cam);
            }
            for (int p = 0; p < n; p++) {
                assertTrue(sim.inspect().plantVisible(p));
                out[0][p] = SpringResponseTest.deviationOf(sim, p);
            }
            for (int i = 0; i < Math.round(TAU * 60); i++) {
                sim.stepFixed(cam);
            }
            for (int p = 0; p < n; p++) {
                out[1][p] = SpringResponseTest.deviationOf(sim, p) / out[0][p];
            }
            return out;
        }
    }

    static double min(double[] a) {
        return java.util.Arrays.stream(a).min().orElseThrow();
    }

    static double max(double[] a) {
        return java.util.Arrays.stream(a).max().orElseThrow();
    }

    @Test
    void stiffnessAndResponseTimeVaryFromPlantToPlantWithinTheirFractions() throws Exception {
        double[][] same = run(VariationDef.builder().variants(1).build());
        assertEquals(min(same[0]), max(same[0]), 0, "no variation: one equilibrium");
        assertEquals(min(same[1]), max(same[1]), 0, "and one release");
        double nominal = same[0][0];
        double left = same[1][0];
        assertEquals(2 * Math.exp(-1), left, 0.005, "(1 + t/tau) e^(-t/tau) at t = tau");

        double[][] varied = run(VariationDef.builder().variants(1).responseTime(RESPONSE_VARIATION)
                .stiffness(STIFFNESS_VARIATION).build());
        double lo = min(varied[0]) / nominal;
        double hi = max(varied[0]) / nominal;
        assertTrue(lo >= 1 / (1 + STIFFNESS_VARIATION) - 1e-6 && hi <= 1 / (1 - STIFFNESS_VARIATION) + 1e-6,
                "equilibria within the stiffness variation: " + lo + " .. " + hi);
        assertTrue(hi - lo > STIFFNESS_VARIATION, "and spread over it: " + lo + " .. " + hi);
        double slow = (1 + 1 / (1 + RESPONSE_VARIATION)) * Math.exp(-1 / (1 + RESPONSE_VARIATION));
        double quick = (1 + 1 / (1 - RESPONSE_VARIATION)) * Math.exp(-1 / (1 - RESPONSE_VARIATION));
        assertTrue(min(varied[1]) >= quick - 0.005 && max(varied[1]) <= slow + 0.005, "releases within the response "
                + "variation: " + min(varied[1]) + " .. " + max(varied[1]) + " in " + quick + " .. " + slow);
        assertTrue(max(varied[1]) - min(varied[1]) > 0.5 * (slow - quick), "and spread over it");
    }
}
