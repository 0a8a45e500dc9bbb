package org.jecosys.jmh;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.jecosys.wind.WindField;
import org.joml.Vector2d;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * JMH: summed velocity of five flows (uniform, gust, source, sink, vortex; paper section 3.2) at
 * 1024 points per call, reported per point. With {@code -prof gc} it should read 0 B/op.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class FlowEvaluationBenchmark {
    private static final int POINTS = 1024;
    private WindField wind;
    private final double[] xs = new double[POINTS];
    private final double[] zs = new double[POINTS];
    private final Vector2d dest = new Vector2d();

    @Setup
    public void setup() {
        wind = WindField.of(List.of(FlowDef.uniform("breeze", 2, 0.3),
                new FlowDef("gust", FlowKind.GUST, true, 0, 0, 3, 0.5, 0.5, Double.POSITIVE_INFINITY,
                        ActivationDef.ALWAYS, MotionDef.FIXED, 8, 0.25, 1, FlowDef.DEFAULT_GUST_STRENGTH,
                        FlowDef.DEFAULT_TURBULENCE),
                FlowDef.point("source", FlowKind.SOURCE, 10, 10, 20),
                FlowDef.point("sink", FlowKind.SINK, -10, 5, 15),
                FlowDef.point("vortex", FlowKind.VORTEX, 0, -20, 40)));
        for (int i = 0; i < POINTS; i++) {
            xs[i] = (i * 37 % 101) - 50;
            zs[i] = (i * 53 % 97) - 48;
        }
    }

    @Benchmark
    @OperationsPerInvocation(POINTS)
    public double evaluate() {
        wind.advance(1.0 / 60);
        double sum = 0;
        for (int i = 0; i < POINTS; i++) {
            wind.velocity(xs[i], zs[i], dest);
            sum += dest.x + dest.y;
        }
        return sum;
    }
}
