package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import org.jecosys.anim.AnimationMode;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.wind.AbstractWindSource;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;
import org.joml.Vector2d;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/**
 * Reliability, faults 1, 3 and 8 of the third pass: {@link Simulation#close()} from another thread
 * while a step runs never hangs the stepping thread, every call after close says the simulation is
 * closed, and a flow that cannot run is refused by the call (its id and slot never leak).
 * {@code -Djecosys.closeRace.trials=1000} runs more trials of the race.
 */
@Tag("reliability")
class SimulationReliabilityTest {
    /** Close-race trials per build (the issue asks for at least 200). */
    static final int TRIALS = Integer.getInteger("jecosys.closeRace.trials", 200);
    /** Longer than any step of the fixture by orders of magnitude: past it, a thread is hung. */
    private static final long HANG_MILLIS = 20_000;

    private static SceneDef raceScene;
    private static World raceWorld;

    /** 2,000 tufts of 25 leaves: 50,000 components, every one in view. */
    private static synchronized World raceWorld() throws Exception {
        if (raceWorld == null) {
            raceScene = SceneFiles.parse(Path.of("jecosys-core/src/test/resources/org/jecosys/sim/close-race-fixture.xml"));
            raceWorld = World.build(raceScene.simulationDef(), Path.of("scenes"), 2, Progress.NONE);
        }
        return raceWorld;
    }

    @Test
    void closeFromAnotherThreadDuringStepsNeverHangsTheSteppingThread() throws Exception {
        World world = raceWorld();
        assertTrue(world.componentCount() >= 50_000, "components: " + world.componentCount());
        ViewCamera cam = ViewCamera.of(raceScene.camera(), 0, 16.0 / 9);
        Random rnd = new Random(29);
        int closedMidStep = 0;
        for (int trial = 0; trial < TRIALS; trial++) {
            Simulation sim = Simulation.of(world, raceScene.simulationDef(), 2);
            assertTrue(sim.inspect().chunks() > 2, "the race needs several chunks: " + sim.inspect().chunks());
            AtomicReference<Throwable> stepperEnd = new AtomicReference<>();
            AtomicInteger stepsRun = new AtomicInteger();
            Thread stepper = new Thread(() -> {
                try {
                    while (true) {
                        stepsRun.addAndGet(sim.step(1.0 / 60, cam));
                    }
                } catch (Throwable t) {
                    stepperEnd.set(t);
                }
            }, "close-race-stepper-" + trial);
            stepper.setDaemon(true);
            stepper.start();
            // let it reach a random point: before its first step, mid-step, between steps
            long until = System.nanoTime() + rnd.nextInt(3_000_000);
            while (System.nanoTime() < until) {
                Thread.onSpinWait();
            }
            Thread closer = new Thread(sim::close, "close-race-closer-" + trial);
            closer.setDaemon(true);
            closer.start();
            closer.join(HANG_MILLIS);
            assertFalse(closer.isAlive(), "trial " + trial + ": close() hung");
            stepper.join(HANG_MILLIS);
            assertFalse(stepper.isAlive(), "trial " + trial + ": the stepping thread hung after close() ("
                    + stepsRun.get() + " steps run)");
            Throwable end = stepperEnd.get();
            assertTrue(end instanceof IllegalStateException && end.getMessage().contains("closed"),
                    "trial " + trial + ": the stepping thread ended with " + end);
            if (stepsRun.get() > 0) {
                closedMidStep++;
            }
            assertThrows(IllegalStateException.class, () -> sim.step(1.0 / 60, cam));
        }
        // most trials close while steps run: the race was really run, not only close before the first step
        assertTrue(closedMidStep > TRIALS / 2, "trials that closed a running loop: " + closedMidStep + " of " + TRIALS);
    }

    @Test
    void workerPoolClosedDuringAwaitStillCompletesTheStep() throws Exception {
        for (int trial = 0; trial < TRIALS; trial++) {
            AtomicInteger ran = new AtomicInteger();
            int chunks = 64;
            WorkerPool pool = new WorkerPool("pool-race", 3, chunks, (c, worker) -> {
                long until = System.nanoTime() + 20_000;
                while (System.nanoTime() < until) {
                    Thread.onSpinWait();
                }
                ran.incrementAndGet();
            });
            Thread closer = new Thread(pool::close);
            closer.setDaemon(true);
            Thread owner = new Thread(() -> {
                pool.start(false);
                closer.start(); // while the owner and the workers run chunks
                pool.await();
            });
            owner.setDaemon(true);
            owner.start();
            owner.join(HANG_MILLIS);
            assertFalse(owner.isAlive(), "trial " + trial + ": await() hung after close()");
            closer.join(HANG_MILLIS);
            assertFalse(closer.isAlive(), "trial " + trial + ": close() hung");
            assertEquals(chunks, ran.get(), "trial " + trial + ": every chunk of the step ran exactly once");
            assertThrows(IllegalStateException.class, () -> pool.start(false));
        }
    }

    @Test
    void closeFromInsideAStepOnTheSteppingThreadEndsThatStepCleanly() throws Exception {
        World world = raceWorld();
        ViewCamera cam = ViewCamera.of(raceScene.camera(), 0, 16.0 / 9);
        Simulation sim = Simulation.of(world, raceScene.simulationDef(), 2);
        sim.stepFixed(cam);
        // a game's flow that closes the simulation while the field evaluates it (mid-step, stepping thread)
        sim.addFlow(new AbstractWindSource("closer") {
            @Override
            protected void flow(double x, double z, double time, Vector2d dest) {
                sim.close();
                dest.set(0, 0);
            }
        });
        Thread stepper = new Thread(() -> {
            try {
                for (int i = 0; i < 5; i++) {
                    sim.stepFixed(cam);
                }
            } catch (IllegalStateException expected) {
                // the step after the one that closed
            }
        });
        stepper.start();
        stepper.join(HANG_MILLIS);
        assertFalse(stepper.isAlive(), "closing from inside a step hung it");
        assertThrows(IllegalStateException.class, () -> sim.stepFixed(cam));
    }

    @Test
    void everyCallAfterCloseThrowsSayingTheSimulationIsClosed() throws Exception {
        Simulation sim = SimFixtures.c1(2);
        ViewCamera cam = SimFixtures.camera();
        sim.stepFixed(cam);
        WindSource breeze = sim.inspect().windField().get(0);
        sim.close();
        sim.close(); // idempotent
        List<Executable> calls = new ArrayList<>();
        calls.add(() -> sim.step(0.1, cam));
        calls.add(() -> sim.stepFixed(cam));
        calls.add(() -> sim.addFlow(FlowDef.point("late", FlowKind.SOURCE, 0, 0, 1)));
        calls.add(() -> sim.addFlow(WindSource.of(FlowDef.point("late2", FlowKind.SOURCE, 0, 0, 1))));
        calls.add(() -> sim.attachAgent(FlowDef.point("agent", FlowKind.SOURCE, 0, 0, 1)));
        calls.add(() -> sim.removeFlow(breeze));
        calls.add(() -> sim.moveAgent(breeze, 1, 1));
        calls.add(() -> sim.blast("boom", 0, 0, 10, 0.5));
        calls.add(() -> sim.setFlowEnabled(breeze, false));
        calls.add(() -> sim.setMode(AnimationMode.STATIC));
        calls.add(() -> sim.setFieldEnabled(false));
        calls.add(() -> sim.setLodTransition(1));
        calls.add(() -> sim.setThinning(1, 2, 0.5));
        calls.add(() -> sim.setLodDistances(0, new double[] {5, 8}));
        calls.add(() -> sim.setLodScale(2));
        for (int i = 0; i < calls.size(); i++) {
            IllegalStateException e = assertThrows(IllegalStateException.class, calls.get(i), "call " + i);
            assertEquals("the simulation is closed", e.getMessage(), "call " + i);
        }
        assertEquals(0, sim.inspect().pendingCommands(), "nothing was queued after close");
    }

    @Test
    void aBlastThatWouldNeverEndIsRefusedByTheCallAndNoSlotLeaks() throws Exception {
        try (Simulation sim = SimFixtures.c1(1)) {
            ViewCamera cam = SimFixtures.camera();
            int flows = sim.inspect().flowCount();
            double[] bad = {Double.POSITIVE_INFINITY, Double.NaN, Double.NEGATIVE_INFINITY, 0, -1, 2e9};
            for (int i = 0; i < 2 * Simulation.MAX_FLOWS; i++) {
                double d = bad[i % bad.length];
                IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                        () -> sim.blast("b", 0, 10, 50, d), "duration " + d);
                assertTrue(e.getMessage().contains("duration"), e.getMessage());
            }
            double[] badValues = {Double.NaN, Double.POSITIVE_INFINITY};
            for (double v : badValues) {
                assertThrows(IllegalArgumentException.class, () -> sim.blast("s", 0, 10, v, 0.5));
                assertThrows(IllegalArgumentException.class, () -> sim.blast("x", v, 10, 50, 0.5));
                assertThrows(IllegalArgumentException.class, () -> sim.addFlow(
                        FlowDef.builder("late", FlowKind.UNIFORM).strength(1).start(v).build()));
                assertThrows(IllegalArgumentException.class, () -> sim.addFlow(
                        FlowDef.builder("nan", FlowKind.GUST).strength(1).noiseFrequency(v).build()));
            }
            assertEquals(flows, sim.inspect().flowCount(), "refused calls hold no slot");
            sim.stepFixed(cam);
            assertEquals(flows, sim.inspect().windField().size(), "and reached no step");
            // a blast that ends frees its slot; 2 x MAX_FLOWS of them never exhaust the slots
            for (int i = 0; i < 2 * Simulation.MAX_FLOWS; i++) {
                sim.blast("ok" + i, 0, 10, 50, 0.01);
                if (i % 200 == 199) {
                    for (int s = 0; s < 5; s++) {
                        sim.stepFixed(cam);
                    }
                }
            }
            for (int s = 0; s < 5; s++) {
                sim.stepFixed(cam);
            }
            assertEquals(flows, sim.inspect().flowCount(), "every expired blast freed its slot");
        }
    }

    @Test
    void aCommandThatFailsInTheStepFreesItsFlowId() throws Exception {
        try (Simulation sim = SimFixtures.c1(1)) {
            ViewCamera cam = SimFixtures.camera();
            int flows = sim.inspect().flowCount();
            // a flow already in the wind field under the same id, added behind the command queue's back
            sim.inspect().windField().add(FlowDef.point("twin", FlowKind.SOURCE, 0, 0, 1));
            sim.addFlow(FlowDef.point("twin", FlowKind.SINK, 1, 1, 1)); // the call cannot see it
            assertEquals(flows + 1, sim.inspect().flowCount());
            try {
                sim.stepFixed(cam);
                fail("the step adds a duplicate id");
            } catch (IllegalArgumentException expected) {
                assertTrue(expected.getMessage().contains("'twin'"), expected.getMessage());
            }
            assertEquals(flows, sim.inspect().flowCount(), "the failed command freed its reservation");
            sim.stepFixed(cam);
        }
    }
}
