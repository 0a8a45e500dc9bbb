package org.jecosys.bench;

import org.jecosys.render.gl.GlContexts;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.jecosys.anim.AnimationMode;
import org.jecosys.math.Progress;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.SceneRenderer;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.World;

/**
 * Tables 5, 6 and 7 of the paper (section 5.2) for scenes C1-C3 (and the meadow in a full run):
 * the camera walks each scene's path; each frame is one fixed simulation step (field update and
 * animation), and in the rendered variant also a headless 1280x720 frame on this machine's GL
 * (finished before the clock stops). Configurations: S1 static, S2 random, S3 constraint (field
 * on; Table 7), random with the field off (Table 6's "frame rate 2"). The four configurations of a
 * scene run side by side and take turns in short blocks (see {@link FrameRun#measure}), so that the
 * machine's drift over a run does not decide their ratios.
 */
final class PaperScenesSection implements Section {
    static final int WIDTH = 1280;
    static final int HEIGHT = 720;
    private static final String[] NAMES = {"C1", "C2", "C3", "Meadow"};
    private static final String[] FILES = {"c1.xml", "c2.xml", "c3.xml", "meadow.xml"};
    /** Frames per turn when the four configurations take turns (see {@link FrameRun#measure}). */
    private static final int SIM_BLOCK = 200;
    private static final int RENDER_BLOCK = 8;

    private final Path scenes;

    PaperScenesSection(Path scenes) {
        this.scenes = scenes;
    }

    @Override
    public String name() {
        return "Tables 5-7 (frame rates while walking C1-C3)";
    }

    @Override
    public List<String> charts() {
        return List.of("table7.png");
    }

    /** The four runs of one scene in one variant (simulation only, or rendered). */
    record Runs(FrameRun s1, FrameRun s2, FrameRun s3, FrameRun fieldOff) {
    }

    @Override
    public void run(Mode mode, Report report) throws Exception {
        int count = mode == Mode.FULL ? 4 : mode == Mode.SMOKE ? 1 : 3;
        int simWarm = mode == Mode.SMOKE ? 5 : mode == Mode.QUICK ? 600 : 2000;
        int simFrames = mode == Mode.SMOKE ? 10 : mode == Mode.QUICK ? 3000 : 12000;
        int renderWarm = mode == Mode.SMOKE ? 2 : mode == Mode.QUICK ? 40 : 120;
        int renderFrames = mode == Mode.SMOKE ? 4 : mode == Mode.QUICK ? 240 : 900;
        List<Runs> sim = new ArrayList<>();
        List<Runs> rendered = new ArrayList<>();
        List<SceneDef> defs = new ArrayList<>();
        List<World> worlds = new ArrayList<>();
        for (int s = 0; s < count; s++) {
            SceneDef scene = SceneFiles.parse(scenes.resolve(FILES[s]));
            World world = World.build(scene.simulationDef(), scenes, 2, Progress.NONE);
            defs.add(scene);
            worlds.add(world);
            sim.add(runs(scene, world, simWarm, simFrames, null, null));
        }
        String renderProblem = null;
        try (GlContext gl = GlContext.headless(DebugOutput.OFF)) {
            report.glRenderer(gl.describe());
            try (GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), WIDTH, HEIGHT)) {
                for (int s = 0; s < count; s++) {
                    SceneDef scene = defs.get(s);
                    RenderSettings settings = RenderSettings.standalone();
                    settings.lighting().setSky(scene.render().sky());
                    try (SceneRenderer renderer = new SceneRenderer(gl, worlds.get(s), settings)) {
                        fb.bind();
                        int frames = s == 3 ? Math.max(2, renderFrames / 4) : renderFrames;
                        rendered.add(runs(scene, worlds.get(s), renderWarm, frames, gl, renderer));
                    }
                }
            }
        } catch (RuntimeException | LinkageError e) {
            renderProblem = "rendering was not possible here: " + e.getMessage();
        }
        table5(report, sim, rendered, count, renderProblem);
        table6(report, sim, "simulation only", "6a");
        table7(report, sim, "simulation only", "7a");
        if (!rendered.isEmpty()) {
            table6(report, rendered, "rendered at " + WIDTH + "x" + HEIGHT, "6b");
            table7(report, rendered, "rendered at " + WIDTH + "x" + HEIGHT, "7b");
        }
        report.raw("paperScenes", raw(sim, rendered, count));
        chart(report, sim, rendered);
    }

    private static Runs runs(SceneDef scene, World world, int warm, int frames, GlContext gl, SceneRenderer r) {
        AnimationMode[] modes = {AnimationMode.STATIC, AnimationMode.RANDOM, AnimationMode.CONSTRAINT,
            AnimationMode.RANDOM};
        boolean[] fields = {true, true, true, false};
        FrameRun[] f = FrameRun.measure(scene, world, modes, fields, warm, frames, r == null ? SIM_BLOCK : RENDER_BLOCK,
                gl, r, WIDTH, HEIGHT);
        return new Runs(f[0], f[1], f[2], f[3]);
    }

    private static String paperFps(double[] row, int at) {
        return FrameRun.pm(row[at], row[at + 1]);
    }

    private static void table5(Report report, List<Runs> sim, List<Runs> rendered, int count, String problem) {
        Table t = new Table("table5", "Table 5: performance against geometrical complexity (field and animation on)",
                List.of("scene", "paper ~triangles", "here ~triangles", "paper ~lines", "here ~lines", "paper fps",
                        "here fps, simulation only", "here fps, rendered", "components animated"));
        for (int s = 0; s < count; s++) {
            double[] p = s < 3 ? PaperNumbers.TABLE5[s] : null;
            Runs r = rendered.size() > s ? rendered.get(s) : null;
            t.row(NAMES[s], p == null ? null : p[0], r == null ? null : r.s3().triangles, p == null ? null : p[1],
                    r == null ? null : r.s3().lines, p == null ? "-" : paperFps(p, 2), sim.get(s).s3().fpsText(),
                    r == null ? "-" : r.s3().fpsText(), sim.get(s).s3().componentsAnimated);
        }
        t.note("Mean ± standard deviation over the frames of the walk; one frame = one fixed step (field update and "
                + "dynamic-constraint animation), plus a finished " + WIDTH + "x" + HEIGHT + " headless frame in the "
                + "rendered column. Primitives are those submitted per rendered frame.");
        if (problem != null) {
            t.note(problem);
        }
        report.add(t);
    }

    private static void table6(Report report, List<Runs> runs, String variant, String id) {
        Table t = new Table("table" + id, "Table 6: force-field performance (" + variant + ", random animation)",
                List.of("scene", "paper update ms", "here update ms", "paper fps field on", "here fps field on",
                        "paper fps field off", "here fps field off", "paper on/off", "here on/off"));
        for (int s = 0; s < runs.size(); s++) {
            double[] p = s < 3 ? PaperNumbers.TABLE6[s] : null;
            Runs r = runs.get(s);
            t.row(NAMES[s], p == null ? "-" : FrameRun.pm(p[0], p[1]),
                    FrameRun.pm(Stats.mean(r.s2().fieldMs), Stats.sd(r.s2().fieldMs)),
                    p == null ? "-" : paperFps(p, 2), r.s2().fpsText(), p == null ? "-" : paperFps(p, 4),
                    r.fieldOff().fpsText(), p == null ? null : p[2] / p[4], r.s2().fpsMean() / r.fieldOff().fpsMean());
        }
        t.note("Frame rate 1: field active; frame rate 2: field disabled (no flow evaluated, no culling: every plant "
                + "animated), both in random animation as in the paper. The paper's on/off ratios are 0.94-0.96; "
                + "the target here is at least 0.98.");
        report.add(t);
    }

    private static void table7(Report report, List<Runs> runs, String variant, String id) {
        Table t = new Table("table" + id, "Table 7: animation algorithm performance (" + variant + ", field on)",
                List.of("scene", "paper S1", "here S1", "paper S2", "here S2", "paper S3", "here S3", "paper S3/S1",
                        "here S3/S1"));
        for (int s = 0; s < runs.size(); s++) {
            double[] p = s < 3 ? PaperNumbers.TABLE7[s] : null;
            Runs r = runs.get(s);
            t.row(NAMES[s], p == null ? "-" : paperFps(p, 0), r.s1().fpsText(), p == null ? "-" : paperFps(p, 2),
                    r.s2().fpsText(), p == null ? "-" : paperFps(p, 4), r.s3().fpsText(),
                    p == null ? null : p[4] / p[0], r.s3().fpsMean() / r.s1().fpsMean());
        }
        t.note("S1 static scene (user movement only), S2 random animation, S3 the framework's dynamic-constraint "
                + "animation. The paper's S3/S1 ratios are 0.50-0.67; the target here is at least 0.95.");
        report.add(t);
    }

    private static Map<String, Object> raw(List<Runs> sim, List<Runs> rendered, int count) {
        Map<String, Object> m = new LinkedHashMap<>();
        for (int s = 0; s < count; s++) {
            Map<String, Object> scene = new LinkedHashMap<>();
            scene.put("simulation", runMap(sim.get(s)));
            if (rendered.size() > s) {
                scene.put("rendered", runMap(rendered.get(s)));
            }
            m.put(NAMES[s], scene);
        }
        return m;
    }

    private static Map<String, Object> runMap(Runs r) {
        Map<String, Object> m = new LinkedHashMap<>();
        String[] keys = {"S1", "S2", "S3", "randomFieldOff"};
        FrameRun[] runs = {r.s1(), r.s2(), r.s3(), r.fieldOff()};
        for (int i = 0; i < 4; i++) {
            Map<String, Object> x = new LinkedHashMap<>();
            x.put("fpsMean", runs[i].fpsMean());
            x.put("fpsSd", runs[i].fpsSd());
            x.put("frameMsMedian", Stats.median(runs[i].frameMs));
            x.put("fieldMsMean", Stats.mean(runs[i].fieldMs));
            x.put("fieldMsSd", Stats.sd(runs[i].fieldMs));
            x.put("triangles", runs[i].triangles);
            x.put("lines", runs[i].lines);
            x.put("componentsAnimated", runs[i].componentsAnimated);
            m.put(keys[i], x);
        }
        return m;
    }

    private static void chart(Report report, List<Runs> sim, List<Runs> rendered) throws java.io.IOException {
        if (rendered.isEmpty()) {
            return;
        }
        Table t = new Table("chart7", "Table 7, rendered at " + WIDTH + "x" + HEIGHT + ": fps",
                List.of("scene", "paper S1", "here S1", "paper S3", "here S3"));
        for (int s = 0; s < Math.min(3, rendered.size()); s++) {
            t.row(NAMES[s], PaperNumbers.TABLE7[s][0], rendered.get(s).s1().fpsMean(), PaperNumbers.TABLE7[s][4],
                    rendered.get(s).s3().fpsMean());
        }
        report.saveChart("table7.png", png -> Charts.bars(t, 0, List.of("paper S1", "here S1", "paper S3", "here S3"), "frames per second", png));
    }
}
