package com.example.gdxmeadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
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
 * The libGDX example in its test mode, in a child JVM on a virtual display (Xvfb): 40 frames of the
 * example's meadow at 640 x 360 with libGDX's default context (GL20 emulation: a compatibility
 * profile) and with an OpenGL 3.3 core one, then its screenshot (read back after the HUD) shows the
 * HUD text, the game's own ground, its player and the JEcoSys plants where the example says they are,
 * the player has pushed the plants around it, and no phase of any frame raised a GL error. The two runs
 * go at once, each on its own display: much of a run is single-threaded (the JVM's start, Mesa
 * compiling shaders), so together they take little more than one.
 */
class GdxMeadowExampleTest {
    private static final String TAG = "[gdx-meadow]";
    private static final Path OUT = Path.of("examples/gdx/target/example-test");
    private static final List<VirtualDisplay> DISPLAYS = new java.util.ArrayList<>();
    private static ExecutorService runs;
    private static Future<ExampleShot> gl20;
    private static Future<ExampleShot> gl30;

    @BeforeAll
    static void startBothRuns() throws Exception {
        runs = Executors.newFixedThreadPool(2);
        gl20 = start("gl20");
        gl30 = start("gl30", "--gl30");
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
        List<String> args = new java.util.ArrayList<>(List.of("--frames", "40", "--screenshot", png.toString(),
                "--size", "640x360"));
        args.addAll(List.of(extra));
        ChildJvm.Result r = ChildJvm.run(GdxMeadowLauncher.class.getName(), args,
                Map.of("DISPLAY", display.name()), 90);
        Files.writeString(OUT.resolve(name + ".log"), r.output());
        assertEquals(0, r.exitCode(), "the example's exit status; it printed:\n" + r.output());
        assertTrue(Files.isRegularFile(png), "the screenshot " + png);
        ExampleShot shot = ExampleShot.read(png, r.output(), TAG);
        assertEquals(640, shot.image().getWidth());
        assertEquals(360, shot.image().getHeight());
        return shot;
    }

    @Test
    void theDefaultContextShowsHudGroundPlayerAndPushedPlantsWithoutGlErrors() throws Exception {
        ExampleShot shot = shot(gl20);
        assertEquals(List.of(), shot.problems(), "see " + OUT.resolve("gl20.png"));
    }

    @Test
    void anOpenGl33CoreContextShowsTheSame() throws Exception {
        ExampleShot shot = shot(gl30);
        assertEquals(List.of(), shot.problems(), "see " + OUT.resolve("gl30.png"));
    }
}
