package org.jecosys.app;

import org.jecosys.render.gl.GlContexts;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.SceneRenderer;
import org.jecosys.scene.RenderDef;
import org.jecosys.scene.OutputFiles;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.DrawQuality;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.World;
import org.jecosys.terrain.TerrainMaps;
import org.lwjgl.system.MemoryUtil;

/**
 * Renders a scene headless (GLFW null platform + EGL, e.g. Mesa llvmpipe; no X server) to numbered
 * PNG files {@code frame-00001.png ...}, at 30 frames per second of scene time from the scene's
 * start camera; optionally also the water, nutrient and species maps. Used by {@code jecosys render}
 * and by {@code jecosys view} when there is no display. Every file goes through {@link OutputFiles}
 * (atomic, never through a link, never onto a pipe or device); the command checks the names of
 * {@link #outputNames} before the run with an {@link OutputPlan}. The command's thread; allocates.
 */
final class HeadlessRender {
    /** Scene seconds between rendered frames. */
    static final double FRAME_DT = 1.0 / 30;
    /**
     * Frames of temporal accumulation ({@link GlFramebuffer#setAccumulation}) in the viewer, the render
     * command and the gallery, wherever the scene's framebuffer is multisampled: the whole jitter pattern.
     */
    static final int ACCUMULATION = 16;

    /** Turns temporal accumulation on ({@link #ACCUMULATION} frames) when the framebuffer is multisampled. */
    static void accumulate(GlFramebuffer fb) {
        if (fb.samples() > 1) {
            fb.setAccumulation(ACCUMULATION);
        }
    }

    /**
     * Draws a frame held still and resolves it: with accumulation on, as many jittered frames of it as the
     * running mean holds, so that a still picture shows what a view held still would; otherwise once.
     */
    static void drawStill(GlFramebuffer fb, SceneRenderer renderer, Frame frame, org.jecosys.math.Camera camera,
                          int width, int height) {
        for (int i = 0; i < Math.max(1, fb.accumulation()); i++) {
            fb.bind();
            renderer.render(frame, fb.jittered(camera, true), width, height);
            fb.resolve();
        }
    }
    /** Side of the map images, pixels. */
    static final int MAP_SIDE = 512;

    /** The map files {@code --maps} writes. */
    static final List<String> MAPS = List.of("water.png", "nutrients.png", "species.png");

    private HeadlessRender() {
    }

    /** {@return the file name of frame {@code i} (from 1): frame-00001.png} */
    static String frameName(int i) {
        return String.format(Locale.ROOT, "frame-%05d.png", i);
    }

    /** {@return every file name a run of {@code frames} frames writes into its folder, maps included if asked} */
    static List<String> outputNames(int frames, boolean maps) {
        List<String> names = new ArrayList<>(frames + MAPS.size());
        for (int i = 1; i <= frames; i++) {
            names.add(frameName(i));
        }
        if (maps) {
            names.addAll(MAPS);
        }
        return names;
    }

    /** The render settings a scene asks for, with the library's sky and terrain (the whole picture). */
    static RenderSettings settings(RenderDef def) {
        RenderSettings s = RenderSettings.of(def);
        s.setClear(true);
        s.setTerrain(true);
        return s;
    }

    /**
     * Renders {@code frames} frames of a scene into {@code out}. With {@code holdFirst} (the render
     * command's single picture) the first picture is the view held still, as a photograph of that moment
     * (with accumulation on: {@link #ACCUMULATION} frames of it); without it (a sequence, which
     * accumulates as the viewer does; the viewer's headless fallback) every frame is drawn once.
     */
    static void run(Scene scene, DrawQuality quality, int frames, Path out, int width, int height,
                    boolean maps, boolean holdFirst, PrintWriter log, Progress progress) throws IOException {
        SceneDef def = scene.def();
        if (def.isOpenWorld()) {
            if (maps) {
                throw new IllegalArgumentException("--maps needs a scene of one square: '" + def.name()
                        + "' is an open world, whose plants exist only around the camera");
            }
            OpenWorldFrames.run(scene, quality, frames, out, width, height, holdFirst, log);
            return;
        }
        log.println("Building '" + def.name() + "' ...");
        log.flush();
        try (Simulation sim = Simulation.create(def.simulationDef(), scene.images(), 0, progress)) {
            sim.setLodTransition(def.render().lodTransition());
            if (quality != null) {
                quality.applyTo(sim);
            }
            render(def, sim, frames, out, width, height, maps, holdFirst, log);
        }
    }

    private static void render(SceneDef def, Simulation sim, int frames, Path out, int width, int height,
                               boolean maps, boolean holdFirst, PrintWriter log) throws IOException {
        World world = sim.world();
        BuildReport.print(world, log, log);
        OutputFiles files = new OutputFiles();
        if (maps) {
            files.writeFile(out.resolve(MAPS.get(0)), temporary ->
                    TerrainMaps.writeWater(world.terrain().water(), MAP_SIDE, MAP_SIDE, temporary));
            files.writeFile(out.resolve(MAPS.get(1)), temporary ->
                    TerrainMaps.writeNutrients(world.terrain().nutrients(), MAP_SIDE, MAP_SIDE, temporary));
            int[] palette = {0x4F8A2B, 0xF2D21B, 0x7B3FB0, 0xD0402A, 0x2A7FD0, 0xE08A1E, 0x20A0A0, 0xA02080};
            int[] pal = new int[Math.max(palette.length, world.plants().species().size())];
            for (int i = 0; i < pal.length; i++) {
                pal[i] = palette[i % palette.length];
            }
            files.writeFile(out.resolve(MAPS.get(2)), temporary -> TerrainMaps.writeSpecies(
                    world.terrain().heightfield(), world.layout(), pal, MAP_SIDE, MAP_SIDE, temporary));
            log.println("Wrote water.png, nutrients.png and species.png to " + out);
        }
        double ground = world.terrain().heightfield().height(def.camera().x(), def.camera().z());
        ViewCamera camera = ViewCamera.of(def.camera(), ground, width / (double) height);
        ByteBuffer px = MemoryUtil.memAlloc(4 * width * height);
        try (GlContext gl = GlContext.headless(DebugOutput.OFF)) {
            log.println("OpenGL: " + gl.describe());
            try (GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), width, height, def.render().antialiasing());
                 SceneRenderer renderer = new SceneRenderer(gl, world, settings(def.render()))) {
                renderer.setField(sim.inspect().forceField().debugView());
                accumulate(fb);
                for (int i = 1; i <= frames; i++) {
                    sim.step(FRAME_DT, camera);
                    Frame frame = sim.latestFrame();
                    if (i == 1 && holdFirst) {
                        // the first picture as a view held still shows it; later ones as the plants move
                        drawStill(fb, renderer, frame, camera, width, height);
                    } else {
                        fb.bind();
                        renderer.render(frame, fb.jittered(camera, false), width, height);
                        fb.resolve();
                    }
                    Pixels.read(width, height, px);
                    files.writeFile(out.resolve(frameName(i)), temporary -> Pixels.writePng(temporary, px, width, height));
                }
            }
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) px);
        }
        log.println("Wrote " + frames + " frame(s) of " + width + "x" + height + " to " + out.toAbsolutePath());
        log.flush();
    }
}
