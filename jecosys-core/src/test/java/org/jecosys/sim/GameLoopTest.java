package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.jecosys.anim.AnimationMode;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.Scenes;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;
import org.junit.jupiter.api.Test;

/** Embeds the simulation in a game loop as the package documentation shows. */
class GameLoopTest {
    @Test
    void aGameLoopStepsMovesAnAgentSwitchesModesAndCloses() throws Exception {
        long[] workers;
        try (Simulation sim = Scenes.simulation(Path.of("scenes/c1.xml"), Progress.NONE)) {
            workers = sim.inspect().workerThreadIds();
            ViewCamera camera = new ViewCamera();
            camera.setPosition(0, 2, 14);
            camera.setOrientation(0, -0.2);
            WindSource player = sim.attachAgent(FlowDef.point("player", FlowKind.SOURCE, 0, 10, 4));
            long lastFrame = -1;
            int fixedSteps = 0;
            double now = 0;
            for (int tick = 0; tick < 240; tick++) {
                double frameTime = tick % 7 == 0 ? 0.031 : 0.009; // an uneven game frame rate
                now += frameTime;
                double px = 4 * Math.sin(now);
                sim.moveAgent(player, px, 8);
                camera.setPosition(0, 2, 14 - 0.02 * tick);
                fixedSteps += sim.step(frameTime, camera);
                Frame f = sim.latestFrame();
                assertTrue(f.number() >= lastFrame);
                lastFrame = f.number();
                if (tick == 80) {
                    sim.setMode(AnimationMode.RANDOM);
                }
                if (tick == 120) {
                    sim.setMode(AnimationMode.CONSTRAINT);
                    sim.setFieldEnabled(false);
                }
                if (tick == 160) {
                    sim.setFieldEnabled(true);
                    sim.setLodScale(2);
                    sim.removeFlow(player);
                }
            }
            assertEquals(fixedSteps, sim.inspect().steps());
            assertEquals(sim.inspect().steps(), sim.latestFrame().number());
            // each frame (at most 0.031 s, plus less than one fixed step of backlog) makes fewer fixed
            // steps due than the cap (maxSubSteps), so none is dropped: the simulation time is the
            // steps run, and lags the real time by the accumulator's remainder, under one fixed step
            assertEquals(0, sim.inspect().droppedSteps());
            assertEquals(sim.inspect().fixedStep() * sim.inspect().steps(), sim.inspect().time(), 1e-9);
            double unsimulated = now - sim.inspect().time();
            assertTrue(unsimulated >= -1e-9 && unsimulated < sim.inspect().fixedStep(),
                    "real time " + now + " s, simulated " + sim.inspect().time() + " s, fixed step "
                            + sim.inspect().fixedStep() + " s");
            assertEquals(-1, sim.inspect().windField().indexOf("player"));
            assertTrue(sim.inspect().fieldEnabled());
            assertEquals(AnimationMode.CONSTRAINT, sim.inspect().mode());
        }
        for (long id : workers) {
            for (Thread t : Thread.getAllStackTraces().keySet()) {
                assertFalse(t.getId() == id && t.isAlive(), "worker " + id + " still alive after close");
            }
        }
    }

    @Test
    void theAccumulatorCapsSubStepsAndDropsTheBacklog() throws Exception {
        try (Simulation sim = SimFixtures.c1(1)) {
            ViewCamera cam = SimFixtures.camera();
            assertEquals(0, sim.step(0.005, cam));
            assertEquals(1, sim.step(0.012, cam));
            int max = sim.def().animation().maxSubSteps();
            assertEquals(max, sim.step(1.0, cam));
            assertTrue(sim.inspect().droppedSteps() > 0);
            assertEquals(0, sim.step(0, cam));
            assertThrows(IllegalArgumentException.class, () -> sim.step(-1, cam));
            assertThrows(IllegalArgumentException.class, () -> sim.step(Double.NaN, cam));
        }
    }

    @Test
    void windMovesTheMeadowAndTheFieldOffStopsIt() throws Exception {
        try (Simulation on = SimFixtures.c1(2); Simulation off = SimFixtures.c1(2)) {
            off.setFieldEnabled(false);
            ViewCamera cam = SimFixtures.camera();
            long rest = on.inspect().stateHash();
            for (int i = 0; i < 60; i++) {
                on.stepFixed(cam);
                off.stepFixed(cam);
            }
            assertNotEquals(rest, on.inspect().stateHash());
            for (int c = 0; c < off.componentCount(); c++) {
                assertEquals(0, off.inspect().state().deviationX(c), "no field, no wind: upright from the first step");
                assertEquals(0, off.inspect().state().deviationZ(c));
            }
            assertEquals(off.componentCount(), off.latestFrame().componentsAnimated() + notDrawn(off),
                    "with the field off every plant counts as visible");
        }
    }

    private static int notDrawn(Simulation s) {
        int n = 0;
        for (int p = 0; p < s.plantCount(); p++) {
            int bit = 1 << s.inspect().state().level(p);
            for (int c = s.world().firstComponent(p), e = c + s.world().componentsOf(p); c < e; c++) {
                n += (s.inspect().state().kinds().lodMask(s.inspect().state().kind(c)) & bit) == 0 ? 1 : 0;
            }
        }
        return n;
    }
}
