package org.jecosys.bench;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.PassTimes;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.ResolvePath;
import org.jecosys.render.SceneRenderer;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.CameraWalk;
import org.jecosys.sim.DrawQuality;
import org.jecosys.sim.Simulation;

/**
 * Where a frame's GPU time goes (issue 42): each scene's camera walk drawn with pass timing on
 * ({@link SceneRenderer#setPassTiming}), the median and 95th percentile of every pass, and the sum of the
 * passes' medians against the median of the frames timed whole (every fourth). On a GPU the passes are
 * timed by timer queries read a few frames later; on a software rasteriser by the clock around
 * {@code glFinish} after each pass (its timer queries do not time passes).
 */
final class RenderPassSection implements Section {
    private static final double DT = 1 / 30.0;
    private final Path scenes;
    /** Thinning for every scene, or null for each scene's own. */
    private final DrawQuality quality;

    RenderPassSection(Path scenes, DrawQuality quality) {
        this.scenes = scenes;
        this.quality = quality;
    }

    @Override
    public String name() {
        return "render passes";
    }

    @Override
    public void run(Mode mode, Report report) throws Exception {
        int width = mode == Mode.SMOKE ? 160 : 1920;
        int height = mode == Mode.SMOKE ? 90 : 1080;
        int frames = switch (mode) {
            case SMOKE -> 8;
            case QUICK -> 16;
            case FULL -> 48;
        };
        List<String> files = switch (mode) {
            case SMOKE -> List.of("c1.xml");
            case QUICK -> List.of("meadow.xml");
            case FULL -> List.of("meadow.xml", "large.xml");
        };
        List<String> headers = new ArrayList<>();
        headers.add("scene");
        for (PassTimes.Pass p : PassTimes.Pass.values()) {
            headers.add(p.name().toLowerCase(Locale.ROOT).replace('_', ' ') + " ms");
        }
        headers.add("sum of passes ms");
        headers.add("whole frame ms");
        headers.add("sum / whole");
        headers.add("frame CPU ms");
        Table t = new Table("render-passes", String.format(Locale.ROOT, "GPU time per pass: %dx%d, each scene's "
                + "camera walk, 4 samples, median (95th percentile)", width, height), headers);
        String how = "";
        try (GlContext gl = GlContext.headless(DebugOutput.OFF);
             GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), width, height, 4)) {
            report.glRenderer(gl.describe());
            how = org.jecosys.render.gl.SoftwareGl.is(gl.describe())
                    ? "the clock around glFinish after each pass (a software rasteriser: its timer queries do not"
                    + " time passes)" : "GL_TIME_ELAPSED queries read four frames later, never waited for";
            // on a GPU both resolve paths, so that the per-pass times show what the resolve costs on each
            boolean gpu = !org.jecosys.render.gl.SoftwareGl.is(gl.describe());
            List<ResolvePath> paths = gpu && ResolvePath.COMPUTE.supported(gl.capabilities())
                    ? List.of(ResolvePath.COMPUTE, ResolvePath.TRANSFORM_FEEDBACK) : List.of(ResolvePath.best(gl));
            for (String file : files) {
                for (ResolvePath path : paths) {
                    Scene scene = SceneFiles.read(scenes.resolve(file));
                    try (Simulation sim = Scenes.simulation(scene, 0, Progress.NONE)) {
                        if (quality != null) {
                            quality.applyTo(sim);
                        }
                        RenderSettings settings = RenderSettings.of(scene.def().render());
                        settings.setClear(true);
                        settings.setTerrain(true);
                        CameraWalk walk = new CameraWalk(scene.def().camera(), sim.world().terrain().heightfield(),
                                width / (double) height);
                        try (SceneRenderer r = new SceneRenderer(gl, sim.world(), settings, path)) {
                            r.setPassTiming(true);
                            int passes = PassTimes.Pass.values().length;
                            double[][] per = new double[passes][frames * 2];
                            double[] sums = new double[frames * 2];
                            double[] wholes = new double[frames * 2];
                            double[] cpus = new double[frames * 2];
                            int nc = 0;
                            int np = 0;
                            int nw = 0;
                            long seenPass = 0;
                            long seenWhole = 0;
                            fb.bind();
                            // 4 frames more at each end: the queries' latency
                            for (int i = 0; i < frames + 2 * 4; i++) {
                                ViewCamera cam = walk.at(i * DT);
                                sim.step(DT, cam);
                                long c0 = ProcessCpu.nanos();
                                r.render(sim.latestFrame(), cam, width, height);
                                long c1 = ProcessCpu.nanos();
                                if (i >= 4 && i < frames + 4 && c0 >= 0) {
                                    cpus[nc++] = (c1 - c0) / 1e6;
                                }
                                PassTimes pt = r.passTimes();
                                if (pt.passFrames() > seenPass && i >= 4) {
                                    for (PassTimes.Pass p : PassTimes.Pass.values()) {
                                        per[p.ordinal()][np] = pt.nanos(p) / 1e6;
                                    }
                                    sums[np++] = pt.passSumNanos() / 1e6;
                                }
                                if (pt.wholeFrames() > seenWhole && i >= 4) {
                                    wholes[nw++] = pt.frameNanos() / 1e6;
                                }
                                seenPass = pt.passFrames();
                                seenWhole = pt.wholeFrames();
                            }
                            List<Object> row = new ArrayList<>();
                            row.add(file + " (" + path.name().toLowerCase(Locale.ROOT).replace('_', ' ') + ")");
                            double sumOfMedians = 0;
                            for (int p = 0; p < passes; p++) {
                                double[] v = Arrays.copyOf(per[p], np);
                                double m = Stats.median(v);
                                sumOfMedians += m;
                                row.add(String.format(Locale.ROOT, "%.2f (%.2f)", m, Stats.percentile(v, 95)));
                                report.raw("render passes / " + file + " / " + path + " / "
                                        + PassTimes.Pass.values()[p], v);
                            }
                            double whole = Stats.median(Arrays.copyOf(wholes, nw));
                            row.add(String.format(Locale.ROOT, "%.2f", sumOfMedians));
                            row.add(String.format(Locale.ROOT, "%.2f", whole));
                            row.add(String.format(Locale.ROOT, "%.3f", sumOfMedians / whole));
                            double[] cpu = Arrays.copyOf(cpus, nc);
                            row.add(nc == 0 ? "n/a" : String.format(Locale.ROOT, "%.2f (%.2f)", Stats.median(cpu),
                                    Stats.percentile(cpu, 95)));
                            if (nc > 0) {
                                report.raw("render passes / " + file + " / " + path + " / frame CPU", cpu);
                            }
                            t.row(row.toArray());
                            report.raw("render passes / " + file + " / " + path + " / whole frame",
                                    Arrays.copyOf(wholes, nw));
                        }
                    }
                }
            }
            double plain = resolveMillis(gl, fb, 0);
            double temporal = resolveMillis(gl, fb, 16);
            t.note(String.format(Locale.ROOT, "The framebuffer's resolve after the passes (not in the table; the clock "
                    + "around glFinish, median of %d): the one-frame filter %.2f ms, with temporal accumulation (16 "
                    + "frames; a depth blit and one full-screen pass) %.2f ms.", RESOLVES, plain, temporal));
            t.note("GL renderer: " + gl.describe() + ". Timed by " + how + ". Each pass: ground maps (the splatted"
                    + " shadow and contact darkening, when they change), resolve (the near plants' lists, uploads and"
                    + " per-component pass), shadow map (the shadow-map path only), near plants, cover, ground"
                    + " (terrain), sky, far plants (line levels), overlays. Every fourth timed frame is measured whole"
                    + " instead; \"sum / whole\" compares the passes' medians summed with it. Frame CPU: the"
                    + " process's CPU time over each frame's draw calls, every thread counted (on a software rasteriser"
                    + " its threads do the GPU's work; the host's other tenants do not count; the JVM reads it in steps of"
                    + " 10 ms on Linux), median of every timed frame.");
        }
        report.add(t);
    }

    /** Resolves timed by {@link #resolveMillis}. */
    private static final int RESOLVES = 15;

    /**
     * The median time of the framebuffer's resolve with temporal accumulation of {@code frames} frames (0:
     * off), by the clock around glFinish; whatever the framebuffer holds is resolved again and again.
     */
    private static double resolveMillis(GlContext gl, GlFramebuffer fb, int frames) {
        fb.setAccumulation(frames);
        ViewCamera still = new ViewCamera();
        double[] ms = new double[RESOLVES];
        for (int i = 0; i < RESOLVES + 4; i++) {
            fb.jittered(still, true);
            gl.finish();
            long t0 = System.nanoTime();
            fb.resolve();
            gl.finish();
            if (i >= 4) {
                ms[i - 4] = (System.nanoTime() - t0) / 1e6;
            }
            fb.bind();
        }
        fb.setAccumulation(0);
        return Stats.median(ms);
    }
}
