package com.example.jmemeadow;

import com.jme3.app.SimpleApplication;
import com.jme3.asset.plugins.FileLocator;
import com.jme3.font.BitmapText;
import com.jme3.input.KeyInput;
import com.jme3.input.controls.KeyTrigger;
import com.jme3.light.AmbientLight;
import com.jme3.light.DirectionalLight;
import com.jme3.material.Material;
import com.jme3.material.RenderState.BlendMode;
import com.jme3.math.ColorRGBA;
import com.jme3.math.FastMath;
import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.shape.Cylinder;
import com.jme3.scene.shape.Quad;
import com.jme3.system.AppSettings;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import org.jecosys.jme.PlantAppState;
import org.jecosys.jme.SceneAssetLoader;
import org.jecosys.jme.SceneKey;
import org.jecosys.math.CameraDef;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.Scene;
import org.jecosys.sim.Simulation;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;

/**
 * A small jMonkeyEngine game around JEcoSys plants: its own ground (a mesh of the scene's
 * heightfield), a player that walks a loop through the grass (arrow keys or WASD steer it) with a
 * source flow attached that pushes the plants aside, a camera that follows the player, and a HUD of
 * {@code BitmapText} on the {@code guiNode}. The scene loads through jME's {@code AssetManager}
 * ({@link SceneAssetLoader}); {@link PlantAppState} steps and draws the plants.
 * <pre>
 * JmeMeadowGame [--scene FILE] [--size WxH] [--renderer core|core33|compat] [--no-gamma]
 *               [--frames N --screenshot FILE.png] [--restart-at N] [--graphics-debug]
 *               [--start-view] [--ground-screenshot FILE.png] [--sheen FILE]
 * </pre>
 * {@code --renderer compat} runs jME's OpenGL 2 renderer (a compatibility context); {@code core} (the
 * default, jME's {@code LWJGL_OPENGL32}) and {@code core33} a core one. {@code --frames N} is the test
 * mode: N frames at a fixed 1/30 s, then the finished frame (GUI included) is saved to
 * {@code --screenshot}, what the test checks is printed, and the game exits with 0. {@code --restart-at
 * N} calls {@code restart()} after frame N (jME makes a new GL context, as a game does to change the
 * resolution, vsync or samples); {@code --graphics-debug} turns on jME's GL error check after every
 * call of its own ({@code AppSettings.setGraphicsDebug}), which fails the game on any GL error.
 * {@code --start-view} (test mode) puts the camera at the scene's start camera ({@code <camera>}: its
 * pose above the ground and its lens), standing still, and leaves the player and its flow out: the
 * meadow's start view, as the library's viewer opens it; {@code --ground-screenshot} also saves the
 * last frame as it is before the plants are drawn (the game's ground as lit); {@code --sheen} writes,
 * for every frame, the mean luminance of each 16 x 16 block of the picture after the plants and before
 * the GUI ({@link TestCapture#blockLuminance}).
 */
public final class JmeMeadowGame extends SimpleApplication {
    /** Player flow strength, m²/s: a source of this strength blows 3.2 m/s one metre away. */
    static final double PLAYER_STRENGTH = 20;
    /** HUD text colour. */
    static final ColorRGBA HUD_TEXT = new ColorRGBA(1f, 0.85f, 0.1f, 1f);
    /** Walking speed, m/s. */
    private static final float SPEED = 1.4f;

    /**
     * What the game starts with.
     *
     * @param scene      the scene's asset name (on the classpath) or a file on disk (absolute)
     * @param width      window width, pixels
     * @param height     window height, pixels
     * @param renderer   jME's renderer name ({@code AppSettings.LWJGL_OPENGL32}, ...)
     * @param gamma      jME's gamma correction (its default: on)
     * @param frames     test mode: frames to render before the screenshot; 0 to play
     * @param screenshot test mode: where to write the PNG
     * @param restartAt  test mode: the frame after which the app restarts its context; 0 for none
     * @param debug      jME's graphics debugging (a GL error check after each of its calls)
     * @param startView  test mode: the scene's start camera, still, and no player
     * @param groundShot test mode: where to write the last frame before the plants, or null
     * @param sheen      test mode: where to write the frames' block luminance, or null
     */
    record Options(String scene, int width, int height, String renderer, boolean gamma, int frames,
                   Path screenshot, int restartAt, boolean debug, boolean startView, Path groundShot, Path sheen) {
    }

    private final Options options;
    private final CountDownLatch done = new CountDownLatch(1);
    private volatile int exitCode;
    private TestCapture capture;
    private PlantAppState plants;
    private WindSource playerFlow;
    private Heightfield terrain;
    private Geometry player;
    private BitmapText hud;
    private Geometry hudPanel;
    private final StringBuilder hudText = new StringBuilder(128);
    private float centreX;
    private float centreZ;
    private float loopRadius;
    private float time;
    private float playerX;
    private float playerZ;
    private float heading;
    private float turn;
    private float ahead;
    private final Vector3f eye = new Vector3f();
    private final Vector3f target = new Vector3f();

    JmeMeadowGame(Options options) {
        super(new com.jme3.app.state.AppState[0]); // no default app states: no fly camera, no statistics
        this.options = options;
    }

    @Override
    public void simpleInitApp() {
        // the scene, through jME's asset manager: its images are found next to it
        assetManager.registerLoader(SceneAssetLoader.class, SceneAssetLoader.EXTENSION);
        String key = options.scene();
        if (Path.of(key).isAbsolute()) {
            Path file = Path.of(key);
            assetManager.registerLocator(file.getParent().toString(), FileLocator.class);
            key = file.getFileName().toString();
        }
        Scene scene = assetManager.loadAsset(new SceneKey(key));
        plants = new PlantAppState(scene); // builds the simulation; steps and draws it once attached
        stateManager.attach(plants);
        Simulation sim = plants.simulation();

        terrain = sim.world().terrain().heightfield();
        centreX = (float) (terrain.minX() + terrain.sizeX() / 2);
        centreZ = (float) (terrain.minZ() + terrain.sizeZ() / 2);
        loopRadius = (float) Math.min(terrain.sizeX(), terrain.sizeZ()) * 0.2f;

        Geometry ground = new Geometry("ground", GroundMesh.of(terrain));
        ground.setMaterial(lit(new ColorRGBA(0.50f, 0.36f, 0.22f, 1f)));
        rootNode.attachChild(ground);
        Cylinder body = new Cylinder(2, 16, 0.25f, 1.7f, true);
        player = new Geometry("player", body);
        player.setMaterial(lit(new ColorRGBA(0.15f, 0.3f, 0.95f, 1f)));
        if (!options.startView()) {
            rootNode.attachChild(player);
        }
        rootNode.addLight(new AmbientLight(new ColorRGBA(0.45f, 0.45f, 0.5f, 1f)));
        rootNode.addLight(new DirectionalLight(new Vector3f(-0.4f, -1f, 0.3f).normalizeLocal(),
                new ColorRGBA(0.8f, 0.78f, 0.7f, 1f)));
        viewPort.setBackgroundColor(new ColorRGBA(0.55f, 0.72f, 0.92f, 1f));
        cam.setFrustumPerspective(55, cam.getWidth() / (float) cam.getHeight(), 0.05f, 300f);

        hud = new BitmapText(guiFont);
        hud.setSize(guiFont.getCharSet().getRenderedSize() * 1.25f);
        hud.setColor(HUD_TEXT);
        Material panel = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        panel.setColor("Color", new ColorRGBA(0f, 0f, 0f, 0.55f));
        panel.getAdditionalRenderState().setBlendMode(BlendMode.Alpha);
        hudPanel = new Geometry("hud panel", new Quad(1, 1));
        hudPanel.setMaterial(panel);
        guiNode.attachChild(hudPanel);
        guiNode.attachChild(hud);

        if (options.startView()) {
            startView(scene.def().camera());
        } else {
            walk(0);
            playerFlow = sim.attachAgent(FlowDef.point("player", FlowKind.SOURCE, playerX, playerZ, PLAYER_STRENGTH));
        }
        if (options.frames() > 0) {
            capture = new TestCapture(this, options);
        } else {
            keys();
        }
    }

    /**
     * The test mode's still camera: the scene's start camera (its height above the ground under it),
     * with its lens, as the library's viewer opens the scene.
     */
    private void startView(CameraDef c) {
        ViewCamera v = ViewCamera.of(c, terrain.height(c.x(), c.z()), cam.getWidth() / (double) cam.getHeight());
        org.joml.Vector3f ahead = v.forward(new org.joml.Vector3f());
        cam.setFrustumPerspective((float) Math.toDegrees(v.fovY()), (float) v.aspect(), (float) v.near(),
                (float) v.far());
        cam.setLocation(new Vector3f((float) v.x(), (float) v.y(), (float) v.z()));
        cam.lookAtDirection(new Vector3f(ahead.x, ahead.y, ahead.z), Vector3f.UNIT_Y);
    }

    private Material lit(ColorRGBA colour) {
        Material m = new Material(assetManager, "Common/MatDefs/Light/Lighting.j3md");
        m.setBoolean("UseMaterialColors", true);
        m.setColor("Diffuse", colour);
        m.setColor("Ambient", colour);
        return m;
    }

    private void keys() {
        inputManager.addMapping("left", new KeyTrigger(KeyInput.KEY_LEFT), new KeyTrigger(KeyInput.KEY_A));
        inputManager.addMapping("right", new KeyTrigger(KeyInput.KEY_RIGHT), new KeyTrigger(KeyInput.KEY_D));
        inputManager.addMapping("ahead", new KeyTrigger(KeyInput.KEY_UP), new KeyTrigger(KeyInput.KEY_W));
        inputManager.addMapping("back", new KeyTrigger(KeyInput.KEY_DOWN), new KeyTrigger(KeyInput.KEY_S));
        inputManager.addListener((com.jme3.input.controls.ActionListener) (name, pressed, tpf) -> {
            float d = pressed ? 1 : -1;
            switch (name) {
                case "left" -> turn += d;
                case "right" -> turn -= d;
                case "ahead" -> ahead += d;
                case "back" -> ahead -= d;
                default -> { }
            }
        }, "left", "right", "ahead", "back");
    }

    @Override
    public void simpleUpdate(float tpf) {
        if (capture != null) {
            capture.beforeFrame();
        }
        time += tpf;
        if (playerFlow != null) {
            walk(tpf);
            plants.simulation().moveAgent(playerFlow, playerX, playerZ);
            follow();
        }
        hudText.setLength(0);
        hudText.append("JEcoSys in jME: ").append(plants.simulation().plantCount()).append(" plants, ")
                .append(Math.round(timer.getFrameRate())).append(" fps; WASD walks");
        hud.setText(hudText);
        float top = cam.getHeight() - 12;
        hud.setLocalTranslation(12, top, 0);
        hudPanel.setLocalScale(hud.getLineWidth() + 12, hud.getLineHeight() + 12, 1);
        hudPanel.setLocalTranslation(6, top - hud.getLineHeight() - 6, 0);
    }

    /** The player: the scripted loop, or the keys when one is held. */
    private void walk(float dt) {
        if (turn != 0 || ahead != 0) {
            heading += 1.8f * turn * dt;
            playerX += FastMath.cos(heading) * SPEED * ahead * dt;
            playerZ += FastMath.sin(heading) * SPEED * ahead * dt;
            playerX = (float) Math.max(terrain.minX() + 0.5, Math.min(terrain.maxX() - 0.5, playerX));
            playerZ = (float) Math.max(terrain.minZ() + 0.5, Math.min(terrain.maxZ() - 0.5, playerZ));
        } else {
            // the loop: a circle around the middle of the field, walked counter-clockwise seen from above
            float a = time * SPEED / loopRadius;
            playerX = centreX + loopRadius * FastMath.cos(a);
            playerZ = centreZ - loopRadius * FastMath.sin(a);
            heading = -a - FastMath.HALF_PI;
        }
        player.setLocalTranslation(playerX, (float) terrain.height(playerX, playerZ) + 0.85f, playerZ);
        player.setLocalRotation(UPRIGHT);
    }

    /** A cylinder's axis is its Z: stand it up. */
    private static final Quaternion UPRIGHT = new Quaternion().fromAngleAxis(FastMath.HALF_PI, Vector3f.UNIT_X);

    /** The camera: behind the player and above it, looking a little ahead of it. */
    private void follow() {
        float fx = FastMath.cos(heading);
        float fz = FastMath.sin(heading);
        float ex = playerX - 3.2f * fx;
        float ez = playerZ - 3.2f * fz;
        eye.set(ex, (float) terrain.height(ex, ez) + 2.6f, ez);
        target.set(playerX + 1.5f * fx, (float) terrain.height(playerX, playerZ) + 0.2f, playerZ + 1.5f * fz);
        cam.setLocation(eye);
        cam.lookAt(target, Vector3f.UNIT_Y);
    }

    /** The failed start or a failure in the loop: said on stderr, and the process exits with 1. */
    @Override
    public void handleError(String message, Throwable t) {
        System.err.println("jme-meadow: " + message);
        if (t != null) {
            t.printStackTrace();
        }
        exitCode = 1;
        if (context != null) {
            stop();
        }
        done.countDown(); // a context that never started never calls destroy()
    }

    @Override
    public void destroy() {
        try {
            super.destroy(); // app states' cleanup: the plants' GL objects and simulation
        } finally {
            done.countDown();
        }
    }

    // what the test mode reads
    PlantAppState plants() {
        return plants;
    }

    float playerX() {
        return playerX;
    }

    float playerZ() {
        return playerZ;
    }

    BitmapText hud() {
        return hud;
    }

    /**
     * Runs the game.
     *
     * @param args see the class comment
     * @throws InterruptedException when interrupted while the game runs
     */
    public static void main(String[] args) throws InterruptedException {
        Options o;
        try {
            o = parse(args);
        } catch (IllegalArgumentException e) {
            System.err.println("jme-meadow: " + e.getMessage());
            System.err.println("usage: JmeMeadowGame [--scene FILE] [--size WxH] [--renderer core|core33|compat] "
                    + "[--no-gamma] [--frames N --screenshot FILE.png] [--restart-at N] [--graphics-debug] "
                    + "[--start-view] [--ground-screenshot FILE.png] [--sheen FILE]");
            System.exit(2);
            return;
        }
        JmeMeadowGame app = new JmeMeadowGame(o);
        AppSettings s = new AppSettings(true);
        s.setTitle("JEcoSys meadow (jMonkeyEngine)");
        s.setRenderer(o.renderer());
        s.setResolution(o.width(), o.height());
        s.setDepthBits(24);
        s.setGammaCorrection(o.gamma());
        s.setAudioRenderer(null);
        s.setGraphicsDebug(o.debug());
        if (o.frames() > 0) {
            s.setVSync(false);
            s.setFrameRate(-1);
            s.setResizable(false);
            app.setTimer(new FixedTimer(1 / 30f));
        }
        app.setSettings(s);
        app.setShowSettings(false);
        app.setPauseOnLostFocus(false);
        app.start(); // on Linux the game runs on the thread "jME3 Main"
        app.done.await();
        System.exit(app.exitCode);
    }

    static Options parse(String[] args) {
        String scene = "meadow/patch.xml";
        int w = 1280;
        int h = 720;
        String renderer = AppSettings.LWJGL_OPENGL32;
        boolean gamma = true;
        int frames = 0;
        Path shot = null;
        int restartAt = 0;
        boolean debug = false;
        boolean startView = false;
        Path groundShot = null;
        Path sheen = null;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            switch (a) {
                case "--scene" -> {
                    Path p = Path.of(value(args, ++i, a));
                    if (!Files.isRegularFile(p)) {
                        throw new IllegalArgumentException("--scene: no file " + p);
                    }
                    scene = p.toAbsolutePath().normalize().toString();
                }
                case "--size" -> {
                    String[] wh = value(args, ++i, a).split("x");
                    if (wh.length != 2) {
                        throw new IllegalArgumentException("--size: WxH, e.g. 640x360");
                    }
                    w = Integer.parseInt(wh[0]);
                    h = Integer.parseInt(wh[1]);
                }
                case "--renderer" -> renderer = switch (value(args, ++i, a)) {
                    case "core" -> AppSettings.LWJGL_OPENGL32;
                    case "core33" -> AppSettings.LWJGL_OPENGL33;
                    case "compat" -> AppSettings.LWJGL_OPENGL2;
                    default -> throw new IllegalArgumentException("--renderer: core, core33 or compat");
                };
                case "--no-gamma" -> gamma = false;
                case "--frames" -> frames = Integer.parseInt(value(args, ++i, a));
                case "--screenshot" -> shot = Path.of(value(args, ++i, a));
                case "--restart-at" -> restartAt = Integer.parseInt(value(args, ++i, a));
                case "--graphics-debug" -> debug = true;
                case "--start-view" -> startView = true;
                case "--ground-screenshot" -> groundShot = Path.of(value(args, ++i, a));
                case "--sheen" -> sheen = Path.of(value(args, ++i, a));
                default -> throw new IllegalArgumentException("unknown argument " + a);
            }
        }
        if (w < 16 || h < 16 || frames < 0) {
            throw new IllegalArgumentException("--size at least 16x16, --frames at least 0");
        }
        if (restartAt < 0 || restartAt > 0 && restartAt >= frames) {
            throw new IllegalArgumentException("--restart-at: a frame before the last (--frames)");
        }
        if (frames > 0 && shot == null) {
            throw new IllegalArgumentException("--frames needs --screenshot FILE.png");
        }
        if (frames == 0 && (startView || groundShot != null || sheen != null)) {
            throw new IllegalArgumentException("--start-view, --ground-screenshot and --sheen are for the test mode (--frames)");
        }
        return new Options(scene, w, h, renderer, gamma, frames, shot, restartAt, debug, startView, groundShot, sheen);
    }

    private static String value(String[] args, int i, String flag) {
        if (i >= args.length) {
            throw new IllegalArgumentException(flag + " needs a value");
        }
        return args[i];
    }
}
