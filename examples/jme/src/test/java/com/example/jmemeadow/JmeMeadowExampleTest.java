package com.example.jmemeadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.jecosys.render.ChildJvm;
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
 * around it, and no phase of any frame raised a GL error. The three runs go at once, each on its own
 * display: much of a run is single-threaded (the JVM's start, Mesa compiling shaders).
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

    @BeforeAll
    static void startTheRuns() throws Exception {
        runs = Executors.newFixedThreadPool(4);
        core = start("core", "--renderer", "core");
        compat = start("compat", "--renderer", "compat");
        coreNoGamma = start("core-no-gamma", "--renderer", "core", "--no-gamma");
        restarted = start("core-restart", "--renderer", "core", "--restart-at", "10", "--graphics-debug");
    }

    @AfterAll
    static void stopDisplays() {
        if (runs != null) {
            runs.shutdownNow();
        }
        DISPLAYS.forEach(VirtualDisplay::close);
    }

    /** Starts a run on a display of its own. */
    private static Future<ExampleShot> start(String name, String... extra) throws Exception {
        VirtualDisplay display = VirtualDisplay.start(1024, 768);
        DISPLAYS.add(display);
        return runs.submit(() -> run(display, name, extra));
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

    private static ExampleShot run(VirtualDisplay display, String name, String... extra) throws Exception {
        Files.createDirectories(OUT);
        Path png = OUT.resolve(name + ".png");
        Files.deleteIfExists(png);
        List<String> args = new ArrayList<>(List.of("--frames", "40", "--screenshot", png.toString(),
                "--size", "640x360"));
        args.addAll(List.of(extra));
        ChildJvm.Result r = ChildJvm.run(JmeMeadowGame.class.getName(), args, Map.of("DISPLAY", display.name()), 90);
        Files.writeString(OUT.resolve(name + ".log"), r.output());
        assertEquals(0, r.exitCode(), "the example's exit status; it printed:\n" + r.output());
        assertTrue(Files.isRegularFile(png), "the screenshot " + png);
        ExampleShot shot = ExampleShot.read(png, r.output(), TAG);
        assertEquals(640, shot.image().getWidth());
        assertEquals(360, shot.image().getHeight());
        return shot;
    }

    @Test
    void theCoreProfileShowsHudGroundPlayerAndPushedPlantsWithoutGlErrors() throws Exception {
        ExampleShot shot = shot(core);
        assertEquals(List.of(), shot.problems(), "see " + OUT.resolve("core.png"));
    }

    @Test
    void theCompatibilityProfileShowsTheSame() throws Exception {
        ExampleShot shot = shot(compat);
        assertEquals(List.of(), shot.problems(), "see " + OUT.resolve("compat.png"));
    }

    /**
     * {@code app.restart()} after frame 10 gives jME a new GL context: the plants' renderer notices it at
     * its next frame (context generation 1), forgets its old objects without a GL call and makes them
     * again, so the last frame shows as many plant pixels (within 5%) as the run without a restart,
     * with jME's graphics debugging on (a GL error check after each of its calls: any error fails the
     * game), no GL error in any phase, and a clean exit (status 0, the screenshot checks pass).
     */
    @Test
    void afterRestartWithANewContextThePlantsAreDrawnAsBeforeWithoutGlErrors() throws Exception {
        ExampleShot shot = shot(restarted);
        ExampleShot plain = shot(core);
        assertEquals(List.of(), shot.problems(), "see " + OUT.resolve("core-restart.png"));
        String log = Files.readString(OUT.resolve("core-restart.log"));
        assertTrue(log.contains(TAG + " context generation 1"), "the renderer saw one new context:\n" + log);
        int w = shot.image().getWidth();
        int h = shot.image().getHeight();
        int after = shot.count(ExampleShot::plant, 0, 0, w, h);
        int without = plain.count(ExampleShot::plant, 0, 0, w, h);
        System.out.printf("%s plant pixels: %d after restart(), %d without%n", TAG, after, without);
        assertTrue(without > 1000, "plant pixels without a restart: " + without);
        assertTrue(Math.abs(after - without) <= 0.05 * without,
                "plant pixels after restart() " + after + ", without " + without);
    }

    /**
     * With jME's gamma correction (GL_FRAMEBUFFER_SRGB on an sRGB back buffer) the plants keep their
     * hue: the renderer writes its display colours unconverted while it draws (converted again by the
     * framebuffer, the median plant pixel came out 50 to 70 levels lighter, and the darker channels
     * several times lighter: a washed-out hue). They do get lighter, as the game's own models do: the
     * root node's lights are linear under gamma correction and light the plants encoded to display
     * values (about 1.3 times brighter here). So each channel's ratio, with gamma to without, lies in
     * [1, 1.6] and the three ratios agree within 0.1.
     */
    @Test
    void gammaCorrectionKeepsThePlantsColours() throws Exception {
        ExampleShot linear = shot(coreNoGamma);
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
            assertTrue(ratio >= 0.97 && ratio <= 1.6, "channel " + c + ": " + both);
            least = Math.min(least, ratio);
            most = Math.max(most, ratio);
        }
        assertTrue(most - least <= 0.1, "the hue is kept: " + both);
    }
}
