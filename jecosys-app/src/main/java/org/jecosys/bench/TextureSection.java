package org.jecosys.bench;

import java.nio.file.Path;
import java.util.Locale;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.GpuWork;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.SceneRenderer;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;

/**
 * What textures on components cost (issue 40): the meadow and the textured meadow ({@code textured.xml},
 * the same plants with images on their blades, petals and heads) from the same start camera, each frame
 * after 30 steps, drawn in alternating rounds so that both see the same machine: frame time (render +
 * finish) median, draw calls, fragment-shader invocations (pipeline-statistics queries, counted apart)
 * and the bytes the render thread allocates per frame after warm-up.
 */
final class TextureSection implements Section {
    private final Path scenes;

    TextureSection(Path scenes) {
        this.scenes = scenes;
    }

    @Override
    public String name() {
        return "textures";
    }

    @Override
    public void run(Mode mode, Report report) throws Exception {
        int width = mode == Mode.SMOKE ? 160 : 1920;
        int height = mode == Mode.SMOKE ? 90 : 1080;
        int rounds = switch (mode) {
            case SMOKE -> 1;
            case QUICK -> 6;
            case FULL -> 15;
        };
        int perRound = 3;
        Scene[] loaded = new Scene[2];
        String[] files = {"meadow.xml", "textured.xml"};
        if (mode == Mode.SMOKE) {
            // seconds, not the meadow's build twice: C1, and C1 with its grass textured (read from memory)
            String c1 = java.nio.file.Files.readString(scenes.resolve("c1.xml"));
            byte[] blade = java.nio.file.Files.readAllBytes(scenes.resolve("textures/grass-blade.png"));
            loaded[0] = SceneFiles.read(scenes.resolve("c1.xml"));
            loaded[1] = SceneFiles.read(new java.io.ByteArrayInputStream(c1.replace("colour=\"#4f8a2b\"",
                    "colour=\"#4f8a2b\" texture=\"textures/grass-blade.png\"").getBytes(
                    java.nio.charset.StandardCharsets.UTF_8)), "c1-textured.xml",
                    org.jecosys.terrain.ImageSource.of(java.util.Map.of("textures/grass-blade.png", blade)));
            files = new String[] {"c1.xml", "c1-textured.xml"};
        } else {
            loaded[0] = SceneFiles.read(scenes.resolve(files[0]));
            loaded[1] = SceneFiles.read(scenes.resolve(files[1]));
        }
        Table t = new Table("textures", String.format(Locale.ROOT, "Textured components: the meadow with and without "
                + "its images, %dx%d, start camera, 4 samples", width, height),
                java.util.List.of("scene", "frame ms (median)", "draw calls", "FS invocations / frame",
                        "bytes allocated / frame", "frame vs meadow", "FS vs meadow"));
        java.lang.management.ThreadMXBean threads = java.lang.management.ManagementFactory.getThreadMXBean();
        com.sun.management.ThreadMXBean alloc = threads instanceof com.sun.management.ThreadMXBean a ? a : null;
        try (GlContext gl = GlContext.headless(DebugOutput.OFF);
             GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), width, height, 4);
             GpuWork work = new GpuWork(gl)) {
            report.glRenderer(gl.describe());
            Simulation[] sims = new Simulation[files.length];
            SceneRenderer[] renderers = new SceneRenderer[files.length];
            Frame[] frames = new Frame[files.length];
            ViewCamera[] cams = new ViewCamera[files.length];
            try {
                for (int k = 0; k < files.length; k++) {
                    Scene scene = loaded[k];
                    SceneDef def = scene.def();
                    sims[k] = Scenes.simulation(scene, 0, Progress.NONE);
                    cams[k] = ViewCamera.of(def.camera(), sims[k].world().terrain().heightfield().height(
                            def.camera().x(), def.camera().z()), width / (double) height);
                    for (int i = 0; i < 30; i++) {
                        sims[k].stepFixed(cams[k]);
                    }
                    frames[k] = sims[k].latestFrame();
                    RenderSettings settings = RenderSettings.of(def.render());
                    settings.setClear(true);
                    settings.setTerrain(true);
                    renderers[k] = new SceneRenderer(gl, sims[k].world(), settings);
                }
                double[][] ms = new double[files.length][rounds * perRound];
                double[] draws = new double[files.length];
                double[] fs = new double[files.length];
                double[] bytes = new double[files.length];
                fb.bind();
                for (int k = 0; k < files.length; k++) { // warm-up, and the counts
                    for (int i = 0; i < 3; i++) {
                        renderers[k].render(frames[k], cams[k], width, height);
                    }
                    gl.finish();
                    long a0 = alloc == null ? 0 : alloc.getCurrentThreadAllocatedBytes();
                    renderers[k].render(frames[k], cams[k], width, height);
                    long a1 = alloc == null ? 0 : alloc.getCurrentThreadAllocatedBytes();
                    bytes[k] = alloc == null ? -1 : a1 - a0;
                    draws[k] = renderers[k].drawCalls();
                    work.begin();
                    renderers[k].render(frames[k], cams[k], width, height);
                    work.end();
                    fs[k] = work.fragmentInvocations();
                }
                for (int r = 0; r < rounds; r++) {
                    for (int k = 0; k < files.length; k++) {
                        for (int i = 0; i < perRound; i++) {
                            long t0 = System.nanoTime();
                            renderers[k].render(frames[k], cams[k], width, height);
                            gl.finish();
                            ms[k][r * perRound + i] = (System.nanoTime() - t0) / 1e6;
                        }
                    }
                }
                double base = Stats.median(ms[0]);
                for (int k = 0; k < files.length; k++) {
                    double m = Stats.median(ms[k]);
                    t.row(files[k], m, (long) draws[k], (long) fs[k], (long) bytes[k], m / base, fs[k] / fs[0]);
                    report.raw("textures / " + files[k] + " / frame ms", ms[k]);
                }
            } finally {
                for (int k = 0; k < files.length; k++) {
                    if (renderers[k] != null) {
                        renderers[k].close();
                    }
                    if (sims[k] != null) {
                        sims[k].close();
                    }
                }
            }
            t.note("GL renderer: " + gl.describe() + ". Each scene's frame after 30 fixed steps from its start camera, "
                    + "drawn with its own <render> settings into a 4-sample framebuffer; " + rounds + " rounds of "
                    + perRound + " frames each, the scenes in turn. Frame = render + glFinish. Draw calls as the "
                    + "renderer counts them; fragment-shader invocations from a pipeline-statistics query around one "
                    + "more frame; bytes from the render thread's allocation counter around one frame after 3 warm-up "
                    + "frames.");
        }
        report.add(t);
    }
}
