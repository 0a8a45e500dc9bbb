package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import com.sun.management.ThreadMXBean;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.Scenes;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;
import org.junit.jupiter.api.Test;

/**
 * {@link Simulation#moveAgent}, what a game calls every frame: it allocates nothing after the agent's
 * first move, the latest move before a step wins, a removed agent is not moved, and a closed
 * simulation refuses it.
 */
class MoveAgentTest {
    private static final ThreadMXBean MX = (ThreadMXBean) ManagementFactory.getThreadMXBean();

    private static ViewCamera camera() {
        ViewCamera camera = new ViewCamera();
        camera.setPosition(0, 2, 14);
        camera.setOrientation(0, -0.2);
        return camera;
    }

    @Test
    void movingAnAgentEveryFrameAllocatesNothingAndTheLatestMoveWins() throws Exception {
        long self = Thread.currentThread().getId();
        try (Simulation sim = Scenes.simulation(Path.of("scenes/c1.xml"), Progress.NONE)) {
            ViewCamera camera = camera();
            WindSource player = sim.attachAgent(FlowDef.point("player", FlowKind.SOURCE, 0, 0, 4));
            for (int i = 0; i < 20_000; i++) { // warm-up: the slot, and the JIT
                sim.moveAgent(player, (i % 13) * 0.5, 2);
                if (i % 100 == 0) {
                    sim.stepFixed(camera);
                }
            }
            // ten windows of 1,000 calls (a step after each): a move that allocated would show in every one;
            // the least is taken, as a stray allocation of the JIT or the runtime lands in one window
            long least = Long.MAX_VALUE;
            for (int w = 0; w < 10; w++) {
                long before = MX.getThreadAllocatedBytes(self);
                for (int i = 0; i < 1_000; i++) {
                    sim.moveAgent(player, (i % 17) * 0.25, -3);
                }
                least = Math.min(least, MX.getThreadAllocatedBytes(self) - before);
                sim.stepFixed(camera);
            }
            assertEquals(0, least, "bytes allocated by 1,000 moveAgent calls (the least of ten windows)");

            sim.moveAgent(player, 1, 2);
            sim.moveAgent(player, 5, -6); // the latest move before the step wins
            assertEquals(0, sim.inspect().pendingCommands(), "moves do not fill the command queue");
            sim.stepFixed(camera);
            assertEquals(5, player.centreX(), 0);
            assertEquals(-6, player.centreZ(), 0);

            sim.removeFlow(player);
            sim.moveAgent(player, 7, 7); // no longer in the simulation: not moved
            sim.stepFixed(camera);
            assertEquals(5, player.centreX(), 0);
            assertEquals(-1, sim.inspect().windField().indexOf("player"));

            WindSource again = sim.attachAgent(FlowDef.point("later", FlowKind.SOURCE, 0, 0, 4));
            sim.moveAgent(again, -2, 3); // added and moved before the same step: added, then moved
            sim.stepFixed(camera);
            assertEquals(-2, again.centreX(), 0);
            assertEquals(3, again.centreZ(), 0);

            sim.close();
            IllegalStateException closed = assertThrows(IllegalStateException.class, () -> sim.moveAgent(again, 0, 0));
            assertEquals("the simulation is closed", closed.getMessage());
        }
    }
}
