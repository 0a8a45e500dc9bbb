package org.jecosys.jmh;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.field.QuadtreeForceField;
import org.jecosys.math.Rng;
import org.jecosys.math.ViewCamera;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindField;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * JMH: one LOD quadtree force-field update (paper section 3.1) with a camera that moves every
 * call, for 10k to 1M plants. With {@code -prof gc} the allocation rate should read 0 B/op.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class FieldUpdateBenchmark {
    @Param({"10000", "100000", "1000000"})
    public int plants;

    private QuadtreeForceField field;
    private WindField wind;
    private final ViewCamera camera = new ViewCamera();
    private double size;
    private int frame;

    @Setup
    public void setup() {
        size = Math.sqrt(plants / 4.0);
        camera.setLens(Math.toRadians(60), 16.0 / 9, 0.1, 500);
        wind = WindField.of(List.of(FlowDef.uniform("breeze", 2, 0.3),
                FlowDef.point("vortex", FlowKind.VORTEX, size / 3, size / 3, 40),
                FlowDef.point("source", FlowKind.SOURCE, size / 2, size / 4, 20)));
        field = new QuadtreeForceField(ForceFieldDef.defaults(), 0, 0, size, size, 0, 2, wind, plants);
        Rng rng = new Rng(7);
        for (int i = 0; i < plants; i++) {
            field.addPlant(rng.nextDouble(0, size), rng.nextDouble(0, size));
        }
    }

    @Benchmark
    public int update() {
        double a = ++frame * 0.005;
        camera.setPosition(size / 2 + size * 0.3 * Math.cos(a), 1.7, size / 2 + size * 0.3 * Math.sin(a));
        camera.setOrientation(2 * a, -0.1);
        wind.advance(1.0 / 60);
        field.update(camera);
        return field.counters().flowEvaluations();
    }
}
