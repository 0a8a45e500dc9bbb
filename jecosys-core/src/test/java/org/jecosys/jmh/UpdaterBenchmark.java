package org.jecosys.jmh;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.CameraDef;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.SpeciesLibrary;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.SimulationDef;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.terrain.ResourceMapDef;
import org.jecosys.terrain.TerrainDef;
import org.jecosys.wind.FlowDef;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * JMH: one fixed step of the dynamic-constraint updater (paper section 4.2, eq. 5) over grass tufts
 * A, every plant visible, with 1 or 2 workers. The score is per step; divide the component count by
 * it for updates per second. With {@code -prof gc} the stepping thread reads 0 B/op.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class UpdaterBenchmark {
    @Param({"100000", "1000000"})
    public int components;

    @Param({"1", "2"})
    public int workers;

    private Simulation sim;
    private ViewCamera camera;

    @Setup(Level.Trial)
    public void setup() throws Exception {
        int tufts = components / 25;
        double side = Math.sqrt(tufts / 4.0) * 1.2;
        SimulationDef def = new SimulationDef(new TerrainDef(side, side, 17, 0, 0.5, 1, null,
                ResourceMapDef.UNIFORM_FULL, ResourceMapDef.UNIFORM_FULL), List.of(SpeciesLibrary.grassTuftA()),
                List.of(DistributionDef.builder(SpeciesLibrary.grassTuftA().id()).count(tufts).footprint(0.12)
                        .waterUse(0).nutrientUse(0).build()), List.of(), List.of(FlowDef.uniform("breeze", 3, 0.4)),
                ForceFieldDef.defaults(), new AnimationDef(AnimationMode.CONSTRAINT, 1.0 / 60, 8, 4, 0, 1), 1);
        sim = Simulation.create(def, Path.of("."), workers, Progress.NONE);
        camera = ViewCamera.of(new CameraDef(0, side * 0.6 + 5, 0, 0, -Math.PI / 2 + 1e-3, Math.toRadians(100), 0.5,
                side * 4 + 100, List.of(), 1, false), 0, 16.0 / 9);
    }

    @TearDown(Level.Trial)
    public void close() {
        sim.close();
    }

    @Benchmark
    public int step() {
        sim.stepFixed(camera);
        return sim.latestFrame().componentsAnimated();
    }
}
