package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.ViewCamera;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;
import org.junit.jupiter.api.Test;

/**
 * The simulation's commands check their arguments in the call that makes them, with the scene
 * schema's ranges: a duplicate flow id, NaN or a huge strength never reach a step.
 */
class ApiArgumentsTest {
    @Test
    void aDuplicateFlowIdIsRefusedByTheCallNotByTheNextStep() throws Exception {
        try (Simulation sim = SimFixtures.c1(1)) {
            ViewCamera cam = SimFixtures.camera();
            String sceneId = sim.inspect().windField().get(0).id();
            IllegalArgumentException dup = assertThrows(IllegalArgumentException.class,
                    () -> sim.addFlow(FlowDef.point(sceneId, FlowKind.SOURCE, 0, 0, 1)));
            assertTrue(dup.getMessage().contains("'" + sceneId + "'"), dup.getMessage());
            sim.blast("boom", 0, 10, 50, 0.5);
            IllegalArgumentException twice = assertThrows(IllegalArgumentException.class,
                    () -> sim.blast("boom", 0, 10, 50, 0.5));
            assertTrue(twice.getMessage().contains("'boom'"), twice.getMessage());
            WindSource queued = sim.addFlow(FlowDef.point("agent", FlowKind.SOURCE, 0, 0, 1));
            assertThrows(IllegalArgumentException.class, () -> sim.addFlow(FlowDef.point("agent", FlowKind.SINK, 1, 1, 1)));
            for (int i = 0; i < 3; i++) {
                sim.stepFixed(cam); // nothing queued can fail now
            }
            assertTrue(sim.inspect().windField().indexOf("boom") >= 0);
            // removing frees the id at once; a blast's id is free once it is over
            sim.removeFlow(queued);
            sim.addFlow(FlowDef.point("agent", FlowKind.SINK, 1, 1, 1));
            for (int i = 0; i < 60; i++) {
                sim.stepFixed(cam);
            }
            assertEquals(-1, sim.inspect().windField().indexOf("boom"));
            sim.blast("boom", 0, 10, 50, 0.5);
            sim.stepFixed(cam);
            assertTrue(sim.inspect().windField().indexOf("boom") >= 0);
        }
    }

    @Test
    void nanAndHugeValuesAreRefusedWithTheSchemaRanges() throws Exception {
        try (Simulation sim = SimFixtures.c1(1)) {
            ViewCamera cam = SimFixtures.camera();
            IllegalArgumentException huge = assertThrows(IllegalArgumentException.class,
                    () -> sim.addFlow(FlowDef.point("huge", FlowKind.SOURCE, 0, 14, 1e12)));
            assertTrue(huge.getMessage().startsWith("strength must be in [0.0, 1000000.0]"), huge.getMessage());
            assertThrows(IllegalArgumentException.class,
                    () -> sim.addFlow(FlowDef.point("nan", FlowKind.SOURCE, 0, 14, Double.NaN)));
            assertThrows(IllegalArgumentException.class,
                    () -> sim.addFlow(FlowDef.point("vortex", FlowKind.VORTEX, 0, 14, -2e6)));
            assertThrows(IllegalArgumentException.class, () -> sim.blast("b", 0, 14, 1e12, 0.5));
            assertThrows(IllegalArgumentException.class, () -> sim.blast("b", 0, 14, Double.NaN, 0.5));
            assertThrows(IllegalArgumentException.class, () -> sim.blast("b", 0, 14, 10, 2e9));
            assertThrows(IllegalArgumentException.class, () -> sim.blast("", 0, 14, 10, 1));
            assertThrows(IllegalArgumentException.class, () -> sim.blast("b", 2e6, 14, 10, 1));
            WindSource agent = sim.addFlow(FlowDef.point("agent", FlowKind.SOURCE, 0, 14, 1));
            assertThrows(IllegalArgumentException.class, () -> sim.moveAgent(agent, Double.NaN, 0));
            assertThrows(IllegalArgumentException.class, () -> sim.moveAgent(agent, 0, 1e7));
            assertThrows(IllegalArgumentException.class,
                    () -> FlowDef.builder("g", FlowKind.GUST).strength(2).noiseScale(1e-100).build());
            assertThrows(IllegalArgumentException.class,
                    () -> FlowDef.builder("g", FlowKind.GUST).strength(2).noiseScale(Double.MIN_VALUE).build());
            // the strongest flow the schema allows leaves no NaN, also after it is gone
            WindSource strongest = sim.addFlow(FlowDef.point("strongest", FlowKind.SOURCE, 0, 14, FlowDef.MAX_STRENGTH));
            for (int i = 0; i < 30; i++) {
                sim.stepFixed(cam);
            }
            sim.removeFlow(strongest);
            for (int i = 0; i < 30; i++) {
                sim.stepFixed(cam);
            }
            for (int c = 0; c < sim.componentCount(); c++) {
                assertFalse(Float.isNaN(sim.inspect().state().deviationX(c)) || Float.isNaN(sim.inspect().state()
                        .poseCoordinate(c)),
                        "component " + c);
            }
        }
    }
}
