package org.jecosys.app;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_A;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_D;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_E;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_F;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_F12;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_P;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_Q;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_RIGHT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_S;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_W;
import static org.lwjgl.glfw.GLFW.GLFW_MOUSE_BUTTON_LEFT;
import static org.lwjgl.glfw.GLFW.GLFW_MOUSE_BUTTON_RIGHT;
import static org.lwjgl.glfw.GLFW.GLFW_PRESS;
import static org.lwjgl.glfw.GLFW.glfwGetCursorPos;
import static org.lwjgl.glfw.GLFW.glfwGetFramebufferSize;
import static org.lwjgl.glfw.GLFW.glfwGetKey;
import static org.lwjgl.glfw.GLFW.glfwGetMouseButton;
import static org.lwjgl.glfw.GLFW.glfwGetTime;
import static org.lwjgl.glfw.GLFW.glfwGetWindowSize;
import static org.lwjgl.glfw.GLFW.glfwPollEvents;
import static org.lwjgl.glfw.GLFW.glfwSetWindowShouldClose;
import static org.lwjgl.glfw.GLFW.glfwShowWindow;
import static org.lwjgl.glfw.GLFW.glfwSwapBuffers;
import static org.lwjgl.glfw.GLFW.glfwSwapInterval;
import static org.lwjgl.glfw.GLFW.glfwWindowShouldClose;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext;
import org.jecosys.render.Pixels;
import org.jecosys.render.SceneRenderer;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.jecosys.wind.WindSource;
import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.system.MemoryUtil;

/**
 * {@code jecosys view}: the desktop viewer. One thread (the caller's) is the render thread and also
 * steps the {@link Simulation}; the window closes with Escape or its close button.
 *
 * <p>Allocation: {@link org.jecosys.render.SceneRenderer#render} and its per-frame uploads allocate
 * nothing after warm-up (RenderResourcesTest measures it), but the interactive viewer does: the HUD
 * formats its strings (fps, counters, milliseconds) every frame and the ImGui panel builds its
 * widgets' labels, a few kilobytes of short-lived garbage per frame. Headless rendering has no HUD.
 */
final class Viewer {
    static final String AGENT_ID = "cursor-agent";

    private final SceneDef def;
    private final Path file;
    private final Path base;
    private final double[] cx = new double[1];
    private final double[] cy = new double[1];
    private final int[] iw = new int[1];
    private final int[] ih = new int[1];
    private final int[] ww = new int[1];
    private final int[] wh = new int[1];
    private final double[] hit = new double[2];
    private final Matrix4f inv = new Matrix4f();
    private final Vector4f a = new Vector4f();
    private final Vector4f b = new Vector4f();

    Viewer(SceneDef def, Path file, Path base) {
        this.def = def;
        this.file = file;
        this.base = base;
    }

    void run(Progress progress) throws IOException {
        System.out.println("Building '" + def.name() + "' ...");
        try (Simulation sim = Simulation.create(def.simulationDef(), base, progress)) {
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
        try (GlContext gl = GlContext.windowed("JEcoSys - " + def.name(), width, height, false)) {
            long window = gl.window();
            glfwSwapInterval(1);
            glfwShowWindow(window);
            try (SceneRenderer renderer = new SceneRenderer(gl, world, HeadlessRender.settings(def.render()));
                 ImGuiLayer ui = new ImGuiLayer(gl, window)) {
                renderer.setField(sim.forceField().debugView());
                ViewerPanel panel = new ViewerPanel(def, file, sim, renderer);
                loop(window, renderer, ui, panel, sim, fly, times, ground);
            }
        }
    }

    private void loop(long window, SceneRenderer renderer, ImGuiLayer ui, ViewerPanel panel, Simulation sim,
                      FlyCamera fly, FrameTimes times, Heightfield ground) throws IOException {
        double last = glfwGetTime();
        double lastX = 0;
        double lastY = 0;
        boolean prevP = false;
        boolean prevF = false;
        boolean prevF12 = false;
        int shots = 0;
        WindSource agent = null;
        ViewCamera camera = fly.camera();
        while (!glfwWindowShouldClose(window)) {
            glfwPollEvents();
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
            double dx = cx[0] - lastX;
            double dy = cy[0] - lastY;
            lastX = cx[0];
            lastY = cy[0];
            boolean mouseFree = !ui.wantsMouse();
            boolean keysFree = !ui.wantsKeyboard();
            if (keysFree && down(window, GLFW_KEY_ESCAPE)) {
                glfwSetWindowShouldClose(window, true);
            }
            if (mouseFree && glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) {
                fly.look(dx, dy);
            }
            boolean p = keysFree && down(window, GLFW_KEY_P);
            if (p && !prevP) {
                fly.togglePath();
            }
            prevP = p;
            if (keysFree) {
                fly.move(dt, axis(window, GLFW_KEY_W, GLFW_KEY_S), axis(window, GLFW_KEY_D, GLFW_KEY_A),
                        axis(window, GLFW_KEY_E, GLFW_KEY_Q),
                        down(window, GLFW_KEY_LEFT_SHIFT) || down(window, GLFW_KEY_RIGHT_SHIFT));
            }
            double sx = cx[0] * w / Math.max(1, ww[0]);
            double sy = cy[0] * h / Math.max(1, wh[0]);
            boolean onGround = pick(camera, ground, sx, sy, w, h);
            boolean f = keysFree && down(window, GLFW_KEY_F);
            if (f && !prevF && onGround) {
                panel.addFlow(hit[0], hit[1], camera.yaw());
            }
            prevF = f;
            // dragging on the terrain: an agent (a repelling source) follows the cursor and pushes plants
            boolean drag = mouseFree && onGround && glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
            if (drag && agent == null) {
                agent = sim.attachAgent(new FlowDef(AGENT_ID, FlowKind.SOURCE, true, hit[0], hit[1], 6, 0,
                        0.3, 2.0, ActivationDef.ALWAYS, MotionDef.FIXED, FlowDef.DEFAULT_NOISE_SCALE,
                        FlowDef.DEFAULT_NOISE_FREQUENCY, 0));
            } else if (drag) {
                sim.moveAgent(agent, hit[0], hit[1]);
            } else if (agent != null) {
                sim.removeFlow(agent);
                agent = null;
            }
            sim.step(dt, camera);
            Frame frame = sim.latestFrame();
            GL11C.glViewport(0, 0, w, h);
            renderer.render(frame, camera, w, h);
            ui.begin(w, h, (float) dt);
            panel.hud(times, fly.playing(), frame);
            panel.panel();
            ui.end();
            boolean f12 = down(window, GLFW_KEY_F12);
            if (f12 && !prevF12) {
                screenshot(Path.of(String.format("jecosys-screenshot-%03d.png", ++shots)), w, h);
            }
            prevF12 = f12;
            glfwSwapBuffers(window);
        }
    }

    private static boolean down(long window, int key) {
        return glfwGetKey(window, key) == GLFW_PRESS;
    }

    private static double axis(long window, int plus, int minus) {
        return (down(window, plus) ? 1 : 0) - (down(window, minus) ? 1 : 0);
    }

    /** The terrain point under pixel (sx, sy) (from the top-left) into {@link #hit}; false if none within 300 m. */
    private boolean pick(ViewCamera camera, Heightfield ground, double sx, double sy, int w, int h) {
        camera.viewProjection(inv).invert();
        double nx = 2 * sx / w - 1;
        double ny = 1 - 2 * sy / h;
        inv.transform(a.set((float) nx, (float) ny, -1, 1));
        inv.transform(b.set((float) nx, (float) ny, 1, 1));
        a.div(a.w);
        b.div(b.w);
        double dx = b.x - a.x;
        double dy = b.y - a.y;
        double dz = b.z - a.z;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        dx /= len;
        dy /= len;
        dz /= len;
        for (double t = 0; t < 300; t += 0.05 + t * 0.01) {
            double x = a.x + dx * t;
            double y = a.y + dy * t;
            double z = a.z + dz * t;
            if (ground.contains(x, z) && y <= ground.height(x, z)) {
                hit[0] = x;
                hit[1] = z;
                return true;
            }
        }
        return false;
    }

    private static void screenshot(Path out, int w, int h) throws IOException {
        ByteBuffer px = MemoryUtil.memAlloc(4 * w * h);
        try {
            Pixels.read(w, h, px);
            Pixels.writePng(out, px, w, h);
            System.out.println("Saved " + out.toAbsolutePath());
        } finally {
            MemoryUtil.memFree(px);
        }
    }
}
