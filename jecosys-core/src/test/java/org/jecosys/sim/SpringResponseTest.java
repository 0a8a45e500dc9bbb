package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.field.DragLaw;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.ComponentType;
import org.jecosys.plant.LodDef;
import org.jecosys.plant.Primitive;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.terrain.PlacementDef;
import org.jecosys.terrain.TerrainDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.junit.jupiter.api.Test;

/**
 * The spring in a running simulation is exact at every step size (paper eq. 5 integrated in closed
 * form, {@code SpringKinds}): one plant of one component in a uniform wind of known force, stepped at
 * 30, 60 and 144 Hz. A flow that switches on at t = 1 s gives {@code |D| = D (1 - (1 + s/tau) e^(-s/tau))}
 * (s the time since the switch) and one that switches off releases the plant along
 * {@code D (1 + s/tau) e^(-s/tau)}, within 0.5% of the closed form at s = tau, 2 tau and 5 tau and
 * within 0.5% of each other; a steady wind starts and stays at its equilibrium, also for a plant that
 * comes into view later; a switch inside a step takes effect at the next sub-interval boundary.
 */
class SpringResponseTest {
    static final double[] STEPS = {1.0 / 30, 1.0 / 60, 1.0 / 144};
    /** Response time, s: tau, 2 tau and 5 tau after t = 1 s fall on step boundaries at all three rates. */
    static final double TAU = 0.5;
    static final double STIFFNESS = 0.5;
    static final double DRAG_AREA = 0.002;
    static final double SPEED = 4.5;
    /** The equilibrium deviation of the wind, metres (below the knee of the bend limit). */
    static final double D_INF = 0.5 * DragLaw.AIR_DENSITY * DRAG_AREA * SPEED * SPEED / STIFFNESS;
    static final double TOLERANCE = 0.005;

    static SimulationDef def(double dt, List<FlowDef> flows) {
        return def(dt, flows, List.of(new PlacementDef("one", 0, 0, 0)));
    }

    static SimulationDef def(double dt, List<FlowDef> flows, List<PlacementDef> plants) {
        ComponentDef stalk = ComponentDef.builder("stalk", ComponentType.STALK).segments(4).length(0.4)
                .baseWidth(0.004).mass(0.003).stiffness(STIFFNESS).responseTime(TAU).dragArea(DRAG_AREA)
                .lodSegments(4).build();
        SpeciesDef one = SpeciesDef.builder("one").maxBend(1.2)
                .lod(new LodDef(Double.POSITIVE_INFINITY, Primitive.TRIANGLES)).component(stalk).build();
        return new SimulationDef(TerrainDef.flat(), List.of(one), List.of(), plants, flows, ForceFieldDef.builder()
                .maxObjectsPerNode(1).maxDepth(4).lodDistances().build(), new AnimationDef(AnimationMode.CONSTRAINT,
                dt, 8, 4, 1,
                1), 3);
    }

    /** A uniform wind along +X of {@link #SPEED} between {@code start} and {@code start + duration}. */
    static FlowDef wind(double start, double duration) {
        return FlowDef.builder("wind", FlowKind.UNIFORM).strength(SPEED).start(start).duration(duration).build();
    }

    static Simulation simulation(SimulationDef def) throws Exception {
        return Simulation.create(def, Path.of("."), 1, Progress.NONE);
    }

    /** Looking at the plant from 5 m. */
    static ViewCamera camera() {
        ViewCamera camera = new ViewCamera();
        camera.setPosition(0, 1.7, 5);
        camera.setOrientation(0, -0.3);
        return camera;
    }

    static double deviation(Simulation sim) {
        return Math.hypot(sim.inspect().state().deviationX(0), sim.inspect().state().deviationZ(0));
    }

    /** |D| at times {@code at} (seconds, multiples of every step), stepping at dt. */
    static double[] run(double dt, List<FlowDef> flows, double[] at) throws Exception {
        double[] out = new double[at.length];
        try (Simulation sim = simulation(def(dt, flows))) {
            ViewCamera cam = camera();
            long steps = 0;
            for (int i = 0; i < at.length; i++) {
                long until = Math.round(at[i] / dt);
                while (steps < until) {
                    sim.stepFixed(cam);
                    steps++;
                }
                out[i] = deviation(sim);
            }
        }
        return out;
    }

    static void assertClosedForm(double[][] got, double[] want, String what) {
        for (int i = 0; i < want.length; i++) {
            for (int r = 0; r < STEPS.length; r++) {
                assertEquals(want[i], got[r][i], TOLERANCE * want[i], what + " at sample " + i + ", dt = " + STEPS[r]);
                for (int q = 0; q < r; q++) {
                    assertEquals(got[q][i], got[r][i], TOLERANCE * got[q][i], what + ": dt " + STEPS[q] + " vs "
                            + STEPS[r] + " at sample " + i);
                }
            }
        }
    }

    @Test
    void aFlowSwitchedOnAtOneSecondGivesTheClosedFormAtEveryStepSize() throws Exception {
        double[] s = {TAU, 2 * TAU, 5 * TAU};
        double[] at = new double[s.length + 1];
        double[] want = new double[s.length + 1];
        at[0] = 1;
        want[0] = 0;
        for (int i = 0; i < s.length; i++) {
            at[i + 1] = 1 + s[i];
            want[i + 1] = D_INF * (1 - (1 + s[i] / TAU) * Math.exp(-s[i] / TAU));
        }
        double[][] got = new double[STEPS.length][];
        for (int r = 0; r < STEPS.length; r++) {
            got[r] = run(STEPS[r], List.of(wind(1, Double.POSITIVE_INFINITY)), at);
            assertEquals(0, got[r][0], 0, "nothing moves before the flow starts");
        }
        assertClosedForm(new double[][] {slice(got[0]), slice(got[1]), slice(got[2])}, slice(want), "switched on");
    }

    @Test
    void aFlowSwitchedOffReleasesThePlantAlongTheClosedForm() throws Exception {
        double[] s = {TAU, 2 * TAU, 5 * TAU};
        double[] at = new double[s.length + 1];
        double[] want = new double[s.length + 1];
        at[0] = 2;
        want[0] = D_INF;
        for (int i = 0; i < s.length; i++) {
            at[i + 1] = 2 + s[i];
            want[i + 1] = D_INF * (1 + s[i] / TAU) * Math.exp(-s[i] / TAU);
        }
        double[][] got = new double[STEPS.length][];
        for (int r = 0; r < STEPS.length; r++) {
            got[r] = run(STEPS[r], List.of(wind(0, 2)), at);
        }
        assertClosedForm(got, want, "released");
    }

    @Test
    void aSteadyWindStartsAndStaysAtItsEquilibriumAtEveryStepSize() throws Exception {
        double[] at = {STEPS[0], 0.5, TAU, 2 * TAU, 5 * TAU};
        for (double dt : STEPS) {
            double[] got = run(dt, List.of(wind(0, Double.POSITIVE_INFINITY)), at);
            for (int i = 0; i < at.length; i++) {
                assertEquals(D_INF, got[i], TOLERANCE * D_INF, "no lean-in from upright: t = " + at[i] + ", dt = " + dt);
            }
        }
    }

    @Test
    void aPlantComingIntoViewIsAlreadyAtTheEquilibriumOfTheWind() throws Exception {
        // the plant at (5, 5) and another far away, so that the camera at (5, -5) is in another node;
        // the wind rises at 0.5 s while the camera looks away, and at 1 s it turns to the plant
        List<PlacementDef> plants = List.of(new PlacementDef("one", 5, 5, 0), new PlacementDef("one", -15, -15, 0));
        try (Simulation sim = simulation(def(1.0 / 60, List.of(wind(0.5, Double.POSITIVE_INFINITY)), plants))) {
            int p = sim.world().plantX(0) > 0 ? 0 : 1;
            ViewCamera away = new ViewCamera();
            away.setPosition(5, 1.7, -5);
            away.setOrientation(0, 0);
            for (int i = 0; i < 60; i++) {
                sim.stepFixed(away);
                assertTrue(!sim.inspect().plantVisible(p), "behind the camera");
            }
            assertEquals(0, deviationOf(sim, p), 0, "the plant was last animated in no wind");
            ViewCamera toward = new ViewCamera();
            toward.setPosition(5, 1.7, -5);
            toward.setOrientation(Math.PI, 0);
            int seen = -1;
            for (int i = 0; i < 10; i++) {
                sim.stepFixed(toward);
                if (sim.inspect().plantVisible(p) && seen < 0) {
                    seen = i;
                    assertEquals(D_INF, deviationOf(sim, p), TOLERANCE * D_INF, "first step in view: no lean-in");
                }
            }
            assertTrue(seen >= 0, "the plant came into view");
            assertEquals(D_INF, deviationOf(sim, p), TOLERANCE * D_INF);
        }
    }

    static double deviationOf(Simulation sim, int p) {
        int c = sim.world().firstComponent(p);
        return Math.hypot(sim.inspect().state().deviationX(c), sim.inspect().state().deviationZ(c));
    }

    @Test
    void aSwitchInsideAStepTakesEffectAtTheNextSubIntervalBoundary() throws Exception {
        double dt = 1.0 / 30;
        double start = 1.005; // sub-intervals of 1/120 s: boundaries at 1, 1.00833..., so the switch is at 121/120 s
        double switched = 121.0 / 120;
        double[] at = {1 + 10 * dt, 1 + 15 * dt, 1 + 75 * dt};
        double[] got = run(dt, List.of(wind(start, Double.POSITIVE_INFINITY)), at);
        for (int i = 0; i < at.length; i++) {
            double s = at[i] - switched;
            double want = D_INF * (1 - (1 + s / TAU) * Math.exp(-s / TAU));
            assertEquals(want, got[i], 1e-3 * want, "t = " + at[i]);
        }
    }

    private static double[] slice(double[] a) {
        return java.util.Arrays.copyOfRange(a, 1, a.length);
    }
}
