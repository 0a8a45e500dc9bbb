package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.jecosys.anim.AnimationMode;
import org.jecosys.math.ViewCamera;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;
import org.junit.jupiter.api.Test;

/**
 * Commands from other threads can never keep a step from returning: a step applies at most what was
 * queued when it began, the queue holds at most {@link Simulation#MAX_PENDING_COMMANDS} commands
 * (more are refused), and at most {@link Simulation#MAX_FLOWS} flows exist. Bounds are counted, not
 * timed: a producer counts the commands accepted since the last step returned and gives up (and
 * fails the test) past a bound only an unbounded drain can reach. Agent moves are not counted: each
 * overwrites its agent's slot, so they never pile up (and a step that the scheduler holds up for a few
 * milliseconds would otherwise see tens of thousands of them).
 */
class CommandFloodTest {
    private static final int STEPS = 60;
    private static final int PRODUCERS = 3;
    /** Accepted commands between two step returns that only a step that drains forever allows. */
    private static final long BOUND = 3L * Simulation.MAX_PENDING_COMMANDS;

    @Test
    void aFloodOfCommandsNeverKeepsAStepFromReturning() throws Exception {
        try (Simulation sim = SimFixtures.c1(2)) {
            ViewCamera cam = SimFixtures.camera();
            AtomicBoolean done = new AtomicBoolean();
            AtomicLong sinceStep = new AtomicLong();
            AtomicLong accepted = new AtomicLong();
            AtomicLong refused = new AtomicLong();
            AtomicReference<String> problem = new AtomicReference<>();
            List<Thread> producers = new ArrayList<>();
            for (int t = 0; t < PRODUCERS; t++) {
                int me = t;
                Thread p = new Thread(() -> {
                    WindSource agent = null;
                    long i = 0;
                    while (!done.get() && problem.get() == null) {
                        i++;
                        try {
                            switch ((int) (i % 5)) {
                                case 0 -> agent = sim.addFlow(FlowDef.point("p" + me + "-" + i, FlowKind.SOURCE, 1, 2, 3));
                                case 1 -> {
                                    if (agent == null) {
                                        continue; // nothing sent, nothing to count
                                    }
                                    sim.removeFlow(agent);
                                }
                                case 2 -> {
                                    if (agent == null) {
                                        continue;
                                    }
                                    sim.moveAgent(agent, i % 7, 3);
                                    // a move overwrites the agent's slot (AgentMoves): never queued, never
                                    // refused, so not a command that could pile up while a step runs
                                    accepted.incrementAndGet();
                                    continue;
                                }
                                case 3 -> sim.blast("b" + me + "-" + i, 0, 0, 50, 0.05);
                                default -> sim.setMode(i % 2 == 0 ? AnimationMode.CONSTRAINT : AnimationMode.RANDOM);
                            }
                            accepted.incrementAndGet();
                            if (sinceStep.incrementAndGet() > BOUND) {
                                problem.compareAndSet(null, "more than " + BOUND + " commands accepted while one step "
                                        + "ran: the step does not return under a flood");
                            }
                        } catch (IllegalStateException e) {
                            refused.incrementAndGet(); // back-pressure: the queue or the flows are full
                        }
                    }
                }, "producer-" + t);
                p.setDaemon(true);
                producers.add(p);
                p.start();
            }
            int maxPending = 0;
            int maxFlows = 0;
            // at least STEPS steps, and on until the producers (who may get the cores late on a loaded
            // machine) have had more than 2 x STEPS commands accepted
            long steps = 0;
            for (int s = 0; (s < STEPS || accepted.get() <= 2L * STEPS) && s < 2_000_000 && problem.get() == null; s++) {
                sim.stepFixed(cam);
                steps++;
                sinceStep.set(0);
                maxPending = Math.max(maxPending, sim.inspect().pendingCommands());
                maxFlows = Math.max(maxFlows, sim.inspect().windField().size());
            }
            done.set(true);
            for (Thread p : producers) {
                p.join();
            }
            assertNull(problem.get());
            assertEquals(steps, sim.inspect().steps());
            assertTrue(steps >= STEPS);
            assertTrue(maxPending <= Simulation.MAX_PENDING_COMMANDS, "pending " + maxPending);
            assertTrue(maxFlows <= Simulation.MAX_FLOWS, "flows " + maxFlows);
            int flows = sim.inspect().flowCount();
            assertTrue(flows <= Simulation.MAX_FLOWS, "flows reserved " + flows);
            assertTrue(accepted.get() > STEPS, "the producers got commands through: " + accepted.get());
            // what is still queued is applied by the next step, and only that
            int before = sim.inspect().pendingCommands();
            sim.stepFixed(cam);
            assertEquals(0, sim.inspect().pendingCommands(), "queued before: " + before);
        }
    }

    @Test
    void theQueueRefusesCommandsPastItsBoundAndTheStepAppliesThemAll() throws Exception {
        try (Simulation sim = SimFixtures.c1(1)) {
            for (int i = 0; i < Simulation.MAX_PENDING_COMMANDS; i++) {
                sim.setFieldEnabled(i % 2 == 0);
            }
            IllegalStateException full = assertThrows(IllegalStateException.class, () -> sim.setMode(AnimationMode.STATIC));
            assertTrue(full.getMessage().contains("command queue is full"), full.getMessage());
            assertEquals(Simulation.MAX_PENDING_COMMANDS, sim.inspect().pendingCommands());
            sim.stepFixed(SimFixtures.camera());
            assertEquals(0, sim.inspect().pendingCommands());
            assertTrue(!sim.inspect().fieldEnabled(), "the last queued command ran");
            sim.setMode(AnimationMode.STATIC);
        }
    }

    @Test
    void flowsHaveAMaximumCountCheckedByTheCall() throws Exception {
        try (Simulation sim = SimFixtures.c1(1)) {
            int scene = sim.inspect().flowCount();
            assertEquals(sim.inspect().windField().size(), scene);
            for (int i = scene; i < Simulation.MAX_FLOWS; i++) {
                sim.addFlow(FlowDef.point("f" + i, FlowKind.SOURCE, 0, 0, 1));
            }
            IllegalStateException ex = assertThrows(IllegalStateException.class,
                    () -> sim.addFlow(FlowDef.point("one-too-many", FlowKind.SOURCE, 0, 0, 1)));
            assertTrue(ex.getMessage().contains("MAX_FLOWS"), ex.getMessage());
            sim.stepFixed(SimFixtures.camera());
            assertEquals(Simulation.MAX_FLOWS, sim.inspect().windField().size());
            sim.removeFlow(sim.inspect().windField().get(0));
            sim.addFlow(FlowDef.point("one-more", FlowKind.SOURCE, 0, 0, 1));
            sim.stepFixed(SimFixtures.camera());
            assertEquals(Simulation.MAX_FLOWS, sim.inspect().windField().size());
        }
    }
}
