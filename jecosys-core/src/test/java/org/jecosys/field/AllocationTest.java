package org.jecosys.field;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.List;
import org.jecosys.math.Rng;
import org.jecosys.math.ViewCamera;
import org.jecosys.math.Waypoint;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.jecosys.wind.WindField;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;

/** The steady-state loop (wind advance, field update, per-plant reads) allocates nothing. */
class AllocationTest {

    private static long allocated() {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        return mx.getThreadAllocatedBytes(Thread.currentThread().getId());
    }

    @Test
    void fieldUpdateAndFlowEvaluationAllocateNothingAfterWarmUp() {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assertTrue(mx.isThreadAllocatedMemorySupported());
        mx.setThreadAllocatedMemoryEnabled(true);
        MotionDef path = new MotionDef(MotionDef.Kind.PATH, List.of(new Waypoint(0, 0, 0), new Waypoint(100, 0, 50)), 3, true);
        MotionDef advected = new MotionDef(MotionDef.Kind.ADVECTED, List.of(), 1, false);
        WindField wind = WindField.of(List.of(
                FlowDef.uniform("u", 2, 0.3),
                new FlowDef("g", FlowKind.GUST, true, 0, 0, 4, 1.0, 0.5, Double.POSITIVE_INFINITY,
                        ActivationDef.ALWAYS, MotionDef.FIXED, 8, 0.25, 1, 0.6, 0.5),
                new FlowDef("v", FlowKind.VORTEX, true, 50, 50, 20, 0, 0.5, 40,
                        new ActivationDef(0.5, 100, 1, 1), path, 8, 0.25, 0, FlowDef.DEFAULT_GUST_STRENGTH,
                        FlowDef.DEFAULT_TURBULENCE),
                new FlowDef("s", FlowKind.SOURCE, true, 30, 70, 10, 0, 0.5, Double.POSITIVE_INFINITY,
                        ActivationDef.ALWAYS, advected, 8, 0.25, 0, FlowDef.DEFAULT_GUST_STRENGTH,
                        FlowDef.DEFAULT_TURBULENCE),
                new FlowDef("r", FlowKind.RAIN, true, 100, 100, 2, 0, 0.2, 30,
                        ActivationDef.ALWAYS, MotionDef.FIXED, 1, 2, 3, FlowDef.DEFAULT_GUST_STRENGTH,
                        FlowDef.DEFAULT_TURBULENCE)));
        wind.blast("boom", 120, 120, 30, 1000);
        var agent = wind.attachAgent(FlowDef.point("agent", FlowKind.SOURCE, 10, 10, 5));
        Rng rng = new Rng(1);
        int n = 20_000;
        QuadtreeForceField f = new QuadtreeForceField(ForceFieldDef.builder().maxDepth(10).build(),
                0, 0, 200, 200, 0, 2, wind, n);
        for (int i = 0; i < n; i++) {
            f.addPlant(rng.nextDouble(0, 200), rng.nextDouble(0, 200));
        }
        ViewCamera cam = new ViewCamera();
        cam.setLens(1.0, 1.7, 0.1, 300);
        float[] wx = new float[n];
        float[] wz = new float[n];
        boolean[] vis = new boolean[n];
        Vector2d v = new Vector2d();
        double[] sink = new double[1];
        Runnable frame = new Runnable() {
            int k;

            @Override
            public void run() {
                k++;
                double a = k * 0.01;
                wind.advance(1.0 / 60);
                agent.setCentre(100 + 50 * Math.cos(a), 100 + 50 * Math.sin(a));
                cam.setPosition(100 + 80 * Math.cos(a), 1.7, 100 + 80 * Math.sin(a));
                cam.setOrientation(a * 3, -0.05);
                f.update(cam);
                f.gather(0, n, wx, wz, vis);
                f.movePlant(k % n, rng.nextDouble(0, 200), rng.nextDouble(0, 200));
                sink[0] += wind.velocity(a, -a, v).x + f.wind(k % n, v).y + f.counters().flowEvaluations();
            }
        };
        for (int i = 0; i < 3000; i++) {
            frame.run();
        }
        // the cost of reading the counter itself: the least of a few readings (the first may still pay for
        // the counter's own code before the JIT has compiled it, which made every window read -272)
        long baseline = Long.MAX_VALUE;
        for (int i = 0; i < 8; i++) {
            long base = allocated();
            baseline = Math.min(baseline, allocated() - base);
        }
        // Warm-up ends when the JIT has settled: once in a while a hundred bytes appear on this thread
        // as compiled code is thrown away and redone (a branch the profile had never seen, after other
        // tests shaped it), never again after. A per-frame allocation of even one byte would never give
        // a zero window.
        long[] windows = new long[10];
        int zeroRun = 0;
        int w = 0;
        for (; w < windows.length && zeroRun < 2; w++) {
            long before = allocated();
            for (int i = 0; i < 500; i++) {
                frame.run();
            }
            windows[w] = allocated() - before - baseline;
            zeroRun = windows[w] == 0 ? zeroRun + 1 : 0;
        }
        assertEquals(2, zeroRun, "two consecutive windows of 500 frames allocating 0 bytes; bytes per window: "
                + java.util.Arrays.toString(java.util.Arrays.copyOf(windows, w)));
        assertTrue(Double.isFinite(sink[0]));
    }
}
