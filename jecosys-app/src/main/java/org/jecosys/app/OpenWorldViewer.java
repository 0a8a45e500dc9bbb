package org.jecosys.app;

import static org.lwjgl.glfw.GLFW.glfwGetCursorPos;
import static org.lwjgl.glfw.GLFW.glfwGetFramebufferSize;
import static org.lwjgl.glfw.GLFW.glfwGetTime;
import static org.lwjgl.glfw.GLFW.glfwGetWindowSize;
import static org.lwjgl.glfw.GLFW.glfwPollEvents;
import static org.lwjgl.glfw.GLFW.glfwSetWindowShouldClose;
import static org.lwjgl.glfw.GLFW.glfwShowWindow;
import static org.lwjgl.glfw.GLFW.glfwSwapBuffers;
import static org.lwjgl.glfw.GLFW.glfwSwapInterval;
import static org.lwjgl.glfw.GLFW.glfwWindowShouldClose;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiWindowFlags;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.Locale;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.OpenWorldRenderer;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.gl.Closing;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.scene.OutputFiles;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.DrawQuality;
import org.jecosys.sim.OpenWorld;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.system.MemoryUtil;

/**
 * {@code jecosys view} on an open world ({@code <world>}): the camera walks the world's hills without an
 * edge and the tiles stream around it ({@link OpenWorld}, drawn by an {@link OpenWorldRenderer}: sky,
 * each tile's ground, the plants). One thread (the caller's) is the render thread and steps the world;
 * the tiles are built on a tile worker between frames. The start is loaded before the window shows
 * anything, as behind a loading screen ({@link OpenWorld#load}); after that a frame never waits for a
 * tile. The HUD shows the frame rate, where the camera is, the tiles alive and being built, the plants
 * and components alive and the heap in use. Input as {@link OpenWorldControls}.
 *
 * <p>Allocation: the world's step and the renderer allocate nothing in a frame where no tile arrives or
 * leaves, but the HUD formats its strings every frame (a few kilobytes of short-lived garbage), as in
 * the viewer of a scene of one square.
 */
final class OpenWorldViewer {
    private final org.jecosys.scene.Scene scene;
    private final SceneDef def;
    private final DrawQuality quality;

    OpenWorldViewer(org.jecosys.scene.Scene scene, DrawQuality quality) {
        this.scene = scene;
        this.def = scene.def();
        this.quality = quality;
    }

    /** Opens the window and runs until Escape or the close button. */
    void run() throws IOException {
        PrintWriter console = new PrintWriter(System.out, true);
        int width = def.render().width();
        int height = def.render().height();
        try (OpenWorld world = Scenes.openWorld(scene, workers(), 1);
             GlContext gl = GlContext.windowed("JEcoSys - " + def.name() + " (open world)", width, height,
                     DebugOutput.OFF)) {
            long window = gl.window();
            glfwSwapInterval(1);
            ViewerInput input = new ViewerInput();
            try (GlfwInput callbacks = new GlfwInput(window, input);
                 Session s = new Session(def, world, gl, window, input, quality, width, height, console)) {
                glfwShowWindow(window);
                loop(window, s);
            }
        }
    }

    /** Animation workers: the cores less the render thread's, at least 1. */
    static int workers() {
        return Math.max(1, Math.min(8, Runtime.getRuntime().availableProcessors() - 1));
    }

    private static void loop(long window, Session s) throws IOException {
        double[] cx = new double[1];
        double[] cy = new double[1];
        int[] iw = new int[1];
        int[] ih = new int[1];
        int[] ww = new int[1];
        int[] wh = new int[1];
        double last = glfwGetTime();
        int shots = 0;
        while (!s.controls().quit()) {
            glfwPollEvents();
            if (glfwWindowShouldClose(window)) {
                glfwSetWindowShouldClose(window, false);
                s.controls().requestQuit();
            }
            double now = glfwGetTime();
            double dt = Math.min(0.1, Math.max(1e-4, now - last));
            last = now;
            glfwGetFramebufferSize(window, iw, ih);
            glfwGetWindowSize(window, ww, wh);
            int w = Math.max(1, iw[0]);
            int h = Math.max(1, ih[0]);
            glfwGetCursorPos(window, cx, cy);
            s.frame(dt, w, h, cx[0] * w / Math.max(1, ww[0]), cy[0] * h / Math.max(1, wh[0]), 0);
            if (s.controls().takeScreenshot()) {
                s.screenshot(Path.of(String.format("jecosys-screenshot-%03d.png", ++shots)), w, h);
            }
            glfwSwapBuffers(window);
        }
    }

    /**
     * One viewer's state over an open world, without the window: the camera, the controls, the
     * renderer, the offscreen target and the HUD. Tests drive it on a headless context (window 0).
     * Render thread.
     */
    static final class Session implements AutoCloseable {
        private final OpenWorld world;
        private final ViewerInput input;
        private final FlyCamera fly;
        private final OpenWorldControls controls;
        private final FrameTimes times = new FrameTimes();
        private final double[] fps = new double[2];
        private final GlFramebuffer target;
        private final OpenWorldRenderer renderer;
        private final ImGuiLayer ui;
        private final String renderNote;
        /** Where the camera started (X, Z), metres. */
        private final double startX;
        private final double startZ;
        private long frames;

        /**
         * Loads the tiles around the scene's camera (stepping and settling until none starts), then
         * makes every live tile's renderer.
         *
         * @param def     the scene, with a {@code <world>}
         * @param world   its open world, not yet stepped
         * @param gl      the render context, current on this thread
         * @param window  the GLFW window the HUD takes its input from, or 0 (headless)
         * @param input   the input queue
         * @param quality the drawing quality asked for, or null (thinned at the low quality on software GL)
         * @param width   the first framebuffer's width, pixels
         * @param height  its height, pixels
         * @param console where the start is reported
         */
        Session(SceneDef def, OpenWorld world, GlContext gl, long window, ViewerInput input, DrawQuality quality,
                int width, int height, PrintWriter console) {
            this.world = world;
            this.input = input;
            ViewCamera camera = ViewCamera.of(def.camera(), def.world().relief().height(def.camera().x(),
                    def.camera().z()), width / (double) height);
            this.fly = FlyCamera.unbounded(camera, def.camera(), def.world().relief(), def.world().reliefHeight());
            this.controls = new OpenWorldControls(world, fly, input);
            this.startX = camera.x();
            this.startZ = camera.z();
            DrawQuality q = quality;
            if (q == null && Viewer.softwareRenderer(gl.describe())) {
                q = DrawQuality.LOW;
                console.println("Software OpenGL (" + gl.describe() + "): drawing far plants thinned, as --quality "
                        + "low; --quality high draws them all.");
            }
            if (q != null) {
                world.setThinning(q.thinStart(), q.thinEnd(), q.thinMinFraction());
            }
            renderNote = q == null ? "all plants drawn" : "plants thinned from " + q.thinStart() + " m (--quality)";
            console.printf(Locale.ROOT, "Open world: %s m tiles within %s m of the camera; loading the start ...%n",
                    def.world().tileSize(), def.world().radius());
            world.load(camera);
            console.printf(Locale.ROOT, "%d tiles, %d plants alive. %s%n", world.liveTiles(), world.livePlants(),
                    "W/A/S/D walk, right-drag looks, T a walker, B a blast, Escape quits (view --help lists all)");
            GlFramebuffer t = null;
            OpenWorldRenderer r = null;
            ImGuiLayer u = null;
            try {
                t = new GlFramebuffer(GlContexts.tracker(gl), width, height, def.render().antialiasing());
                r = new OpenWorldRenderer(gl, world, HeadlessRender.settings(def.render()));
                // the tiles' renderers are made a few a frame: make them all before the first frame shows
                for (int k = 0; k < 512 && r.tileRenderers() < world.liveTiles(); k++) {
                    t.bind();
                    r.render(camera, width, height);
                }
                HeadlessRender.accumulate(t);
                u = new ImGuiLayer(gl, window);
            } catch (RuntimeException e) {
                Closing.closeAll(u, r, t);
                throw e;
            }
            target = t;
            renderer = r;
            ui = u;
        }

        /**
         * One frame: input, a step, the drawing into the offscreen target, the HUD, and the target
         * resolved to {@code screen}.
         *
         * @param dt seconds since the last frame, &gt; 0 (at most 0.1 s is stepped)
         * @param w  framebuffer width, pixels
         * @param h  framebuffer height, pixels
         * @param sx pointer X, framebuffer pixels
         * @param sy pointer Y, framebuffer pixels
         * @param screen the framebuffer the frame ends in: 0, the window's; a test's own
         */
        void frame(double dt, int w, int h, double sx, double sy, int screen) {
            times.add(dt);
            ViewCamera camera = fly.camera();
            camera.setLens(camera.fovY(), w / (double) h, camera.near(), camera.far());
            controls.frame(dt, sx, sy, ui.wantsKeyboard(), ui.wantsMouse());
            if (controls.quit()) {
                return;
            }
            world.step(Math.min(0.1, dt), camera);
            long r0 = System.nanoTime();
            if (target.width() != w || target.height() != h) {
                target.resize(w, h);
            }
            target.bind();
            // the plants move in the wind every frame: accumulation keeps a short mean
            renderer.render(target.jittered(camera, false), w, h);
            target.resolveTo(screen);
            GL11C.glViewport(0, 0, w, h);
            double renderMs = (System.nanoTime() - r0) / 1e6;
            ui.begin(w, h, (float) dt);
            hud(renderMs);
            ui.end();
            frames++;
        }

        private void hud(double renderMs) {
            times.fps(fps);
            ViewCamera c = fly.camera();
            Runtime rt = Runtime.getRuntime();
            ImGui.setNextWindowPos(8, 8, ImGuiCond.Always);
            ImGui.setNextWindowBgAlpha(0.45f);
            ImGui.begin("hud", ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize
                    | ImGuiWindowFlags.NoInputs);
            ImGui.text(String.format(Locale.ROOT, "%.1f fps (sd %.1f)   walk %.1f m/s (Shift x4, Ctrl /4, wheel)"
                    + "   at (%.0f, %.0f) m, %.2f km from the start", fps[0], fps[1], fly.speed(), Math.rint(c.x()) + 0.0,
                    Math.rint(c.z()) + 0.0,
                    Math.hypot(c.x() - startX, c.z() - startZ) / 1000));
            ImGui.text(String.format(Locale.ROOT, "tiles alive %d (drawn %d), being built %d, built %d, "
                            + "frames that waited for a tile %d", world.liveTiles(), renderer.tileRenderers(),
                    world.pendingTiles(), world.builtTiles(), world.tileWaits()));
            ImGui.text(String.format(Locale.ROOT, "plants %,d  components %,d (animated %,d)  heap in use %d MB"
                            + "  render %.1f ms", world.livePlants(), world.liveComponents(),
                    world.animatedComponents(), (rt.totalMemory() - rt.freeMemory()) >> 20, renderMs));
            ImGui.text(fly.playing() ? "camera path playing (P stops)"
                    : "WASD QE, right-drag look, H start, P path, T walker, B blast (view --help lists all); "
                    + renderNote);
            if (!controls.message().isEmpty()) {
                ImGui.text(ViewerPanel.safe(controls.message()));
            }
            ImGui.end();
        }

        /** Writes the default framebuffer's picture to a PNG file. */
        void screenshot(Path out, int w, int h) throws IOException {
            ByteBuffer px = MemoryUtil.memAlloc(4 * w * h);
            try {
                Pixels.read(w, h, px);
                new OutputFiles().writeFile(out, temporary -> Pixels.writePng(temporary, px, w, h));
                controls.setMessage("saved " + out.toAbsolutePath());
            } finally {
                MemoryUtil.memFree((java.nio.Buffer) px);
            }
        }

        OpenWorldControls controls() {
            return controls;
        }

        FlyCamera fly() {
            return fly;
        }

        ViewerInput input() {
            return input;
        }

        OpenWorldRenderer renderer() {
            return renderer;
        }

        long frames() {
            return frames;
        }

        @Override
        public void close() {
            Closing.closeAll(ui, renderer, target);
        }
    }
}
