package com.example.jmemeadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
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
 * The jMonkeyEngine example in its test mode, in a child JVM on a virtual display (Xvfb): 40 frames of
 * the example's meadow at 640 x 360 on jME's core-profile renderer ({@code LWJGL_OPENGL32}, its
 * default) and on its compatibility-profile one ({@code LWJGL_OPENGL2}), with jME's default gamma
 * correction; the screenshot (read after the GUI viewport) shows the HUD text, the game's own ground,
 * its player and the JEcoSys plants where the example says they are, the player has pushed the plants
 * around it, and no phase of any frame raised a GL error. The runs go at once, each on its own
 * display: much of a run is single-threaded (the JVM's start, Mesa compiling shaders). One more run
 * shows the showcase meadow ({@code scenes/meadow.xml}) from its start camera at 960 x 540 on jME's
 * default back buffer (no samples) and the example's own brown ground (issue 38): the plants' ground
 * cover hides the game's ground ({@link #theMeadowsStartViewHidesTheGamesGroundUnderTheCover}).
 */
class JmeMeadowExampleTest {
    private static final String TAG = "[jme-meadow]";
    private static final Path OUT = Path.of("examples/jme/target/example-test");
    private static final List<VirtualDisplay> DISPLAYS = new ArrayList<>();
    private static ExecutorService runs;
    /** The core-profile run with jME's default gamma correction: two tests read it. */
    private static Future<ExampleShot> core;
    private static Future<ExampleShot> compat;
    private static Future<ExampleShot> coreNoGamma;
    /** The core-profile run restarted (a new GL context) after frame 10, with jME's graphics debugging. */
    private static Future<ExampleShot> restarted;
    /** The meadow's start view at 960 x 540, three frames, with the ground read before the plants. */
    private static Future<ExampleShot> startView;
    /** The meadow's start view in the examples' tests: the scene, the picture's size. */
    static final String MEADOW = "scenes/meadow.xml";
    static final int START_W = 960;
    static final int START_H = 540;

    @BeforeAll
    static void startTheRuns() throws Exception {
        runs = Executors.newFixedThreadPool(5);
        core = start("core", 640, 360, 40, "--renderer", "core");
        restarted = start("core-restart", 640, 360, 40, "--renderer", "core", "--restart-at", "10",
                "--graphics-debug");
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

    /**
     * The compatibility-profile run and the run without gamma correction, started when a test first asks
     * (their tests are tagged slow: the default run leaves them to the nightly one).
     */
    private static synchronized Future<ExampleShot> compat() throws Exception {
        if (compat == null) {
            compat = start("compat", 640, 360, 40, "--renderer", "compat");
        }
        return compat;
    }

    private static synchronized Future<ExampleShot> coreNoGamma() throws Exception {
        if (coreNoGamma == null) {
            coreNoGamma = start("core-no-gamma", 640, 360, 40, "--renderer", "core", "--no-gamma");
        }
        return coreNoGamma;
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
        List<String> args = new ArrayList<>(List.of("--frames", String.valueOf(frames), "--screenshot",
                png.toString(), "--size", w + "x" + h));
        args.addAll(List.of(extra));
        ChildJvm.Result r = ChildJvm.run(JmeMeadowGame.class.getName(), args, Map.of("DISPLAY", display.name()),
                90 + frames);
        Files.writeString(OUT.resolve(name + ".log"), r.output());
        assertEquals(0, r.exitCode(), "the example's exit status; it printed:\n" + r.output());
        assertTrue(Files.isRegularFile(png), "the screenshot " + png);
        ExampleShot shot = ExampleShot.read(png, r.output(), TAG);
        assertEquals(w, shot.image().getWidth());
        assertEquals(h, shot.image().getHeight());
        return shot;
    }

    @Test
    void theCoreProfileShowsHudGroundPlayerAndPushedPlantsWithoutGlErrors() throws Exception {
        ExampleShot shot = shot(core);
        assertEquals(List.of(), shot.problems(), "see " + OUT.resolve("core.png"));
        String log = Files.readString(OUT.resolve("core.log"));
        assertTrue(log.contains("1 textures, 1 glTF meshes"), "the petal texture and the seed head's glTF file, "
                + "through jME's asset manager:\n" + log);
    }

    @Test
    @org.junit.jupiter.api.Tag("slow")
    void theCompatibilityProfileShowsTheSame() throws Exception {
        ExampleShot shot = shot(compat());
        assertEquals(List.of(), shot.problems(), "see " + OUT.resolve("compat.png"));
    }

    /**
     * {@code app.restart()} after frame 10 gives jME a new GL context: the plants' renderer notices it at
     * its next frame (context generation 1), forgets its old objects without a GL call and makes them
     * again: the first frame after the restart changes as many pixels in its plants' pass (the frame
     * read before and after the pass) as the last frame before it, within 5%, and the last frame shows
     * as many plant pixels (within 5%) as the run without a restart, with jME's graphics debugging on (a
     * GL error check after each of its calls: any error fails the game), no GL error in any phase, and a
     * clean exit (status 0, the screenshot checks pass).
     */
    @Test
    void afterRestartWithANewContextThePlantsAreDrawnAsBeforeWithoutGlErrors() throws Exception {
        ExampleShot shot = shot(restarted);
        ExampleShot plain = shot(core);
        assertEquals(List.of(), shot.problems(), "see " + OUT.resolve("core-restart.png"));
        String log = Files.readString(OUT.resolve("core-restart.log"));
        assertTrue(log.contains(TAG + " context generation 1"), "the renderer saw one new context:\n" + log);
        int before = plantPassPixels(log, 10, 0);
        int next = plantPassPixels(log, 11, 1);
        int last = plantPassPixels(log, 40, 1);
        System.out.printf("[look] jME example, restart() after frame 10 (graphics debugging on, %s): the plants' pass"
                + " changes %d pixels in frame 10 (before), %d in frame 11 (first after, %+.2f%%), %d in frame 40%n",
                shot.noGlErrors() ? "no GL error" : "GL errors", before, next, 100.0 * (next - before) / before, last);
        assertTrue(before > 1000, "plant pass pixels before the restart: " + before);
        assertTrue(Math.abs(next - before) <= 0.05 * before,
                "plant pass pixels in the first frame after restart() " + next + ", in the last before " + before);
        int w = shot.image().getWidth();
        int h = shot.image().getHeight();
        int after = shot.count(ExampleShot::plant, 0, 0, w, h);
        int without = plain.count(ExampleShot::plant, 0, 0, w, h);
        System.out.printf("%s plant pixels: %d after restart(), %d without%n", TAG, after, without);
        assertTrue(without > 1000, "plant pixels without a restart: " + without);
        assertTrue(Math.abs(after - without) <= 0.05 * without,
                "plant pixels after restart() " + after + ", without " + without);
    }

    /** What the restart run printed for a frame: the pixels the plants' pass changed, in the given context generation. */
    private static int plantPassPixels(String log, int frame, int generation) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile(java.util.regex.Pattern.quote(TAG)
                + " plant pass pixels in frame " + frame + ": (\\d+) \\(context generation " + generation + "\\)")
                .matcher(log);
        assertTrue(m.find(), "frame " + frame + "'s plant pass pixels (context generation " + generation + "):\n" + log);
        return Integer.parseInt(m.group(1));
    }

    /**
     * With jME's gamma correction (GL_FRAMEBUFFER_SRGB on an sRGB back buffer) the plants keep their
     * hue: the renderer writes its display colours unconverted while it draws (converted again by the
     * framebuffer, the median plant pixel came out 50 to 70 levels lighter, and the darker channels
     * about three times lighter: a washed-out hue). They do get lighter, as the game's own models do:
     * the root node's lights are linear under gamma correction and light the plants encoded to display
     * values (about 1.35 times brighter here), and the thin blades, blended by their coverage on this
     * back buffer without samples, carry some of the lighter ground. So each channel's ratio, with gamma
     * to without, lies in [1, 1.8] and the three ratios agree within 0.4.
     */
    @Test
    @org.junit.jupiter.api.Tag("slow")
    void gammaCorrectionKeepsThePlantsColours() throws Exception {
        ExampleShot linear = shot(coreNoGamma());
        ExampleShot gamma = shot(core);
        int[] a = linear.median(ExampleShot::plant, linear.plants(), 4);
        int[] b = gamma.median(ExampleShot::plant, gamma.plants(), 4);
        assertNotNull(a);
        assertNotNull(b);
        String both = "median plant colour without gamma " + java.util.Arrays.toString(a) + ", with gamma "
                + java.util.Arrays.toString(b);
        double least = Double.MAX_VALUE;
        double most = 0;
        for (int c = 0; c < 3; c++) {
            double ratio = b[c] / (double) Math.max(1, a[c]);
            assertTrue(ratio >= 0.97 && ratio <= 1.8, "channel " + c + ": " + both);
            least = Math.min(least, ratio);
            most = Math.max(most, ratio);
        }
        assertTrue(most - least <= 0.4, "the hue is kept: " + both);
    }

    /**
     * Issue 38: the meadow's start view (its scene camera, 960 x 540) on jME's default back buffer (no
     * samples) with its default gamma correction, over the example's own lit brown ground: at most 5%
     * of the lower half keeps the game's ground colour. A pixel keeps it when it has, within 3 levels or
     * 6% a channel ({@link ExampleLook#groundShare}), the colour the same pixel had in the same frame
     * before the plants' pass: the ground as the game lit it, whatever its light and normals; the
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
        System.out.printf("[look] jME example, meadow start view %dx%d, 0 samples: %.2f%% of the lower half keeps"
                + " the game's ground colour (<= 5%%)%n", START_W, START_H, 100 * share);
        assertTrue(share <= 0.05, String.format("%.1f%% of the lower half shows the game's ground, want <= 5%%; see %s",
                100 * share, OUT.resolve("start-view.png")));
    }
}
