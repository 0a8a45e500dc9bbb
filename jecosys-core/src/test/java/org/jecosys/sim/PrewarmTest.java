package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.anim.AnimationDef;
import org.jecosys.math.ViewCamera;
import org.junit.jupiter.api.Test;

/**
 * {@code <animation prewarm>}: the first step runs the prewarm's fixed steps first, so a prewarmed
 * simulation is, step for step, the plain one that many steps later, for any number of workers; the
 * first step's return value and maxSubSteps count only the caller's steps; an out-of-range prewarm is
 * refused naming the attribute.
 */
class PrewarmTest {
    private static final double PREWARM = 0.5;

    private static Simulation prewarmed(int workers) throws Exception {
        SimulationDef d = SimFixtures.scene().simulationDef();
        SimulationDef p = new SimulationDef(d.terrain(), d.species(), d.distributions(), d.placements(), d.flows(),
                d.field(), d.animation().withPrewarm(PREWARM), d.seed());
        return Simulation.of(SimFixtures.world(), p, workers, SimFixtures.CHUNK);
    }

    @Test
    void aPrewarmedSimulationIsThePlainOneThatManyStepsLaterWhateverTheWorkers() throws Exception {
        ViewCamera cam = SimFixtures.camera();
        int n = SimFixtures.scene().simulationDef().animation().withPrewarm(PREWARM).prewarmSteps();
        assertEquals(30, n, "0.5 s at 60 Hz");
        long plain;
        long atStart;
        try (Simulation sim = SimFixtures.c1(2)) {
            sim.stepFixed(cam);
            atStart = sim.inspect().stateHash();
            for (int i = 1; i < n + 10; i++) {
                sim.stepFixed(cam);
            }
            plain = sim.inspect().stateHash();
        }
        for (int w : new int[] {1, 2, 3}) {
            try (Simulation sim = prewarmed(w)) {
                double dt = sim.def().animation().fixedStep();
                int ran = sim.step(3 * dt + 1e-9, cam);
                assertEquals(3, ran, "the first step reports the caller's steps only");
                Frame f = sim.latestFrame();
                assertEquals(n + 3, f.number(), "prewarm and the caller's steps are published");
                assertEquals((n + 3) * dt, f.time(), 1e-9, "the clock includes the prewarm");
                for (int i = 3; i < 10; i++) {
                    sim.stepFixed(cam);
                }
                long hash = sim.inspect().stateHash();
                assertEquals(String.format("%016x", plain), String.format("%016x", hash), w + " workers");
                assertNotEquals(atStart, hash, "the plants moved");
            }
        }
    }

    @Test
    void theFirstStepsOfAPrewarmedSimulationMoveAsMuchAsLaterOnes() throws Exception {
        // C1's wind is steady: the plants start at its equilibrium, so without a prewarm they start still;
        // the prewarm runs on the first call however small dt is
        ViewCamera cam = SimFixtures.camera();
        try (Simulation sim = prewarmed(2)) {
            assertEquals(0, sim.step(0, cam), "no step of the caller's own");
            assertEquals(30, sim.latestFrame().number(), "but the prewarm ran");
            assertEquals(0, sim.step(0, cam));
            assertEquals(30, sim.latestFrame().number(), "and only once");
        }
    }

    @Test
    void aFirstCallThatThrowsLeavesThePrewarmForTheNext() throws Exception {
        ViewCamera cam = SimFixtures.camera();
        UserCodeReliabilityTest.LooseCamera bad = new UserCodeReliabilityTest.LooseCamera(SimFixtures.camera());
        bad.badEye = true;
        bad.x = Double.NaN; // a game's own camera, its eye not finite
        try (Simulation sim = prewarmed(2)) {
            assertThrows(IllegalArgumentException.class, () -> sim.stepFixed(bad), "a camera that is not finite");
            sim.stepFixed(cam);
            assertEquals(31, sim.latestFrame().number(), "the whole prewarm, then the caller's step");
        }
    }

    @Test
    void anOutOfRangePrewarmIsRefusedByName() {
        AnimationDef a = AnimationDef.defaults();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> a.withPrewarm(-1));
        assertTrue(e.getMessage().contains("prewarm"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> a.withPrewarm(AnimationDef.MAX_PREWARM + 1));
        assertTrue(e.getMessage().contains("prewarm"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> a.withPrewarm(Double.NaN));
        assertTrue(e.getMessage().contains("prewarm"), e.getMessage());
        assertEquals(0, a.prewarm(), "no prewarm by default");
        AnimationDef random = a.withPrewarm(0.5).withMode(org.jecosys.anim.AnimationMode.RANDOM);
        assertEquals(0.5, random.prewarm(), "another mode keeps the prewarm");
        assertEquals(org.jecosys.anim.AnimationMode.RANDOM, random.mode());
    }
}
