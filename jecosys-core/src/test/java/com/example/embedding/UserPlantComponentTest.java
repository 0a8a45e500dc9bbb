package com.example.embedding;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.jecosys.anim.AnimationView;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.ComponentFactories;
import org.jecosys.plant.ForwardingPlantComponent;
import org.jecosys.plant.PlantComponent;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.SimulationDef;
import org.jecosys.sim.World;
import org.jecosys.terrain.CompetitiveDistributor;
import org.jecosys.wind.FlowDef;
import org.junit.jupiter.api.Test;

/** A species built in code uses a component type of the game's own (paper §4.1-4.2, §5.1). */
class UserPlantComponentTest {
    /** A leaf four times softer than its def says: eq. 4's PC / 4. */
    static final class SoftLeaf extends ForwardingPlantComponent {
        SoftLeaf(PlantComponent builtIn) {
            super(builtIn);
        }

        @Override
        public double stiffness() {
            return super.stiffness() / 4;
        }
    }

    /** Every variant drawn and animated with variant 0's shape: a uniform lawn. */
    static final class UniformLeaf extends ForwardingPlantComponent {
        UniformLeaf(PlantComponent builtIn) {
            super(builtIn);
        }

        @Override
        public PoseTable poseTable(int variant) {
            return super.poseTable(0);
        }

        @Override
        public double length(int variant) {
            return super.length(0);
        }

        @Override
        public double mass(int variant) {
            return super.mass(0);
        }
    }

    private static SimulationDef breezy() {
        return Meadows.def(Meadows.at(-6, 0, 0, 4, 6, -3), List.of(),
                List.of(FlowDef.uniform("breeze", 2, 0.4)));
    }

    private static World world(SimulationDef def, ComponentFactories components) throws Exception {
        return World.build(def, Path.of("."), 1, Progress.NONE, new CompetitiveDistributor(), components);
    }

    @Test
    void aSofterUserLeafBendsFourTimesAsFar() throws Exception {
        SimulationDef def = breezy();
        World plain = world(def, ComponentFactories.NONE);
        World soft = world(def, ComponentFactories.NONE.with(Meadows.SPECIES, "leaf",
                (species, builtIn) -> new SoftLeaf(builtIn)));
        SpeciesModel model = soft.plants().species().get(0);
        assertInstanceOf(SoftLeaf.class, model.component(0));
        assertEquals(plain.plants().species().get(0).component(0).stiffness() / 4, model.component(0).stiffness(), 0);
        ViewCamera camera = Meadows.overview();
        try (Simulation a = Simulation.of(plain, def, 0); Simulation b = Simulation.of(soft, def, 0)) {
            AnimationView view = b.inspect().state();
            assertEquals(model.component(0).stiffness(), view.kinds().stiffness(view.kind(0)), 0,
                    "the animation takes the spring constant from the user component");
            Meadows.run(a, camera, 4);
            Meadows.run(b, camera, 4);
            assertEquals(plain.plantCount(), soft.plantCount());
            for (int p = 0; p < plain.plantCount(); p++) {
                double stiff = Meadows.deviation(a, p);
                double softer = Meadows.deviation(b, p);
                assertTrue(stiff > 1e-3, "the built-in leaf bends: " + stiff);
                // the equilibrium deviation is F / PC (eq. 4): a quarter of the stiffness, four times the bend
                assertEquals(4, softer / stiff, 0.1, "plant " + p);
            }
        }
    }

    @Test
    void aUserComponentSuppliesThePoseTablesTheSimulationAndRendererUse() throws Exception {
        SimulationDef def = breezy();
        World w = world(def, ComponentFactories.NONE.with(Meadows.SPECIES, "leaf",
                (species, builtIn) -> new UniformLeaf(builtIn)));
        SpeciesModel m = w.plants().species().get(0);
        assertTrue(m.variants() > 1);
        for (int slot = 0; slot < m.slotCount(); slot++) {
            for (int v = 0; v < m.variants(); v++) {
                assertSame(m.component(0).poseTable(0), m.slotPoseTable(slot, v));
            }
        }
        try (Simulation sim = Simulation.of(w, def, 0)) {
            AnimationView view = sim.inspect().state();
            for (int c = 0; c < view.componentCount(); c++) {
                assertEquals(m.component(0).length(0), view.kinds().length(view.kind(c)), 1e-6);
            }
            Meadows.run(sim, Meadows.overview(), 1);
            for (int p = 0; p < w.plantCount(); p++) {
                assertTrue(Meadows.deviation(sim, p) > 1e-3, "plant " + p + " animates");
                float pose = 0;
                for (int c = view.firstComponent(p); c < view.firstComponent(p + 1); c++) {
                    pose = Math.max(pose, view.poseCoordinate(c)); // a leaf leaning into the wind may only turn
                }
                assertTrue(pose > 0, "plant " + p + " leaves its rest pose");
            }
        }
    }

    @Test
    void mistakesAreReportedAtBuildTime() {
        SimulationDef def = breezy();
        IllegalArgumentException unknown = assertThrows(IllegalArgumentException.class, () -> world(def,
                ComponentFactories.NONE.with(Meadows.SPECIES, "petal", (species, builtIn) -> builtIn)));
        assertTrue(unknown.getMessage().contains("petal") && unknown.getMessage().contains("leaf"),
                unknown.getMessage());
        assertThrows(IllegalArgumentException.class, () -> world(def,
                ComponentFactories.NONE.with("rose", "leaf", (species, builtIn) -> builtIn)));
        IllegalArgumentException stiff = assertThrows(IllegalArgumentException.class, () -> world(def,
                ComponentFactories.NONE.with(Meadows.SPECIES, "leaf", (species, builtIn) ->
                        new ForwardingPlantComponent(builtIn) {
                            @Override
                            public double stiffness() {
                                return -1;
                            }
                        })));
        assertTrue(stiff.getMessage().contains("stiffness"), stiff.getMessage());
        IllegalArgumentException variants = assertThrows(IllegalArgumentException.class, () -> world(def,
                ComponentFactories.NONE.with(Meadows.SPECIES, "leaf", (species, builtIn) ->
                        new ForwardingPlantComponent(builtIn) {
                            @Override
                            public int variants() {
                                return 1;
                            }
                        })));
        assertTrue(variants.getMessage().contains("variants"), variants.getMessage());
    }
}
