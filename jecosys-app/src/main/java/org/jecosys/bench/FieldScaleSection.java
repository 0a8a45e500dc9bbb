package org.jecosys.bench;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.jecosys.field.FieldCounters;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.field.QuadtreeForceField;
import org.jecosys.math.Rng;
import org.jecosys.math.ViewCamera;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.jecosys.wind.WindField;

/**
 * Field-update time against plant count (paper section 3.1; the scale curve of the report): one
 * thread, plants uniform at 4 per m^2, a camera walking a circle at 1.7 m while turning, four
 * flows. Also flow evaluations with the scene's LOD distances against full resolution.
 */
final class FieldScaleSection implements Section {
    private static final double DENSITY = 4;

    @Override
    public String name() {
        return "force-field update against plant count";
    }

    @Override
    public List<String> charts() {
        return List.of("field-scale.png");
    }

    static WindField wind() {
        return WindField.of(List.of(FlowDef.uniform("breeze", 2, 0.3),
                new FlowDef("gust", FlowKind.GUST, true, 0, 0, 3, 0.5, 0.5, Double.POSITIVE_INFINITY,
                        ActivationDef.ALWAYS, MotionDef.FIXED, 8, 0.25, 1, FlowDef.DEFAULT_GUST_STRENGTH,
                        FlowDef.DEFAULT_TURBULENCE),
                FlowDef.point("vortex", FlowKind.VORTEX, 20, 20, 40),
                FlowDef.point("source", FlowKind.SOURCE, -10, 30, 20)));
    }

    static QuadtreeForceField field(ForceFieldDef def, int n, WindField wind) {
        double size = Math.sqrt(n / DENSITY);
        Rng rng = new Rng(n);
        QuadtreeForceField f = new QuadtreeForceField(def, 0, 0, size, size, 0, 2, wind, n);
        for (int i = 0; i < n; i++) {
            f.addPlant(rng.nextDouble(0, size), rng.nextDouble(0, size));
        }
        return f;
    }

    static void pose(ViewCamera cam, double size, int k) {
        double a = k * 0.005;
        double r = size * 0.3;
        cam.setPosition(size / 2 + r * Math.cos(a), 1.7, size / 2 + r * Math.sin(a));
        cam.setOrientation(a * 2 + Math.sin(k * 0.01), -0.1);
    }

    @Override
    public void run(Mode mode, Report report) throws Exception {
        int[] sizes = switch (mode) {
            case SMOKE -> new int[] {1_000, 4_000};
            case QUICK -> new int[] {10_000, 100_000, 1_000_000};
            case FULL -> new int[] {10_000, 100_000, 1_000_000, 4_000_000};
        };
        int warmup = mode == Mode.SMOKE ? 5 : 300;
        int frames = mode == Mode.SMOKE ? 10 : 400;
        Table t = new Table("fieldScale", "Force-field update time against plant count (one thread)",
                List.of("plants", "nodes", "visible leaves", "flow evals LOD", "flow evals full", "LOD saving",
                        "median ms", "p90 ms"));
        double[] xs = new double[sizes.length];
        double[] ys = new double[sizes.length];
        List<Object> raw = new ArrayList<>();
        ViewCamera cam = new ViewCamera();
        cam.setLens(Math.toRadians(60), 16.0 / 9, 0.1, 500);
        for (int s = 0; s < sizes.length; s++) {
            int n = sizes[s];
            ForceFieldDef def = ForceFieldDef.defaults();
            WindField w = wind();
            QuadtreeForceField f = field(def, n, w);
            QuadtreeForceField full = field(ForceFieldDef.builder().maxObjectsPerNode(def.maxObjectsPerNode())
                    .maxDepth(def.maxDepth()).lodDistances().build(), n, wind());
            double size = Math.sqrt(n / DENSITY);
            double[] ms = new double[frames];
            long lodEvals = 0;
            long fullEvals = 0;
            long visLeaves = 0;
            for (int k = 0; k < warmup + frames; k++) {
                pose(cam, size, k);
                w.advance(1.0 / 60);
                long t0 = System.nanoTime();
                f.update(cam);
                long t1 = System.nanoTime();
                if (k >= warmup) {
                    ms[k - warmup] = (t1 - t0) / 1e6;
                    full.update(cam);
                    FieldCounters c = f.counters();
                    lodEvals += c.flowEvaluations();
                    fullEvals += full.counters().flowEvaluations();
                    visLeaves += c.visibleLeaves();
                }
            }
            double median = Stats.median(ms);
            t.row(n, f.counters().nodes(), visLeaves / frames, lodEvals / frames, fullEvals / frames,
                    String.format(java.util.Locale.ROOT, "%.1fx", (double) fullEvals / Math.max(1, lodEvals)),
                    median, Stats.percentile(ms, 0.9));
            xs[s] = n;
            ys[s] = median;
            Map<String, Object> r = new LinkedHashMap<>();
            r.put("plants", n);
            r.put("medianMs", median);
            r.put("p90Ms", Stats.percentile(ms, 0.9));
            r.put("flowEvaluationsLod", lodEvals / frames);
            r.put("flowEvaluationsFull", fullEvals / frames);
            raw.add(r);
        }
        t.note("Plants uniform at 4 per square metre; camera walks a circle at 1.7 m while turning; far plane 500 m; "
                + "4 flows; ForceFieldDef.defaults() (8 plants per node, depth 8, lodDistances 15 30). Targets: "
                + "1M plants in at most 2 ms on one core; at least 10x fewer flow evaluations with LOD.");
        report.add(t);
        report.raw("fieldScale", raw);
        report.saveChart("field-scale.png", png -> Charts.lines("Force-field update time", "plants", "median ms per update", List.of("one thread"),
                List.of(xs), List.of(ys), true, true, png));
    }
}
