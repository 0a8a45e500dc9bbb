package com.example.meadowgame;

import static org.lwjgl.glfw.GLFW.GLFW_CLIENT_API;
import static org.lwjgl.glfw.GLFW.GLFW_CONTEXT_CREATION_API;
import static org.lwjgl.glfw.GLFW.GLFW_CONTEXT_VERSION_MAJOR;
import static org.lwjgl.glfw.GLFW.GLFW_CONTEXT_VERSION_MINOR;
import static org.lwjgl.glfw.GLFW.GLFW_EGL_CONTEXT_API;
import static org.lwjgl.glfw.GLFW.GLFW_FALSE;
import static org.lwjgl.glfw.GLFW.GLFW_OPENGL_API;
import static org.lwjgl.glfw.GLFW.GLFW_OPENGL_CORE_PROFILE;
import static org.lwjgl.glfw.GLFW.GLFW_OPENGL_FORWARD_COMPAT;
import static org.lwjgl.glfw.GLFW.GLFW_OPENGL_PROFILE;
import static org.lwjgl.glfw.GLFW.GLFW_PLATFORM;
import static org.lwjgl.glfw.GLFW.GLFW_PLATFORM_NULL;
import static org.lwjgl.glfw.GLFW.GLFW_TRUE;
import static org.lwjgl.glfw.GLFW.GLFW_VISIBLE;
import static org.lwjgl.glfw.GLFW.glfwCreateWindow;
import static org.lwjgl.glfw.GLFW.glfwDefaultWindowHints;
import static org.lwjgl.glfw.GLFW.glfwDestroyWindow;
import static org.lwjgl.glfw.GLFW.glfwGetTime;
import static org.lwjgl.glfw.GLFW.glfwInit;
import static org.lwjgl.glfw.GLFW.glfwInitHint;
import static org.lwjgl.glfw.GLFW.glfwMakeContextCurrent;
import static org.lwjgl.glfw.GLFW.glfwPollEvents;
import static org.lwjgl.glfw.GLFW.glfwSwapBuffers;
import static org.lwjgl.glfw.GLFW.glfwSwapInterval;
import static org.lwjgl.glfw.GLFW.glfwTerminate;
import static org.lwjgl.glfw.GLFW.glfwWindowHint;
import static org.lwjgl.glfw.GLFW.glfwWindowShouldClose;
import static org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_LESS;
import static org.lwjgl.opengl.GL11C.glClear;
import static org.lwjgl.opengl.GL11C.glDepthFunc;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glViewport;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import org.jecosys.math.MatrixCamera;
import org.jecosys.math.Progress;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.Screenshot;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.SceneRenderer;
import org.jecosys.scene.SceneLoadException;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;
import org.joml.Matrix4f;
import org.lwjgl.opengl.GL;
import org.lwjgl.system.MemoryUtil;

/**
 * A small game that embeds JEcoSys the way a game does, in this order:
 * <ol>
 * <li>it opens its own GLFW window and OpenGL 3.3 context and makes it current;</li>
 * <li>it loads a scene into a {@link Simulation} and wraps its own context with
 * {@link GlContext#current(boolean)} for a {@link SceneRenderer} that neither clears nor draws terrain;</li>
 * <li>it adds a player agent (a source flow that follows the player and pushes the grass) and its own
 * wind flow, {@link Breeze};</li>
 * <li>every frame it moves the player, builds its own view and projection matrices with JOML and
 * hands them to the library as a {@link MatrixCamera}, steps the simulation, draws its own sky and
 * ground, lets the library draw the plants over them, and draws its HUD last.</li>
 * </ol>
 * Run it with {@code mvn -pl examples/game exec:java} (a window on a desktop), or headless with
 * {@code -Dexec.args="--headless 60 frame.png"}.
 */
public final class MeadowGame implements AutoCloseable {
    /** Player flow strength, m²/s: a source of this strength blows 3.2 m/s one metre away. */
    public static final double PLAYER_STRENGTH = 20;

    private final int width;
    private final int height;
    private final long window;
    private final GlContext gl;
    private final Simulation sim;
    private final SceneRenderer plants;
    private final GamePasses passes;
    private final WindSource player;
    private final Breeze breeze;
    private final MatrixCamera camera = new MatrixCamera();
    private final Matrix4f view = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();
    private final Matrix4f viewProjection = new Matrix4f();
    private final double centreX;
    private final double centreZ;
    private final double orbit;
    private double time;
    private double playerX;
    private double playerZ;

    /**
     * What the game starts with.
     *
     * @param scene          the scene file
     * @param width          window width, pixels
     * @param height         window height, pixels
     * @param headless       a hidden window on GLFW's null platform with an EGL context (no display)
     * @param playerStrength the player flow's strength, m²/s (0: the player pushes nothing)
     * @param breeze         whether the game's own flow blows
     */
    public record Options(Path scene, int width, int height, boolean headless, double playerStrength,
                          boolean breeze) {
    }

    /**
     * Opens the window and loads the scene. Game thread (it becomes the render thread).
     *
     * @param options what to start with
     * @throws IOException when the scene or an image it names cannot be read
     */
    public MeadowGame(Options options) throws IOException {
        width = options.width();
        height = options.height();
        if (options.headless()) {
            glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_NULL);
        }
        if (!glfwInit()) {
            throw new IllegalStateException("GLFW could not start");
        }
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        if (options.headless()) {
            glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
            glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
        }
        window = glfwCreateWindow(width, height, "Meadow game (JEcoSys example)", 0, 0);
        if (window == 0) {
            glfwTerminate();
            throw new IllegalStateException("no OpenGL 3.3 window");
        }
        glfwMakeContextCurrent(window);
        glfwSwapInterval(1);
        GL.createCapabilities();

        Simulation s = null;
        try {
            s = Scenes.simulation(options.scene(), Progress.NONE);
        } catch (SceneLoadException e) {
            glfwDestroyWindow(window);
            glfwTerminate();
            throw new IOException(e.getMessage(), e);
        }
        sim = s;
        gl = GlContext.current(DebugOutput.OFF);
        // on a software rasteriser (llvmpipe) far plants are thinned, as the viewer and the engine adapters do
        // (it says so once); a GPU keeps the scene's own setting
        org.jecosys.render.SoftwareQuality.apply(gl, sim, null);
        plants = new SceneRenderer(gl, sim.world(), new RenderSettings());
        Heightfield terrain = sim.world().terrain().heightfield();
        passes = new GamePasses(terrain, 96);
        centreX = terrain.minX() + terrain.sizeX() / 2;
        centreZ = terrain.minZ() + terrain.sizeZ() / 2;
        orbit = Math.min(terrain.sizeX(), terrain.sizeZ()) * 0.3;
        playerX = centreX;
        playerZ = centreZ;
        player = sim.attachAgent(FlowDef.point("player", FlowKind.SOURCE, playerX, playerZ,
                options.playerStrength()));
        breeze = new Breeze("swirling-breeze", centreX, centreZ, 6.0, 3.0);
        breeze.setEnabled(options.breeze());
        sim.addFlow(breeze);
    }

    /** The simulation, for the game's logic (and tests). */
    public Simulation simulation() {
        return sim;
    }

    /** Where the player stands, metres: x. */
    public double playerX() {
        return playerX;
    }

    /** Where the player stands, metres: z. */
    public double playerZ() {
        return playerZ;
    }

    /** The game's own wind flow. */
    public Breeze breeze() {
        return breeze;
    }

    /**
     * One game frame: logic, simulation, then drawing into the window's back buffer.
     *
     * @param dt seconds since the last frame
     * @return the frame the plants were drawn from
     */
    public Frame frame(double dt) {
        time += dt;
        // game logic: the player walks a small circle in front of the camera
        playerX = centreX + 1.2 * Math.sin(0.6 * time);
        playerZ = centreZ + 1.2 * Math.cos(0.6 * time);
        sim.moveAgent(player, playerX, playerZ);

        // the game's own camera: orbiting the meadow, matrices built with JOML
        Heightfield terrain = sim.world().terrain().heightfield();
        double a = 0.05 * time;
        float ex = (float) (centreX + orbit * Math.sin(a));
        float ez = (float) (centreZ + orbit * Math.cos(a));
        float ey = (float) terrain.height(ex, ez) + 1.7f;
        view.setLookAt(ex, ey, ez, (float) centreX, (float) terrain.height(centreX, centreZ) + 0.3f,
                (float) centreZ, 0f, 1f, 0f);
        projection.setPerspective((float) Math.toRadians(55), width / (float) height, 0.05f, 300f);
        camera.set(view, projection);
        projection.mul(view, viewProjection);

        sim.step(dt, camera);
        Frame frame = sim.latestFrame();

        glViewport(0, 0, width, height);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glDisable(GL_DEPTH_TEST);
        glDepthMask(false);
        passes.sky();
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(true);
        passes.ground(viewProjection);
        plants.render(frame, camera);          // library: the bound framebuffer and viewport, state put back
        glDisable(GL_DEPTH_TEST);
        passes.hud((float) (0.5 + 0.5 * Math.sin(time)));
        return frame;
    }

    /**
     * Reads the back buffer (RGBA, bottom row first).
     *
     * @param dest at least {@code 4 * width * height} bytes
     */
    public void read(ByteBuffer dest) {
        Screenshot.read(width, height, dest);
    }

    /** Shows the back buffer. */
    public void swap() {
        glfwSwapBuffers(window);
    }

    @Override
    public void close() {
        plants.close();
        passes.close();
        gl.close();
        sim.close();
        GL.setCapabilities(null);
        glfwMakeContextCurrent(0);
        glfwDestroyWindow(window);
        glfwTerminate();
    }

    /**
     * Runs the game. {@code --headless N FILE.png} renders N frames without a display and saves the
     * last; otherwise a window opens until it is closed.
     *
     * @param args {@code [--headless N FILE.png] [SCENE]}
     * @throws IOException when the scene cannot be read or the image written
     */
    public static void main(String[] args) throws IOException {
        boolean headless = args.length >= 3 && args[0].equals("--headless");
        Path scene = Path.of(args.length == 1 ? args[0] : args.length >= 4 ? args[3] : "scenes/meadow.xml");
        Options o = new Options(scene, 1280, 720, headless, PLAYER_STRENGTH, true);
        try (MeadowGame game = new MeadowGame(o)) {
            if (headless) {
                int frames = Integer.parseInt(args[1]);
                for (int i = 0; i < frames; i++) {
                    game.frame(1 / 30.0);
                }
                ByteBuffer px = MemoryUtil.memAlloc(4 * o.width() * o.height());
                try {
                    game.read(px);
                    Screenshot.writePng(Path.of(args[2]), px, o.width(), o.height());
                } finally {
                    MemoryUtil.memFree((java.nio.Buffer) px);
                }
                return;
            }
            double last = glfwGetTime();
            while (!glfwWindowShouldClose(game.window)) {
                double now = glfwGetTime();
                game.frame(now - last);
                last = now;
                game.swap();
                glfwPollEvents();
            }
        }
    }
}
