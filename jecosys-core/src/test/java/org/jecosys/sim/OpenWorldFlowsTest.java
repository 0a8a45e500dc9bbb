package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import org.jecosys.math.ViewCamera;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.junit.jupiter.api.Test;

/**
 * Flows a game adds to an open world at run time ({@link OpenWorld#addFlow}, {@link OpenWorld#moveAgent},
 * {@link OpenWorld#blast}, {@link OpenWorld#removeFlow}): a walker's agent that follows the camera into
 * tiles that did not exist when it was added flattens the grass it passes there (the meadow's grass
 * keeps trails); a blast reaches every tile and is dropped once over; a removed flow leaves every tile;
 * moving an agent every step allocates nothing once it has moved in each tile.
 */
class OpenWorldFlowsTest {
    private static final double RADIUS = 24;

    private static int flows(OpenWorld w, int k) {
        return w.tile(k).simulation().inspect().flowCount();
    }

    @Test
    void aWalkersAgentFlattensTheGrassInTilesMadeAfterItWasAdded() throws Exception {
        SimulationDef def = OpenWorldTest.meadowDef();
        try (OpenWorld w = OpenWorld.create(def, OpenWorldTest.placer(def), RADIUS, 2, 1, 8)) {
            ViewCamera c = OpenWorldTest.walker(0, 3);
            w.stepFixed(c);
            w.addFlow(FlowDef.point("walker", FlowKind.SOURCE, 2, 3, 30));
            assertThrows(IllegalArgumentException.class, () -> w.addFlow(FlowDef.point("walker", FlowKind.SOURCE, 0, 0, 1)));
            assertThrows(IllegalArgumentException.class, () -> w.moveAgent("nobody", 0, 0));
            double x = 0;
            for (int s = 0; s < 1500; s++) { // 25 s at 60 Hz, walking 1.5 m/s: 37.5 m
                x = s * 1.5 / 60;
                c.setPosition(x, OpenWorldTest.GROUND.height(x, 3) + 1.7, 3);
                w.moveAgent("walker", x + 2, 3);
                w.stepFixed(c);
            }
            int base = def.flows().size();
            for (int k = 0; k < w.liveTiles(); k++) {
                assertEquals(base + 1, flows(w, k), "tile " + w.tile(k).i() + "," + w.tile(k).j() + " holds the agent");
            }
            // the tile under the agent now was made during the walk: the plants the agent passed are flattened
            double ax = x + 2;
            WorldTile under = null;
            for (int k = 0; k < w.liveTiles(); k++) {
                WorldTile t = w.tile(k);
                if (t.i() == (int) Math.floor(ax / 16) && t.j() == 0) {
                    under = t;
                }
            }
            assertTrue(under != null && under.i() >= 2, "the agent walked into tile " + (under == null ? "?" : under.i()));
            World tw = under.world();
            float flat = 0;
            int n = 0;
            for (int p = 0; p < tw.plantCount(); p++) {
                double dz = tw.plantZ(p) - 3;
                if (Math.abs(dz) < 0.5 && tw.plantX(p) > under.i() * 16 && tw.plantX(p) < ax - 1) {
                    flat = Math.max(flat, under.simulation().inspect().state().flattening(p));
                    n++;
                }
            }
            assertTrue(n > 0, "plants on the agent's path in the tile");
            assertTrue(flat > 0.3f, "the agent left a trail in a tile made after it was added: flattening " + flat);
            assertTrue(w.removeFlow("walker"));
            assertFalse(w.removeFlow("walker"));
            w.stepFixed(c);
            for (int k = 0; k < w.liveTiles(); k++) {
                assertEquals(base, flows(w, k), "the agent left every tile");
            }
        }
    }

    @Test
    void aBlastReachesEveryTileAndIsDroppedOnceOver() throws Exception {
        SimulationDef def = OpenWorldTest.meadowDef();
        try (OpenWorld w = OpenWorld.create(def, OpenWorldTest.placer(def), RADIUS, 1, 1, 8)) {
            ViewCamera c = OpenWorldTest.walker(0, 3);
            for (int s = 0; s < 20; s++) {
                w.stepFixed(c);
            }
            w.settle();
            w.stepFixed(c);
            int base = def.flows().size();
            w.blast("bang", 4, 3, 50, 0.5);
            w.stepFixed(c);
            for (int k = 0; k < w.liveTiles(); k++) {
                assertEquals(base + 1, flows(w, k));
            }
            for (int s = 0; s < 60; s++) {
                w.stepFixed(c);
            }
            for (int k = 0; k < w.liveTiles(); k++) {
                assertEquals(base, flows(w, k), "the blast is over and dropped");
            }
        }
    }

    @Test
    void movingAnAgentEveryStepAllocatesNothingOnceItMovedInEachTile() throws Exception {
        SimulationDef def = OpenWorldTest.meadowDef();
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        try (OpenWorld w = OpenWorld.create(def, OpenWorldTest.placer(def), RADIUS, 1, 1, 8)) {
            ViewCamera c = OpenWorldTest.walker(5, 3);
            for (int s = 0; s < 20; s++) {
                w.stepFixed(c);
            }
            w.settle();
            w.addFlow(FlowDef.point("walker", FlowKind.SOURCE, 5, 3, 2));
            for (int s = 0; s < 300; s++) {
                w.moveAgent("walker", 5 + 0.01 * (s % 50), 3);
                w.stepFixed(c);
            }
            long id = Thread.currentThread().getId();
            long before = threads.getThreadAllocatedBytes(id);
            for (int s = 0; s < 100; s++) {
                w.moveAgent("walker", 5 + 0.01 * (s % 50), 3);
            }
            assertEquals(0, threads.getThreadAllocatedBytes(id) - before, "bytes allocated by 100 moves");
        }
    }
}
