package com.example.embedding;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.SimulationDef;
import org.jecosys.sim.World;
import org.jecosys.wind.AbstractWindSource;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;

/** A game's own wind flow, written outside the library, drives a running simulation like a built-in flow. */
class UserWindSourceTest {
    /** A fan: a constant wind along +X within {@code radius} of its centre. */
    static final class Fan extends AbstractWindSource {
        private final double speed;
        int advances;

        Fan(String id, double x, double z, double radius, double speed) {
            super(id, x, z, radius, ActivationDef.ALWAYS);
            this.speed = speed;
        }

        @Override
        protected void flow(double x, double z, double time, Vector2d dest) {
            dest.set(speed, 0);
        }

        @Override
        public void onAdvance(double time, double dt) {
            advances++;
        }
    }

    /** The built-in SOURCE's formula (paper §3.2), written by a user: a/(2 pi) (p - c) / max(r, core)^2. */
    static final class UserSource extends AbstractWindSource {
        private final double k;

        UserSource(String id, double x, double z, double strength, double radius, ActivationDef activation) {
            super(id, x, z, radius, activation);
            k = strength / (2 * Math.PI);
        }

        @Override
        protected void flow(double x, double z, double time, Vector2d dest) {
            double dx = x - centreX();
            double dz = z - centreZ();
            double f = k / Math.max(dx * dx + dz * dz, FlowDef.DEFAULT_CORE_RADIUS * FlowDef.DEFAULT_CORE_RADIUS);
            dest.set(f * dx, f * dz);
        }
    }

    @Test
    void aFanBendsThePlantsNearItAndNotTheFarOnes() throws Exception {
        SimulationDef def = Meadows.def(Meadows.at(-10, 0, -9, 1.5, 10, 0, 0, -12), List.of(), List.of());
        World world = Meadows.world(def);
        ViewCamera camera = Meadows.overview();
        try (Simulation sim = Simulation.of(world, def, 0)) {
            Fan fan = new Fan("fan", -10, 0, 4, 6);
            assertSame(fan, sim.addFlow(fan));
            Meadows.run(sim, camera, 2);
            int near = Meadows.plantAt(world, -10, 0);
            int near2 = Meadows.plantAt(world, -9, 1.5);
            int far = Meadows.plantAt(world, 10, 0);
            int far2 = Meadows.plantAt(world, 0, -12);
            for (int p = 0; p < world.plantCount(); p++) {
                assertTrue(sim.inspect().plantVisible(p), "plant " + p + " is in view");
            }
            assertEquals(6, sim.inspect().windX(near), 1e-6);
            assertEquals(0, sim.inspect().windZ(near), 0);
            assertEquals(6, sim.inspect().windX(near2), 1e-6);
            assertEquals(0, sim.inspect().windX(far), 0);
            assertEquals(0, sim.inspect().windX(far2), 0);
            assertTrue(Meadows.deviation(sim, near) > 1e-3, "near plant bends: " + Meadows.deviation(sim, near));
            assertTrue(Meadows.deviation(sim, near2) > 1e-3);
            assertEquals(0, Meadows.deviation(sim, far), 0, "far plant stays at rest");
            assertEquals(0, Meadows.deviation(sim, far2), 0);
            // once per fixed step; the field runs one step ahead of the animation (Simulation's class comment)
            assertEquals(sim.inspect().steps() + 1, fan.advances, "the field advances user flows once per fixed step");
            assertEquals(1, sim.inspect().windField().activeCount());

            double bent = Meadows.deviation(sim, near);
            sim.setFlowEnabled(fan, false);
            Meadows.run(sim, camera, 3);
            assertEquals(0, sim.inspect().windX(near), 0, "a disabled user flow blows no more");
            assertTrue(Meadows.deviation(sim, near) < 0.01 * bent, "and the plant swings back");

            sim.setFlowEnabled(fan, true);
            sim.moveAgent(fan, 10, 0);
            Meadows.run(sim, camera, 2);
            assertEquals(0, sim.inspect().windX(near), 0);
            assertEquals(6, sim.inspect().windX(far), 1e-6, "moved like an agent");
            assertTrue(Meadows.deviation(sim, far) > 1e-3);

            sim.removeFlow(fan);
            sim.step(1.0 / 60, camera);
            assertEquals(-1, sim.inspect().windField().indexOf("fan"));
        }
    }

    @Test
    void aUserFlowIsEvaluatedExactlyLikeTheBuiltInOne() throws Exception {
        SimulationDef def = Meadows.def(Meadows.at(-10, 0, -8, 1, -11, -2, -3, 0, 10, 0),
                List.of(), List.of(FlowDef.builder("breeze", FlowKind.UNIFORM).strength(1).direction(1).build()));
        World world = Meadows.world(def);
        ViewCamera camera = Meadows.overview();
        ActivationDef act = new ActivationDef(0.2, 10, 0.5, 0.5);
        FlowDef builtIn = FlowDef.builder("src", FlowKind.SOURCE).centre(-9, 0).strength(30).influenceRadius(5)
                .activation(act).build();
        long[] hashes = new long[2];
        double[] deviation = new double[2];
        for (int run = 0; run < 2; run++) {
            try (Simulation sim = Simulation.of(world, def, 0)) {
                WindSource s = run == 0 ? sim.addFlow(builtIn) : sim.addFlow(new UserSource("src", -9, 0, 30, 5, act));
                assertEquals(run == 0 ? FlowKind.SOURCE : null, s.kind());
                Meadows.run(sim, camera, 1.5);
                hashes[run] = sim.inspect().stateHash();
                deviation[run] = Meadows.deviation(sim, Meadows.plantAt(world, -10, 0));
            }
        }
        assertTrue(deviation[0] > 1e-3, "the source bends the plant next to it: " + deviation[0]);
        assertEquals(hashes[0], hashes[1], "bit-identical state: same sums, activation ramp and radius");
        try (Simulation calm = Simulation.of(world, def, 0)) {
            Meadows.run(calm, camera, 1.5);
            assertNotEquals(hashes[0], calm.inspect().stateHash(), "and the source does change the state");
        }
    }

    @Test
    void theUserFlowContractIsChecked() {
        assertThrows(IllegalArgumentException.class, () -> new Fan("", 0, 0, 4, 1));
        assertThrows(IllegalArgumentException.class, () -> new Fan("f", Double.NaN, 0, 4, 1));
        assertThrows(IllegalArgumentException.class, () -> new Fan("f", 0, 0, 0, 1));
        WindSource minimal = new WindSource() {
            private boolean on = true;

            @Override
            public String id() {
                return "minimal";
            }

            @Override
            public boolean isEnabled() {
                return on;
            }

            @Override
            public void setEnabled(boolean enabled) {
                on = enabled;
            }

            @Override
            public Vector2d velocity(double x, double z, double time, Vector2d dest) {
                return on ? dest.set(1, 2) : dest.set(0, 0);
            }
        };
        assertEquals(1, minimal.weight(0), 0);
        assertEquals(Double.POSITIVE_INFINITY, minimal.influenceRadius(), 0);
        assertThrows(UnsupportedOperationException.class, () -> minimal.setCentre(1, 1));
        org.jecosys.wind.WindField w = new org.jecosys.wind.WindField();
        w.add(minimal);
        w.add(FlowDef.uniform("u", 1, 0));
        assertEquals(new Vector2d(2, 2), w.velocity(5, 5, new Vector2d()));
        minimal.setEnabled(false);
        assertEquals(new Vector2d(1, 0), w.velocity(5, 5, new Vector2d()));
        assertEquals(1, w.activeCount());
        assertThrows(IllegalArgumentException.class, () -> w.add(new Fan("minimal", 0, 0, 1, 1)));
    }
}
