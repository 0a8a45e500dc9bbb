package com.example.gdxmeadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import javax.imageio.ImageIO;
import org.jecosys.render.ChildJvm;
import org.jecosys.render.ExampleLook;
import org.jecosys.render.ExampleShot;
import org.jecosys.render.VirtualDisplay;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The libGDX example in its test mode, in a child JVM on a virtual display (Xvfb): 40 frames of the
 * example's meadow at 640 x 360 with libGDX's default context (GL20 emulation: a compatibility
 * profile) and with an OpenGL 3.3 core one, then its screenshot (read back after the HUD) shows the
 * HUD text, the game's own ground, its player and the JEcoSys plants where the example says they are,
 * the player has pushed the plants around it, and no phase of any frame raised a GL error. The two runs
 * go at once, each on its own display: much of a run is single-threaded (the JVM's start, Mesa
 * compiling shaders), so together they take little more than one. A third run shows the showcase
 * meadow ({@code scenes/meadow.xml}) from its start camera at 960 x 540 on the example's own back
 * buffer (no samples) and own brown ground (issue 38): the plants' ground cover hides the game's
 * ground ({@link #theMeadowsStartViewHidesTheGamesGroundUnderTheCover}).
 */
class GdxMeadowExampleTest {
    private static final String TAG = "[gdx-meadow]";
    private static final Path OUT = Path.of("examples/gdx/target/example-test");
    private static final List<VirtualDisplay> DISPLAYS = new java.util.ArrayList<>();
    private static ExecutorService runs;
    private static Future<ExampleShot> gl20;
    private static Future<ExampleShot> gl30;
    /** The meadow's start view at 960 x 540, three frames, with the ground read before the plants. */
    private static Future<ExampleShot> startView;
    /** The meadow's start view in the examples' tests: the scene, the picture's size. */
    static final String MEADOW = "scenes/meadow.xml";
    static final int START_W = 960;
    static final int START_H = 540;

    /** The OpenGL 3.3 core run, started when its test (tagged slow: the nightly run) first asks. */
    private static synchronized Future<ExampleShot> gl30() throws Exception {
        if (gl30 == null) {
            gl30 = start("gl30", 640, 360, 40, "--gl30");
        }
        return gl30;
    }

    @BeforeAll
    static void startBothRuns() throws Exception {
        runs = Executors.newFixedThreadPool(3);
        gl20 = start("gl20", 640, 360, 40);
        startView = start("start-view", START_W, START_H, 3, "--scene", MEADOW, "--start-view",
                "--ground-screenshot", OUT.resolve("start-view-ground.png").toString());
    }

    @AfterAll
    static void stopDisplays() {
        if (runs != null) {
            runs.shutdownNow();
        }
        DISPLAYS.forEach(VirtualDisplay::close);
    }

    /** Starts a run on a display of its own. */
    private static Future<ExampleShot> start(String name, int w, int h, int frames, String... extra) throws Exception {
        VirtualDisplay display = VirtualDisplay.start(1024, 768);
        DISPLAYS.add(display);
        return runs.submit(() -> run(display, name, w, h, frames, extra));
    }

    /** The run's screenshot, or what failed in the run, thrown as it was. */
    private static ExampleShot shot(Future<ExampleShot> run) throws Exception {
        try {
            return run.get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof Error error) {
                throw error;
            }
            throw (Exception) e.getCause();
        }
    }

    /**
     * Runs the example's test mode in a child JVM: {@code frames} frames at w x h, the screenshot to
     * {@code OUT/name.png}, its output to {@code OUT/name.log}; fails on a non-zero exit status.
     */
    static ExampleShot run(VirtualDisplay display, String name, int w, int h, int frames, String... extra)
            throws Exception {
        Files.createDirectories(OUT);
        Path png = OUT.resolve(name + ".png");
        Files.deleteIfExists(png);
        List<String> args = new java.util.ArrayList<>(List.of("--frames", String.valueOf(frames), "--screenshot",
                png.toString(), "--size", w + "x" + h));
        args.addAll(List.of(extra));
        ChildJvm.Result r = ChildJvm.run(GdxMeadowLauncher.class.getName(), args,
                Map.of("DISPLAY", display.name()), 90 + frames);
        Files.writeString(OUT.resolve(name + ".log"), r.output());
        assertEquals(0, r.exitCode(), "the example's exit status; it printed:\n" + r.output());
        assertTrue(Files.isRegularFile(png), "the screenshot " + png);
        ExampleShot shot = ExampleShot.read(png, r.output(), TAG);
        assertEquals(w, shot.image().getWidth());
        assertEquals(h, shot.image().getHeight());
        return shot;
    }

    @Test
    void theDefaultContextShowsHudGroundPlayerAndPushedPlantsWithoutGlErrors() throws Exception {
        ExampleShot shot = shot(gl20);
        assertEquals(List.of(), shot.problems(), "see " + OUT.resolve("gl20.png"));
        String log = Files.readString(OUT.resolve("gl20.log"));
        assertTrue(log.contains("1 textures, 1 glTF meshes"), "the petal texture and the seed head's glTF file, "
                + "through libGDX's asset manager:\n" + log);
    }

    @Test
    @org.junit.jupiter.api.Tag("slow")
    void anOpenGl33CoreContextShowsTheSame() throws Exception {
        ExampleShot shot = shot(gl30());
        assertEquals(List.of(), shot.problems(), "see " + OUT.resolve("gl30.png"));
    }

    /**
     * Issue 38: the meadow's start view (its scene camera, 960 x 540) on libGDX's default back buffer (no
     * samples: the launcher asks for none) over the example's own lit brown ground: at most 5% of the
     * lower half keeps the game's ground colour. A pixel keeps it when it has, within 3 levels or 6%
     * a channel ({@link ExampleLook#groundShare}), the colour the same pixel had in the same frame
     * before the plants were drawn: the ground as the game lit it, whatever its light and normals; the
     * ground cover's colours differ from it by tens of levels.
     */
    @Test
    void theMeadowsStartViewHidesTheGamesGroundUnderTheCover() throws Exception {
        ExampleShot shot = shot(startView);
        String log = Files.readString(OUT.resolve("start-view.log"));
        assertTrue(shot.noGlErrors(), "GL errors in the start view run:\n" + log);
        assertTrue(log.contains("back buffer samples 0"), "the default back buffer, no samples:\n" + log);
        BufferedImage ground = ImageIO.read(OUT.resolve("start-view-ground.png").toFile());
        double share = ExampleLook.groundShare(shot.image(), ground);
        double bare = ExampleLook.groundShare(ground, ground);
        assertTrue(bare >= 0.99, "the lower half of the frame before the plants is the game's ground: " + bare);
        System.out.printf("[look] libGDX example, meadow start view %dx%d, 0 samples: %.2f%% of the lower half keeps"
                + " the game's ground colour (<= 5%%)%n", START_W, START_H, 100 * share);
        assertTrue(share <= 0.05, String.format("%.1f%% of the lower half shows the game's ground, want <= 5%%; see %s",
                100 * share, OUT.resolve("start-view.png")));
    }
}
