package com.example.gdxmeadow;

import com.badlogic.gdx.assets.loaders.FileHandleResolver;
import com.badlogic.gdx.assets.loaders.resolvers.AbsoluteFileHandleResolver;
import com.badlogic.gdx.assets.loaders.resolvers.InternalFileHandleResolver;
import com.badlogic.gdx.backends.lwjgl3.Lwjgl3Application;
import com.badlogic.gdx.backends.lwjgl3.Lwjgl3ApplicationConfiguration;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Starts {@link GdxMeadowGame} in a libGDX LWJGL 3 window.
 * <pre>
 * GdxMeadowLauncher [--scene FILE] [--size WxH] [--gl30] [--frames N --screenshot FILE.png]
 *                   [--start-view] [--ground-screenshot FILE.png] [--sheen FILE]
 * </pre>
 * {@code --scene} is a scene file on disk (default: {@code meadow/patch.xml}, an internal file found on
 * the classpath); {@code --gl30} asks libGDX for an OpenGL 3.3 core context (default: libGDX's GL20
 * emulation, a compatibility context); {@code --frames N} is the test mode: N frames at a fixed 1/30 s
 * after the scene has loaded, then the back buffer (HUD included) is saved to {@code --screenshot},
 * what the test checks is printed, and the game exits with 0. In the test mode, {@code --start-view}
 * puts the camera at the scene's start camera ({@code <camera>}: its pose above the ground and its
 * lens), standing still, and leaves the player and its flow out: the meadow's start view, as the
 * library's viewer opens it; {@code --ground-screenshot} also saves the last frame as it is before
 * the plants are drawn (the game's ground as lit, the player); {@code --sheen} writes, for every
 * frame, the mean luminance of each 16 x 16 block of the picture after the plants and before the HUD
 * ({@link TestCapture#blockLuminance}).
 */
public final class GdxMeadowLauncher {
    private GdxMeadowLauncher() {
    }

    /**
     * What the game starts with.
     *
     * @param scene          the scene's asset name (internal file) or absolute path
     * @param width          window width, pixels
     * @param height         window height, pixels
     * @param gl30           OpenGL 3.3 core instead of libGDX's default GL20 emulation
     * @param frames         test mode: frames to render before the screenshot; 0 to play
     * @param screenshot     test mode: where to write the PNG
     * @param playerStrength the player's flow strength, m²/s
     * @param startView      test mode: the scene's start camera, still, and no player
     * @param groundShot     test mode: where to write the last frame before the plants, or null
     * @param sheen          test mode: where to write the frames' block luminance, or null
     */
    record Options(String scene, int width, int height, boolean gl30, int frames, Path screenshot,
                   double playerStrength, boolean startView, Path groundShot, Path sheen) {
    }

    /**
     * Runs the game.
     *
     * @param args see the class comment
     */
    public static void main(String[] args) {
        Options o;
        try {
            o = parse(args);
        } catch (IllegalArgumentException e) {
            System.err.println("gdx-meadow: " + e.getMessage());
            System.err.println("usage: GdxMeadowLauncher [--scene FILE] [--size WxH] [--gl30] "
                    + "[--frames N --screenshot FILE.png] [--start-view] [--ground-screenshot FILE.png] [--sheen FILE]");
            System.exit(2);
            return;
        }
        // a scene file on disk by its absolute path; otherwise an internal file (the working
        // directory, then the classpath), where the example's own scene is
        FileHandleResolver resolver = Path.of(o.scene()).isAbsolute() ? new AbsoluteFileHandleResolver()
                : new InternalFileHandleResolver();
        Lwjgl3ApplicationConfiguration config = new Lwjgl3ApplicationConfiguration();
        config.setTitle("JEcoSys meadow (libGDX)");
        config.setWindowedMode(o.width(), o.height());
        config.setBackBufferConfig(8, 8, 8, 8, 24, 0, 0); // 24-bit depth: libGDX's default is 16
        config.disableAudio(true);
        if (o.gl30()) {
            config.setOpenGLEmulation(Lwjgl3ApplicationConfiguration.GLEmulation.GL30, 3, 3);
        }
        if (o.frames() > 0) {
            config.useVsync(false);
            config.setForegroundFPS(0);
            config.setResizable(false);
        }
        int code = 0;
        try {
            new Lwjgl3Application(new GdxMeadowGame(o, resolver), config); // returns once the game has exited
        } catch (RuntimeException e) {
            e.printStackTrace();
            code = 1;
        }
        System.exit(code);
    }

    static Options parse(String[] args) {
        String scene = "meadow/patch.xml";
        int w = 1280;
        int h = 720;
        boolean gl30 = false;
        int frames = 0;
        Path shot = null;
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
                case "--gl30" -> gl30 = true;
                case "--frames" -> frames = Integer.parseInt(value(args, ++i, a));
                case "--screenshot" -> shot = Path.of(value(args, ++i, a));
                case "--start-view" -> startView = true;
                case "--ground-screenshot" -> groundShot = Path.of(value(args, ++i, a));
                case "--sheen" -> sheen = Path.of(value(args, ++i, a));
                default -> throw new IllegalArgumentException("unknown argument " + a);
            }
        }
        if (w < 16 || h < 16 || frames < 0) {
            throw new IllegalArgumentException("--size at least 16x16, --frames at least 0");
        }
        if (frames > 0 && shot == null) {
            throw new IllegalArgumentException("--frames needs --screenshot FILE.png");
        }
        if (frames == 0 && (startView || groundShot != null || sheen != null)) {
            throw new IllegalArgumentException("--start-view, --ground-screenshot and --sheen are for the test mode (--frames)");
        }
        return new Options(scene, w, h, gl30, frames, shot, GdxMeadowGame.PLAYER_STRENGTH, startView, groundShot, sheen);
    }

    private static String value(String[] args, int i, String flag) {
        if (i >= args.length) {
            throw new IllegalArgumentException(flag + " needs a value");
        }
        return args[i];
    }
}
