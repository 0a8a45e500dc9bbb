package org.jecosys.app;

import org.jecosys.render.gl.GlContexts;
import static org.lwjgl.glfw.GLFW.glfwGetCursorPos;
import static org.lwjgl.glfw.GLFW.glfwGetFramebufferSize;
import static org.lwjgl.glfw.GLFW.glfwGetTime;
import static org.lwjgl.glfw.GLFW.glfwGetWindowSize;
import static org.lwjgl.glfw.GLFW.glfwPollEvents;
import static org.lwjgl.glfw.GLFW.glfwSetWindowShouldClose;
import static org.lwjgl.glfw.GLFW.glfwSetWindowTitle;
import static org.lwjgl.glfw.GLFW.glfwShowWindow;
import static org.lwjgl.glfw.GLFW.glfwSwapBuffers;
import static org.lwjgl.glfw.GLFW.glfwSwapInterval;
import static org.lwjgl.glfw.GLFW.glfwWindowShouldClose;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import org.jecosys.field.FieldDebugView;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.overlay.GizmoRenderer;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.SceneRenderer;
import org.jecosys.scene.OutputFiles;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneDef;
import org.jecosys.terrain.ImageSource;
import org.jecosys.sim.DrawQuality;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.system.MemoryUtil;

/**
 * {@code jecosys view}: the desktop viewer. One thread (the caller's) is the render thread and also
 * steps the {@link Simulation}. Input arrives through GLFW's callbacks ({@link GlfwInput}) into a
 * queue that {@link ViewerControls} handles once per frame, so no key tap is lost however slow the
 * frame; the flows and agents are drawn as gizmos and the wind the plants feel as arrows on the
 * terrain ({@link GizmoRenderer}); the window closes with Escape or its close button, asking first
 * when the scene has unsaved changes.
 *
 * <p>Allocation: {@link org.jecosys.render.SceneRenderer#render} and its per-frame uploads allocate
 * nothing after warm-up (RenderResourcesTest measures it), but the interactive viewer does: the HUD
 * formats its strings (fps, counters, milliseconds) every frame and the ImGui panel builds its
 * widgets' labels, a few kilobytes of short-lived garbage per frame. Headless rendering has no HUD.
 */
final class Viewer {
    private final SceneDef def;
    private final Path file;
    /** The images the scene was checked with: the build decodes these bytes. */
    private final ImageSource images;
    private final DrawQuality quality;
    private final double[] cx = new double[1];
    private final double[] cy = new double[1];
    private final int[] iw = new int[1];
    private final int[] ih = new int[1];
    private final int[] ww = new int[1];
    private final int[] wh = new int[1];

    Viewer(Scene scene, Path file, DrawQuality quality) {
        this.def = scene.def();
        this.file = file;
        this.images = scene.images();
        this.quality = quality;
    }

    void run(Progress progress) throws IOException {
        System.out.println("Building '" + def.name() + "' ...");
        try (Simulation sim = Simulation.create(def.simulationDef(), images, 0, progress)) {
            sim.setLodTransition(def.render().lodTransition());
            if (quality != null) {
                quality.applyTo(sim);
            }
            run(sim);
        }
    }

    private void run(Simulation sim) throws IOException {
        World world = sim.world();
        PrintWriter console = new PrintWriter(System.out, true);
        BuildReport.print(world, console, new PrintWriter(System.err, true));
        Heightfield ground = world.terrain().heightfield();
        int width = def.render().width();
        int height = def.render().height();
        ViewCamera camera = ViewCamera.of(def.camera(), ground.height(def.camera().x(), def.camera().z()),
                width / (double) height);
        FlyCamera fly = new FlyCamera(camera, def.camera(), ground);
        FrameTimes times = new FrameTimes();
        ViewerInput input = new ViewerInput();
        RenderSettings settings = HeadlessRender.settings(def.render());
        try (GlContext gl = GlContext.windowed(title(false), width, height, DebugOutput.OFF)) {
            long window = gl.window();
            if (quality == null && softwareRenderer(gl.describe())) {
                DrawQuality.LOW.applyTo(sim);
                console.println("Software OpenGL (" + gl.describe() + "): drawing far plants thinned, as --quality "
                        + "low; --quality high draws them all, and <render antialiasing=\"1\"> in the scene trades "
                        + "the smooth edges for speed.");
            }
            glfwSwapInterval(1);
            glfwShowWindow(window);
            // the callbacks first: ImGui's backend chains to the callbacks it finds installed
            // the scene goes through an offscreen multisampled framebuffer and its resolve filter,
            // whatever the window offers, so the viewer shows what headless rendering writes
            try (GlfwInput callbacks = new GlfwInput(window, input);
                 GlFramebuffer target = new GlFramebuffer(GlContexts.tracker(gl), width, height,
                         def.render().antialiasing());
                 SceneRenderer renderer = new SceneRenderer(gl, world, settings);
                 GizmoRenderer gizmos = new GizmoRenderer(gl, ground);
                 ImGuiLayer ui = new ImGuiLayer(gl, window)) {
                renderer.setField(sim.inspect().forceField().debugView());
                HeadlessRender.accumulate(target);
                SceneEditor editor = new SceneEditor(def, sim, settings);
                SceneSaver saver = new SceneSaver(file, SceneSaver.shippedFolder());
                ViewerControls controls = new ViewerControls(def, sim, editor, saver, fly, input);
                ViewerPanel panel = new ViewerPanel(def, controls, sim, renderer);
                loop(window, target, renderer, gizmos, ui, panel, controls, sim, fly, times);
            }
        }
    }

    private String title(boolean dirty) {
        return "JEcoSys - " + def.name() + (dirty ? " (unsaved changes)" : "");
    }

    private void loop(long window, GlFramebuffer target, SceneRenderer renderer, GizmoRenderer gizmoRenderer,
                      ImGuiLayer ui,
                      ViewerPanel panel, ViewerControls controls, Simulation sim, FlyCamera fly, FrameTimes times)
            throws IOException {
        double last = glfwGetTime();
        int shots = 0;
        boolean dirty = false;
        WindLegend legend = new WindLegend();
        FieldDebugView view = sim.inspect().forceField().debugView();
        ViewCamera camera = fly.camera();
        while (!controls.quit()) {
            glfwPollEvents();
            if (glfwWindowShouldClose(window)) {
                glfwSetWindowShouldClose(window, false);
                controls.requestQuit();
            }
            double now = glfwGetTime();
            double dt = Math.min(0.1, Math.max(1e-4, now - last));
            last = now;
            times.add(dt);
            glfwGetFramebufferSize(window, iw, ih);
            glfwGetWindowSize(window, ww, wh);
            int w = Math.max(1, iw[0]);
            int h = Math.max(1, ih[0]);
            camera.setLens(camera.fovY(), w / (double) h, camera.near(), camera.far());
            glfwGetCursorPos(window, cx, cy);
            double sx = cx[0] * w / Math.max(1, ww[0]);
            double sy = cy[0] * h / Math.max(1, wh[0]);
            controls.frame(dt, sx, sy, w, h, ui.wantsKeyboard(), ui.wantsMouse());
            if (controls.quit()) {
                break;
            }
            sim.step(dt, camera);
            Frame frame = sim.latestFrame();
            FlowGizmos flows = controls.gizmos();
            legend.update(legend.typical(view), dt);
            long r0 = System.nanoTime();
            if (target.width() != w || target.height() != h) {
                target.resize(w, h);
            }
            target.bind();
            // the plants move in the wind every frame: accumulation keeps a short mean where they drew
            org.jecosys.math.Camera drawn = target.jittered(camera, false);
            renderer.render(frame, drawn, w, h);
            if (controls.showGizmos() || controls.showWind()) {
                gizmoRenderer.render(controls.showGizmos() ? flows.gizmos() : null,
                        controls.showWind() ? view : null, legend.scale(), drawn);
            }
            target.resolveTo(0);
            GL11C.glViewport(0, 0, w, h);
            double renderMs = (System.nanoTime() - r0) / 1e6;
            ui.begin(w, h, (float) dt);
            panel.hud(times, fly, frame, renderMs);
            panel.panel();
            panel.overlays(w, h, controls.showGizmos() ? flows.gizmos() : null, legend);
            ui.end();
            if (controls.takeScreenshot()) {
                screenshot(Path.of(String.format("jecosys-screenshot-%03d.png", ++shots)), w, h);
            }
            if (controls.editor().dirty() != dirty) {
                dirty = controls.editor().dirty();
                glfwSetWindowTitle(window, title(dirty));
            }
            glfwSwapBuffers(window);
        }
    }

    private static void screenshot(Path out, int w, int h) throws IOException {
        ByteBuffer px = MemoryUtil.memAlloc(4 * w * h);
        try {
            Pixels.read(w, h, px);
            new OutputFiles().writeFile(out, temporary -> Pixels.writePng(temporary, px, w, h));
            System.out.println("Saved " + out.toAbsolutePath());
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) px);
        }
    }

    /** {@return whether a GL renderer string names a software rasteriser (llvmpipe, softpipe, SwiftShader)} */
    static boolean softwareRenderer(String renderer) {
        String r = renderer.toLowerCase(java.util.Locale.ROOT);
        return r.contains("llvmpipe") || r.contains("softpipe") || r.contains("swiftshader");
    }
}
