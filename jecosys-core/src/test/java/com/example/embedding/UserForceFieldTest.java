package com.example.embedding;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import org.jecosys.field.FieldBounds;
import org.jecosys.field.FieldCounters;
import org.jecosys.field.FieldDebugView;
import org.jecosys.field.ForceField;
import org.jecosys.field.ForceFieldFactory;
import org.jecosys.math.Camera;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.SimulationDef;
import org.jecosys.sim.World;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;

/** A game's own force field, written outside the library, drives a simulation's animation. */
class UserForceFieldTest {
    /** The simplest field: every plant visible, one uniform wind everywhere, no quadtree. */
    static final class UniformField implements ForceField {
        private float[] xs;
        private float[] zs;
        private int count;
        private final float windX;
        private final float windZ;
        int updates;

        UniformField(float[] xs, float[] zs, float windX, float windZ) {
            this.xs = xs;
            this.zs = zs;
            this.count = xs.length;
            this.windX = windX;
            this.windZ = windZ;
        }

        @Override
        public int addPlant(double x, double z) {
            if (count == xs.length) {
                xs = Arrays.copyOf(xs, 2 * count + 1);
                zs = Arrays.copyOf(zs, 2 * count + 1);
            }
            xs[count] = (float) x;
            zs[count] = (float) z;
            return count++;
        }

        @Override
        public void movePlant(int plant, double x, double z) {
            xs[plant] = (float) x;
            zs[plant] = (float) z;
        }

        @Override
        public int plantCount() {
            return count;
        }

        @Override
        public void update(Camera camera) {
            updates++;
        }

        @Override
        public boolean isVisible(int plant) {
            return true;
        }

        @Override
        public int effectiveNode(int plant) {
            return 0;
        }

        @Override
        public int leafNode(int plant) {
            return 0;
        }

        @Override
        public int depth(int plant) {
            return 0;
        }

        @Override
        public Vector2d wind(int plant, Vector2d dest) {
            return dest.set(windX, windZ);
        }

        @Override
        public void gather(int first, int n, float[] wx, float[] wz, boolean[] visible) {
            Arrays.fill(wx, 0, n, windX);
            Arrays.fill(wz, 0, n, windZ);
            Arrays.fill(visible, 0, n, true);
        }
    }

    /** A field that wraps the paper's quadtree and adds a steady draught along +Z to its wind. */
    static final class DraughtField implements ForceField {
        private final ForceField inner;
        private final float draught;

        DraughtField(ForceField inner, float draught) {
            this.inner = inner;
            this.draught = draught;
        }

        @Override
        public int addPlant(double x, double z) {
            return inner.addPlant(x, z);
        }

        @Override
        public void movePlant(int plant, double x, double z) {
            inner.movePlant(plant, x, z);
        }

        @Override
        public int plantCount() {
            return inner.plantCount();
        }

        @Override
        public void update(Camera camera) {
            inner.update(camera);
        }

        @Override
        public boolean isVisible(int plant) {
            return inner.isVisible(plant);
        }

        @Override
        public int effectiveNode(int plant) {
            return inner.effectiveNode(plant);
        }

        @Override
        public int leafNode(int plant) {
            return inner.leafNode(plant);
        }

        @Override
        public int depth(int plant) {
            return inner.depth(plant);
        }

        @Override
        public Vector2d wind(int plant, Vector2d dest) {
            inner.wind(plant, dest);
            return dest.set(dest.x, dest.y + draught);
        }

        @Override
        public void gather(int first, int n, float[] wx, float[] wz, boolean[] visible) {
            inner.gather(first, n, wx, wz, visible);
            for (int i = 0; i < n; i++) {
                if (visible[i]) {
                    wz[i] += draught;
                }
            }
        }

        @Override
        public FieldCounters counters() {
            return inner.counters();
        }

        @Override
        public FieldDebugView debugView() {
            return inner.debugView();
        }
    }

    private static SimulationDef calm() {
        return Meadows.def(Meadows.at(-10, 0, 5, 5, 10, -10, 0, 15), List.of(), List.of());
    }

    @Test
    void aUniformFieldDrivesEveryPlantEvenOutOfView() throws Exception {
        SimulationDef def = calm();
        World world = Meadows.world(def);
        // low, near the south-west corner, looking south (+Z) out of the meadow: most of it is behind
        ViewCamera camera = new ViewCamera();
        camera.setPosition(-19, 1.7, 19);
        camera.setOrientation(Math.PI, 0);
        FieldBounds[] seen = new FieldBounds[1];
        UniformField[] made = new UniformField[1];
        ForceFieldFactory uniform = (bounds, fieldDef, wind, xs, zs) -> {
            seen[0] = bounds;
            made[0] = new UniformField(xs, zs, 3, -1);
            return made[0];
        };
        try (Simulation sim = Simulation.of(world, def, 0, uniform);
             Simulation reference = Simulation.of(world, def, 0)) {
            assertSame(made[0], sim.inspect().forceField());
            assertEquals(-20, seen[0].minX(), 1e-9);
            assertEquals(20, seen[0].maxZ(), 1e-9);
            assertTrue(seen[0].maxY() > seen[0].minY(), "the box includes the plants' height");
            long rest = sim.inspect().stateHash();
            Meadows.run(sim, camera, 1);
            Meadows.run(reference, camera, 1);
            assertEquals(sim.inspect().steps() + 2, made[0].updates,
                    "updated at t = 0, then once per step, one step ahead");
            assertSame(FieldCounters.NONE, sim.inspect().fieldCounters());
            assertEquals(0, sim.inspect().forceField().debugView().nodeCount());
            assertNotEquals(rest, sim.inspect().stateHash(), "the field's wind moves the meadow");
            int invisibleInReference = 0;
            for (int p = 0; p < world.plantCount(); p++) {
                assertTrue(sim.inspect().plantVisible(p));
                assertEquals(3, sim.inspect().windX(p), 0);
                assertEquals(-1, sim.inspect().windZ(p), 0);
                assertTrue(Meadows.deviation(sim, p) > 1e-3, "plant " + p + " bends in the uniform wind");
                assertEquals(0, Meadows.deviation(reference, p), 0, "no wind in the scene itself");
                invisibleInReference += reference.inspect().plantVisible(p) ? 0 : 1;
            }
            assertTrue(invisibleInReference > 0, "the quadtree culls plants behind the camera; this field does not");
            // the plants bend downwind: along (3, -1)
            int p = Meadows.plantAt(world, 10, -10);
            double dx = 0;
            double dz = 0;
            int end = sim.inspect().state().firstComponent(p + 1);
            for (int c = sim.inspect().state().firstComponent(p); c < end; c++) {
                dx += sim.inspect().state().deviationX(c);
                dz += sim.inspect().state().deviationZ(c);
            }
            assertTrue(dx > 0 && dz < 0 && dx > 2 * -dz, "deviation (" + dx + ", " + dz + ") follows the wind");
        }
    }

    @Test
    void aFieldWrappingTheQuadtreeAddsItsOwnWind() throws Exception {
        SimulationDef def = calm();
        World world = Meadows.world(def);
        ViewCamera camera = Meadows.overview();
        ForceFieldFactory draught = (bounds, fieldDef, wind, xs, zs) ->
                new DraughtField(ForceFieldFactory.QUADTREE.create(bounds, fieldDef, wind, xs, zs), 2);
        try (Simulation sim = Simulation.of(world, def, 0, draught)) {
            Meadows.run(sim, camera, 1);
            assertTrue(sim.inspect().fieldCounters().nodes() > 1, "the quadtree's counters come through");
            assertTrue(sim.inspect().forceField().debugView().nodeCount() > 1);
            for (int p = 0; p < world.plantCount(); p++) {
                assertTrue(sim.inspect().plantVisible(p));
                assertEquals(0, sim.inspect().windX(p), 0);
                assertEquals(2, sim.inspect().windZ(p), 0);
                assertTrue(Meadows.deviation(sim, p) > 1e-4);
            }
        }
    }

    @Test
    void aFieldMustHoldEveryPlant() throws Exception {
        SimulationDef def = calm();
        World world = Meadows.world(def);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Simulation.of(world, def, 1,
                (bounds, fieldDef, wind, xs, zs) -> new UniformField(new float[1], new float[1], 1, 0)));
        assertTrue(e.getMessage().contains("plants"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Simulation.of(world, def, 1, (ForceFieldFactory) null));
    }
}
