package org.jecosys.bench;

import org.jecosys.render.internal.SceneParts;
import org.jecosys.render.gl.GlContexts;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.GpuWork;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.ResolvePath;
import org.jecosys.render.SceneRenderer;
import org.jecosys.render.ShadowPath;
import org.jecosys.render.ground.SunShadowMap;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.CameraWalk;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.ViewDecision;

/**
 * Render scale: frames of the meadow (417,004 components), large (1,000,000) and prairie (about
 * 4,000,000) at 1920x1080 with the camera walking each scene's path, one fixed step per frame: frames
 * per second, frame time (step, render and the GPU finishing), the render thread's CPU time inside
 * {@link SceneRenderer#render} (what the library costs the thread that submits; on a software
 * rasteriser it includes the driver's vertex work), bytes uploaded per frame, components drawn, the
 * plants' instanced draw calls (what a hardware driver's submit cost grows with), and the GL renderer
 * and path: each scene on every {@link ResolvePath} the context supports, the one
 * a renderer takes by itself first. A smoke run renders the meadow only, small. A second table switches
 * the meadow's wind sheen and sun shadows on and off ({@link #looks}).
 */
final class RenderScaleSection implements Section {
    private static final String[] FILES = {"meadow.xml", "large.xml", "prairie.xml"};
    private static final double DT = 1 / 30.0;

    private final Path scenes;
    private final org.jecosys.sim.DrawQuality quality;

    RenderScaleSection(Path scenes, org.jecosys.sim.DrawQuality quality) {
        this.scenes = scenes;
        this.quality = quality;
    }

    @Override
    public String name() {
        return "render scale (meadow, large, prairie at 1920x1080)";
    }

    @Override
    public void run(Mode mode, Report report) throws Exception {
        boolean smoke = mode == Mode.SMOKE;
        int width = smoke ? 320 : 1920;
        int height = smoke ? 180 : 1080;
        int count = smoke ? 1 : FILES.length;
        int warm = smoke ? 1 : mode == Mode.QUICK ? 3 : 10;
        int frames = smoke ? 2 : mode == Mode.QUICK ? 8 : 40;
        Table t = new Table("render-scale", "Render scale: " + width + "x" + height + ", camera walking, 1/30 s of "
                + "simulation per frame", java.util.List.of("scene", "components", "drawn (median)", "fps",
                "frame ms (median)", "frame ms (p90)", "ms per fixed step", "render-thread CPU ms", "of which lists and records, Java ms",
                "2nd view: decision, lists and records, Java ms", "KiB uploaded / frame", "plant draw calls",
                "VS invocations / frame", "FS invocations / frame", "primitives / frame", "fragments / pixel",
                "path", "upload ring waits"));
        Map<String, Object> raw = new LinkedHashMap<>();
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        Table stepOnlyTable = null;
        Table looksTable;
        try (GlContext gl = GlContext.headless(DebugOutput.OFF);
             GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), width, height)) {
            report.glRenderer(gl.describe());
            ResolvePath best = ResolvePath.best(gl);
            java.util.List<ResolvePath> paths = new java.util.ArrayList<>(java.util.List.of(best));
            for (ResolvePath p : ResolvePath.values()) {
                if (p != best && p.supported(gl.capabilities())) {
                    paths.add(p);
                }
            }
            StringBuilder skipped = new StringBuilder();
            for (int s = 0; s < count; s++) {
                SceneDef def = SceneFiles.parse(scenes.resolve(FILES[s]));
                try (Simulation sim = Simulation.create(def.simulationDef(), scenes, 0, Progress.NONE)) {
                    sim.setLodTransition(def.render().lodTransition());
                    if (quality != null) {
                        quality.applyTo(sim);
                    }
                    if (s == 0) {
                        stepOnlyTable = stepOnly(def, sim, smoke ? 4 : mode == Mode.QUICK ? 120 : 240, raw);
                    }
                    for (ResolvePath path : paths) {
                        SceneRenderer r;
                        try {
                            RenderSettings settings = RenderSettings.standalone();
                            settings.lighting().setSky(def.render().sky());
                            r = new SceneRenderer(gl, sim.world(), settings, path);
                        } catch (IllegalArgumentException e) {
                            // a path the context cannot run for this scene (a storage buffer too small)
                            skipped.append(" ").append(def.name()).append(" not on ").append(path.name())
                                    .append(": ").append(e.getMessage()).append('.');
                            continue;
                        }
                        try (r; GpuWork work = new GpuWork(gl)) {
                            measure(gl, def, sim, r, work, fb, t, raw, width, height, warm, frames, threads);
                        }
                    }
                }
            }
            t.note("GL renderer: " + gl.describe() + ". Frame = the fixed steps of 1/30 s of simulation (two of"
                    + " the scenes' 1/60 s) + render + glFinish; ms per fixed step = their time over their count"
                    + " (the steps run right after the rasteriser, caches cold); render-thread CPU"
                    + " = the calling thread's CPU time inside SceneRenderer.render (on a software rasteriser it"
                    + " includes the driver's vertex processing); of which the library's Java work: building the draw lists"
                    + " from the frame's decision and writing the instance records; a second view adds its own decision"
                    + " (a camera turned a quarter to the side). GPU work of the frame (terrain, sky and plants),"
                    + " counted by pipeline-statistics queries (ARB_pipeline_statistics_query): vertex and fragment"
                    + " shader invocations and the primitives entering clipping; fragments per pixel = fragment"
                    + " invocations / (width x height). Uploads: 8 bytes per component of the drawn plants'"
                    + " range (its deviation D, X and Z, written by the animation workers) plus 8 bytes per drawn"
                    + " plant and level. Plant draw calls: the instanced draws of the plants (per species and level,"
                    + " one for the plants drawn whole and one for those in a transition band). Upload ring waits:"
                    + " the frames of the whole run (warm-up included) that found their region of the persistently"
                    + " mapped upload ring still read by the GPU and waited (\"no ring\" without buffer storage)."
                    + " Each scene runs on"
                    + " every resolve path the context supports, the one a renderer takes by itself first." + skipped);
            // in the same context: a second headless context in one process after the first was closed
            // drew nothing on NVIDIA's EGL (every count 0)
            looksTable = looks(gl, fb, width, height, smoke ? 1 : 2, smoke ? 1 : mode == Mode.QUICK ? 4 : 12, raw);
        }
        report.add(t);
        if (stepOnlyTable != null) {
            report.add(stepOnlyTable);
        }
        report.add(looksTable);
        report.raw("renderScale", raw);
    }

    /**
     * The first scene's (the meadow's) fixed step along the same walk without rendering: what the
     * simulation costs a game whose GPU draws, free of a software rasteriser's threads and of the cache
     * misses its frames cause. The walk starts where the rendered one began; the simulation's
     * own workers. Allocates (a table).
     */
    private static Table stepOnly(SceneDef def, Simulation sim, int frames, Map<String, Object> raw) {
        CameraWalk walk = new CameraWalk(def.camera(), sim.world().terrain().heightfield(), 16 / 9.0);
        // the first frames of the walk twice, the first pass to warm up: run alone (--only
        // "render scale") the JIT is still compiling the step's loops after a few frames; the second
        // pass walks the same path (the simulation goes on), so the figure does not depend on how many
        // frames the rendered walk had
        int n0 = frames;
        double[] ms = new double[n0];
        for (int i = 0; i < 2 * n0; i++) {
            ViewCamera cam = walk.at((i % n0) * DT);
            long t0 = System.nanoTime();
            int n = Math.max(1, sim.step(DT, cam));
            long t1 = System.nanoTime();
            if (i >= n0) {
                ms[i - n0] = (t1 - t0) / 1e6 / n;
            }
        }
        Table t = new Table("render-scale-step", def.name() + ": fixed step along the walk, simulation only",
                java.util.List.of("workers", "fixed steps", "ms per fixed step (median)", "ms per fixed step (p90)"));
        t.row(sim.inspect().workers(), (long) (frames * Math.round(DT / sim.inspect().fixedStep())), Stats.median(ms),
                Stats.percentile(ms, 0.9));
        t.note("The camera walks the first " + n0 + " frames of the render-scale path twice (1/30 s of"
                + " simulation per frame, in fixed steps of " + sim.inspect().fixedStep()
                + " s), the first time to warm"
                + " up; nothing is drawn. Target (issue 28): at most 2 ms per fixed step with 2 workers.");
        raw.put("stepOnly / " + def.name(), ms);
        return t;
    }

    /**
     * What the wind's sheen and the sun shadows cost: the meadow with its own look ({@code <render>}:
     * ground cover, sheen, shadows) from its start camera after the wind has blown for a second, the
     * sheen on and off, the shadows on each path ({@link ShadowPath#GROUND}, {@link ShadowPath#MAP}) and
     * off: frame time (render + glFinish) and the frame's GPU work by pipeline statistics.
     */
    private Table looks(GlContext gl, GlFramebuffer fb, int width, int height, int warm, int frames,
                        Map<String, Object> raw) throws Exception {
        Table t = new Table("render-looks", "The meadow's look switched: " + width + "x" + height + ", start camera",
                java.util.List.of("sheen", "sun shadows", "frame ms (median)", "VS invocations / frame",
                        "FS invocations / frame", "primitives / frame", "fragments / pixel"));
        SceneDef def = SceneFiles.parse(scenes.resolve(FILES[0]));
        try (Simulation sim = Simulation.create(def.simulationDef(), scenes, 0, Progress.NONE)) {
            ViewCamera cam = ViewCamera.of(def.camera(), sim.world().terrain().heightfield().height(def.camera().x(),
                    def.camera().z()), width / (double) height);
            for (int i = 0; i < 30; i++) {
                sim.stepFixed(cam);
            }
            Frame f = sim.latestFrame();
            RenderSettings settings = RenderSettings.of(def.render());
            settings.setClear(true);
            settings.setTerrain(true);
            float sheen = settings.sheen();
            float shadows = settings.shadows() > 0 ? settings.shadows() : 0.6f;
            try (SceneRenderer r = new SceneRenderer(gl, sim.world(), settings); GpuWork work = new GpuWork(gl)) {
                fb.bind();
                // sheen on and off; shadows on the ground path, on the map's path (the plants drawn a
                // second time, from the sun) and off
                ShadowPath[] paths = {ShadowPath.GROUND, ShadowPath.MAP, null, ShadowPath.GROUND, null};
                for (int v = 0; v < paths.length; v++) {
                    boolean on = v < 3;
                    boolean shade = paths[v] != null;
                    settings.setSheen(on ? sheen : 0f);
                    settings.setShadows(shade ? shadows : 0f);
                    settings.setShadowPath(shade ? paths[v] : ShadowPath.AUTO);
                    String shadowName = shade ? paths[v] == ShadowPath.MAP ? "map" : "ground" : "off";
                    double[] ms = new double[frames];
                    double[] vs = new double[frames];
                    double[] fs = new double[frames];
                    double[] prims = new double[frames];
                    for (int i = 0; i < warm + frames; i++) {
                        long t0 = System.nanoTime();
                        r.render(f, cam, width, height);
                        gl.finish();
                        long t1 = System.nanoTime();
                        work.begin();
                        r.render(f, cam, width, height);
                        work.end();
                        int k = i - warm;
                        if (k >= 0) {
                            ms[k] = (t1 - t0) / 1e6;
                            vs[k] = work.vertexInvocations();
                            fs[k] = work.fragmentInvocations();
                            prims[k] = work.primitives();
                        }
                    }
                    t.row(on ? "on" : "off", shadowName, Stats.median(ms), (long) Stats.median(vs),
                            (long) Stats.median(fs), (long) Stats.median(prims),
                            Stats.median(fs) / ((double) width * height));
                    raw.put("looks / sheen " + (on ? "on" : "off") + " / shadows " + shadowName, ms);
                }
            }
            t.note("GL renderer: " + gl.describe() + ". The meadow's frame after 30 steps from its start camera, drawn"
                    + " with its own <render> settings; sheen " + sheen + ", shadows " + shadows + " when on."
                    + " Shadows \"ground\": the splat of the plants' rest poses, rebuilt when switched on (during"
                    + " the warm-up frames), then read as one more texture channel, no extra pass; \"map\": the"
                    + " plants resolved for the view drawn again from the sun into a " + SunShadowMap.DEFAULT_SIZE
                    + "-texel depth map every frame (the counts include that pass), read per fragment by the"
                    + " plants and the terrain. Frame = render + glFinish; GPU work counted apart by"
                    + " pipeline-statistics queries.");
        }
        return t;
    }

    /** Frames of one scene with one renderer: a row of {@code t} and the raw series. */
    private static void measure(GlContext gl, SceneDef def, Simulation sim, SceneRenderer r, GpuWork work,
                                GlFramebuffer fb, Table t, Map<String, Object> raw, int width, int height, int warm,
                                int frames, ThreadMXBean threads) {
        CameraWalk walk = new CameraWalk(def.camera(), sim.world().terrain().heightfield(),
                width / (double) height);
        double[] frameMs = new double[frames];
        double[] stepMs = new double[frames];
        double[] cpuMs = new double[frames];
        double[] uploaded = new double[frames];
        double[] drawn = new double[frames];
        double[] javaMs = new double[frames];
        double[] draws = new double[frames];
        double[] secondMs = new double[frames];
        double[] vertices = new double[frames];
        double[] fragments = new double[frames];
        double[] primitives = new double[frames];
        ViewDecision second = new ViewDecision(sim.world());
        ViewCamera side = new ViewCamera();
        java.nio.IntBuffer scratch = java.nio.IntBuffer.allocate(
                2 * Math.max(1, SceneParts.plants(r).batches().maxInstances()));
        fb.bind();
        for (int i = 0; i < warm + frames; i++) {
            ViewCamera cam = walk.at(i * DT);
            long t0 = System.nanoTime();
            int fixedSteps = Math.max(1, sim.step(DT, cam));
            long t1 = System.nanoTime();
            Frame f = sim.latestFrame();
            long c0 = threads.getCurrentThreadCpuTime();
            r.render(f, cam, width, height);
            long c1 = threads.getCurrentThreadCpuTime();
            gl.finish();
            long t2 = System.nanoTime();
            // the GPU work of the same frame, counted apart (the queries' read-back waits), not timed
            work.begin();
            r.render(f, cam, width, height);
            work.end();
            int k = i - warm;
            if (k >= 0) {
                frameMs[k] = (t2 - t0) / 1e6;
                stepMs[k] = (t1 - t0) / 1e6 / fixedSteps;
                cpuMs[k] = (c1 - c0) / 1e6;
                uploaded[k] = r.uploadedBytes() / 1024.0;
                drawn[k] = r.drawnComponents();
                draws[k] = r.drawCalls();
                // the library's own per-frame Java work, apart from the driver: lists from the
                // frame's decision and the instance records (done again here, timed alone)
                long j0 = threads.getCurrentThreadCpuTime();
                SceneParts.plants(r).batches().update(f);
                SceneParts.plants(r).batches().writeInstances(scratch);
                javaMs[k] = (threads.getCurrentThreadCpuTime() - j0) / 1e6;
                // a second view (turned a quarter to the side): its own decision, then lists and records
                side.set(cam).setOrientation(cam.yaw() + Math.PI / 2, cam.pitch());
                long v0 = threads.getCurrentThreadCpuTime();
                second.decide(f, side);
                SceneParts.plants(r).batches().update(f, second.levels(), second.keeps());
                SceneParts.plants(r).batches().writeInstances(scratch);
                secondMs[k] = (threads.getCurrentThreadCpuTime() - v0) / 1e6;
                vertices[k] = work.vertexInvocations();
                fragments[k] = work.fragmentInvocations();
                primitives[k] = work.primitives();
            }
        }
        double median = Stats.median(frameMs);
        t.row(def.name(), sim.componentCount(), (long) Stats.median(drawn), 1000 / median, median,
                Stats.percentile(frameMs, 0.9), Stats.median(stepMs), Stats.median(cpuMs),
                Stats.median(javaMs), Stats.median(secondMs), Stats.median(uploaded), (long) Stats.median(draws),
                (long) Stats.median(vertices), (long) Stats.median(fragments), (long) Stats.median(primitives),
                Stats.median(fragments) / ((double) width * height), r.resolvePath().description(),
                r.uploadRing() ? Long.toString(r.uploadWaits()) : "no ring");
        Map<String, Object> series = new LinkedHashMap<>();
        series.put("frameMs", frameMs);
        series.put("stepMs", stepMs);
        series.put("renderCpuMs", cpuMs);
        series.put("uploadedKiB", uploaded);
        series.put("drawnComponents", drawn);
        series.put("listsAndRecordsJavaMs", javaMs);
        series.put("plantDrawCalls", draws);
        series.put("secondViewJavaMs", secondMs);
        series.put("vertexInvocations", vertices);
        series.put("fragmentInvocations", fragments);
        series.put("primitives", primitives);
        series.put("uploadRingWaits", r.uploadRing() ? r.uploadWaits() : -1L);
        raw.put(def.name() + " / " + r.resolvePath().name(), series);
    }
}
