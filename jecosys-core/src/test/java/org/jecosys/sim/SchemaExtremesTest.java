package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.anim.AnimationView;
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
 * Every value the scene schema accepts gives finite winds, deviations, velocities, poses and azimuths:
 * the flows at their strongest (1e6 m/s, 1e6 m^2/s with the smallest core radius, the wildest gusts),
 * components at each end of every range (stiffness 1e-9 and 1e6 N/m, dragArea 0 and 10 m^2, response
 * time 1e-3 and 10 s, length 1e-6 and 10 m, maxBend 1e-3 rad and 90 degrees), the largest variation
 * between plants, and the shortest and longest fixed steps with 64 and 1 sub-intervals. (Before the
 * bend was bounded, 1e6 m/s on dragArea 10 and stiffness 1e-7 gave |D| = 6e19 m and a NaN bend.)
 */
class SchemaExtremesTest {
    static SpeciesDef species(String id, double length, double stiffness, double dragArea, double tau, double mass,
                              double maxBend, int poses, int segments, VariationDef variation) {
        ComponentDef c = ComponentDef.builder("c", ComponentType.STALK).segments(segments).length(length)
                .baseWidth(Math.min(ComponentDef.MAX_WIDTH, length)).tipWidth(0).mass(mass).stiffness(stiffness).responseTime(tau)
                .dragArea(dragArea).lodSegments(segments).build();
        ComponentDef petal = ComponentDef.builder("p", ComponentType.PETAL).count(3).attachTo("c").segments(1)
                .length(length).baseWidth(Math.min(1, length)).mass(mass).stiffness(stiffness).responseTime(tau)
                .dragArea(dragArea).lodSegments(1).build();
        return SpeciesDef.builder(id).poses(poses).maxBend(maxBend).variation(variation)
                .lod(new LodDef(Double.POSITIVE_INFINITY, Primitive.TRIANGLES)).component(c).component(petal).build();
    }

    static SimulationDef def(double fixedStep, int subIntervals) {
        VariationDef most = VariationDef.builder().variants(4).length(0.9).width(0.9).curvature(0.9)
                .tilt(Math.toRadians(45)).responseTime(0.9).stiffness(0.9).build();
        double minBend = Math.toRadians(SpeciesDef.MIN_MAX_BEND_DEGREES);
        double maxBend = Math.toRadians(SpeciesDef.MAX_MAX_BEND_DEGREES);
        List<SpeciesDef> species = List.of(
                species("soft", ComponentDef.MAX_LENGTH, ComponentDef.MIN_STIFFNESS, ComponentDef.MAX_DRAG_AREA,
                        ComponentDef.MAX_RESPONSE_TIME, ComponentDef.MAX_MASS, maxBend, SpeciesDef.MAX_POSES,
                        ComponentDef.MAX_SEGMENTS, most),
                species("stiff", ComponentDef.MIN_LENGTH, ComponentDef.MAX_STIFFNESS, 0, ComponentDef.MIN_RESPONSE_TIME,
                        ComponentDef.MIN_MASS, minBend, 2, 1, VariationDef.NONE),
                species("quick", 0.4, ComponentDef.MIN_STIFFNESS, ComponentDef.MAX_DRAG_AREA,
                        ComponentDef.MIN_RESPONSE_TIME, ComponentDef.MIN_MASS, minBend, 16, 4, most),
                species("slow", 0.4, 1e-7, ComponentDef.MAX_DRAG_AREA, ComponentDef.MAX_RESPONSE_TIME,
                        ComponentDef.MIN_MASS, 1.2, 16, 4, VariationDef.NONE));
        List<PlacementDef> plants = new ArrayList<>();
        for (int i = 0; i < 24; i++) {
            plants.add(new PlacementDef(species.get(i % 4).id(), -18 + 1.5 * i, (i % 5) * 3 - 6, 0.25 * i));
        }
        plants.add(new PlacementDef("quick", 3, 3, 0)); // on the vortex's centre
        plants.add(new PlacementDef("soft", -3, 0.0005, 0)); // inside the source's core
        double fmax = FlowDef.MAX_STRENGTH;
        List<FlowDef> flows = List.of(
                FlowDef.builder("u", FlowKind.UNIFORM).strength(fmax).direction(Math.toRadians(360)).build(),
                FlowDef.builder("g", FlowKind.GUST).strength(fmax).gustStrength(FlowDef.MAX_GUST_STRENGTH)
                        .turbulence(FlowDef.MAX_TURBULENCE).noiseScale(FlowDef.MIN_NOISE_SCALE)
                        .noiseFrequency(FlowDef.MAX_NOISE_FREQUENCY).seed(Long.MIN_VALUE).build(),
                FlowDef.builder("v", FlowKind.VORTEX).centre(3, 3).strength(-fmax).coreRadius(FlowDef.MIN_CORE_RADIUS)
                        .build(),
                FlowDef.builder("s", FlowKind.SOURCE).centre(-3, 0).strength(fmax).coreRadius(FlowDef.MIN_CORE_RADIUS)
                        .build(),
                FlowDef.builder("k", FlowKind.SINK).centre(10, -5).strength(fmax).coreRadius(FlowDef.MIN_CORE_RADIUS)
                        .start(2 * fixedStep).duration(3 * fixedStep).build(),
                FlowDef.builder("b", FlowKind.BLAST).centre(0, 0).strength(fmax).coreRadius(FlowDef.MIN_CORE_RADIUS)
                        .start(fixedStep).duration(5 * fixedStep).build());
        return new SimulationDef(TerrainDef.flat(), species, List.of(), plants, flows,
                ForceFieldDef.builder().maxObjectsPerNode(1).lodDistances(5.0).build(),
                new AnimationDef(AnimationMode.CONSTRAINT, fixedStep, 8, subIntervals, 2, 1), 11);
    }

    static void assertFinite(Simulation sim, String what) {
        AnimationView s = sim.inspect().state();
        for (int p = 0; p < sim.plantCount(); p++) {
            assertTrue(Float.isFinite(sim.inspect().windX(p)) && Float.isFinite(sim.inspect().windZ(p)),
                    what + ": wind of plant " + p);
        }
        for (int c = 0; c < sim.componentCount(); c++) {
            float pose = s.poseCoordinate(c);
            int k = s.kind(c);
            String at = what + ", component " + c;
            assertTrue(Float.isFinite(s.deviationX(c)) && Float.isFinite(s.deviationZ(c)), at + ": deviation");
            assertTrue(Math.hypot(s.deviationX(c), s.deviationZ(c)) <= 1.00001 * s.kinds().bendLimit(k),
                    at + ": |D| within the bend limit (to float rounding)");
            assertTrue(Float.isFinite(s.velocityX(c)) && Float.isFinite(s.velocityZ(c)), at + ": velocity");
            assertTrue(pose >= 0 && pose <= s.kinds().poseMax(k), at + ": pose " + pose);
            assertTrue(Float.isFinite(s.azimuth(c)) && Math.abs(s.azimuth(c)) <= Math.PI + 1e-6, at + ": azimuth");
            assertTrue(Float.isFinite(sim.latestFrame().poseCoord(c)), at + ": frame");
        }
    }

    @Test
    void theSchemasExtremesGiveFiniteValuesEverywhere() throws Exception {
        double[] steps = {1e-5, 1.0 / 60, 1};
        int[] subs = {64, 4, 1};
        for (int r = 0; r < steps.length; r++) {
            try (Simulation sim = Simulation.create(def(steps[r], subs[r]), Path.of("."), 2, Progress.NONE)) {
                String what = "step " + steps[r] + " s, " + subs[r] + " sub-intervals";
                assertFinite(sim, what + ", before the first step");
                ViewCamera cam = new ViewCamera();
                cam.setPosition(0, 30, 30);
                cam.setOrientation(0, -0.8);
                for (int i = 0; i < 40; i++) {
                    cam.setOrientation(0.05 * i, -0.8); // plants leave and enter the view
                    sim.stepFixed(cam);
                    assertFinite(sim, what + ", step " + i);
                }
            }
        }
    }
}
