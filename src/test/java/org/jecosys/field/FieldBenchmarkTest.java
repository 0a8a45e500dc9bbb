package org.jecosys.field;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.jecosys.math.Rng;
import org.jecosys.math.ViewCamera;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.jecosys.wind.WindField;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Field-update benchmark (paper §3.1, issue "Force field"): median update time for 10k, 100k and
 * 1M plants with a walking, turning camera on one thread, and flow evaluations with LOD versus
 * full resolution for a viewer standing inside the scene. Reports only; asserts no timing.
 * Run with {@code mvn -B verify -Pbench}; writes target/bench/field.md.
 */
@Tag("benchmark")
class FieldBenchmarkTest {
    private static final double DENSITY = 4; // plants per m^2, a meadow
    private static final int WARMUP = 300;
    private static final int FRAMES = 400;

    private static WindField wind() {
        return WindField.of(List.of(FlowDef.uniform("breeze", 2, 0.3),
                new FlowDef("gust", FlowKind.GUST, true, 0, 0, 3, 0.5, 0.5, Double.POSITIVE_INFINITY,
                        ActivationDef.ALWAYS, MotionDef.FIXED, 8, 0.25, 1),
                FlowDef.point("vortex", FlowKind.VORTEX, 20, 20, 40),
                FlowDef.point("source", FlowKind.SOURCE, -10, 30, 20)));
    }

    private static QuadtreeForceField field(ForceFieldDef def, int n, WindField wind) {
        double size = Math.sqrt(n / DENSITY);
        Rng rng = new Rng(n);
        QuadtreeForceField f = new QuadtreeForceField(def, 0, 0, size, size, 0, 2, wind, n);
        for (int i = 0; i < n; i++) {
            f.addPlant(rng.nextDouble(0, size), rng.nextDouble(0, size));
        }
        return f;
    }

    private static void pose(ViewCamera cam, double size, int k) {
        double a = k * 0.005;
        double r = size * 0.3;
        cam.setPosition(size / 2 + r * Math.cos(a), 1.7, size / 2 + r * Math.sin(a))
                .setOrientation(a * 2 + Math.sin(k * 0.01), -0.1);
    }

    @Test
    void fieldUpdate() throws IOException {
        StringBuilder md = new StringBuilder();
        md.append("# Field update benchmark\n\n");
        md.append("One thread, ").append(Runtime.getRuntime().availableProcessors()).append(" cores, Java ")
                .append(System.getProperty("java.version")).append(". Plants uniform at ").append(DENSITY)
                .append(" /m^2; camera walks a circle at 1.7 m, turning, far 500 m; 4 flows (uniform, gust, vortex, source).\n")
                .append("ForceFieldDef.defaults(): 8 plants/node, max depth 8, lodDistances [15, 30] m. ")
                .append("Median and p90 over ").append(FRAMES).append(" updates after ").append(WARMUP).append(" warm-up.\n\n");
        md.append("| plants | nodes | leaves | visible leaves | effective nodes | flow evals (LOD) | flow evals (full) | ratio | median ms | p90 ms |\n");
        md.append("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        int[] sizes = {10_000, 100_000, 1_000_000};
        ViewCamera cam = new ViewCamera().setLens(Math.toRadians(60), 16.0 / 9, 0.1, 500);
        for (int n : sizes) {
            ForceFieldDef def = ForceFieldDef.defaults();
            WindField w = wind();
            QuadtreeForceField f = field(def, n, w);
            QuadtreeForceField full = field(new ForceFieldDef(true, def.maxObjectsPerNode(), def.maxDepth(), List.of()),
                    n, wind());
            double size = Math.sqrt(n / DENSITY);
            long[] t = new long[FRAMES];
            long lodEvals = 0;
            long fullEvals = 0;
            long visLeaves = 0;
            long eff = 0;
            for (int k = 0; k < WARMUP + FRAMES; k++) {
                pose(cam, size, k);
                w.advance(1.0 / 60);
                long t0 = System.nanoTime();
                f.update(cam);
                long t1 = System.nanoTime();
                if (k >= WARMUP) {
                    t[k - WARMUP] = t1 - t0;
                    full.update(cam);
                    lodEvals += f.counters().flowEvaluations();
                    fullEvals += full.counters().flowEvaluations();
                    visLeaves += f.counters().visibleLeaves();
                    eff += f.counters().effectiveNodes();
                }
            }
            Arrays.sort(t);
            double median = t[FRAMES / 2] / 1e6;
            double p90 = t[FRAMES * 9 / 10] / 1e6;
            md.append(String.format("| %,d | %,d | %,d | %,d | %,d | %,d | %,d | %.1fx | %.3f | %.3f |%n", n,
                    f.counters().nodes(), f.counters().leaves(), visLeaves / FRAMES, eff / FRAMES, lodEvals / FRAMES,
                    fullEvals / FRAMES, (double) fullEvals / Math.max(1, lodEvals), median, p90));
            assertTrue(lodEvals > 0);
        }
        md.append("\nTargets (not asserted): 1M plants in <= 2 ms on one core; >= 10x fewer flow evaluations with LOD.\n");
        System.out.println(md);
        Path out = Path.of("target", "bench", "field.md");
        Files.createDirectories(out.getParent());
        Files.writeString(out, md.toString());
    }
}
