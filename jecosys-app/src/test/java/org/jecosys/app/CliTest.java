package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The command line: names, flags, exit codes and messages that scripts rely on. */
class CliTest {
    record Result(int code, String out, String err) {
    }

    static Result run(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Main.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        return new Result(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    @Test
    void helpListsEveryCommand() {
        Result r = run("--help");
        assertEquals(0, r.code());
        for (String c : new String[] {"view", "check", "simulate", "render", "bench", "gallery"}) {
            assertTrue(r.out().contains("  " + c + " "), c);
        }
    }

    @Test
    void everyCommandHasHelp() {
        for (String c : new String[] {"view", "check", "simulate", "render", "bench", "gallery"}) {
            Result r = run(c, "--help");
            assertEquals(0, r.code(), c);
            assertTrue(r.out().startsWith("Usage: jecosys " + c), c);
        }
        assertTrue(run("simulate", "--help").out().contains("--dump=FILE.csv"));
        assertTrue(run("render", "--help").out().contains("--size=WxH"));
    }

    @Test
    void versionPrintsTheProjectVersion() {
        Result r = run("--version");
        assertEquals(0, r.code());
        assertTrue(r.out().matches("jecosys \\d+\\.\\d+\\.\\d+.*\\(Java .*\\)\\s*"), r.out());
    }

    @Test
    void aBadFlagPrintsUsageAndExits2() {
        Result r = run("check", "--bogus", "scenes/meadow.xml");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("Unknown option: '--bogus'"), r.err());
        assertTrue(r.err().contains("Usage: jecosys check"), r.err());
    }

    @Test
    void badFlagValuesNameTheFlagAndWhatIsAllowed() {
        Result mode = run("simulate", "scenes/meadow.xml", "--mode", "fast");
        assertEquals(2, mode.code());
        assertTrue(mode.err().contains("expected static, random or constraint"), mode.err());
        Result steps = run("simulate", "scenes/meadow.xml", "--steps", "0");
        assertEquals(2, steps.code());
        assertTrue(steps.err().contains("--steps must be in [1, 10000000], got 0"), steps.err());
        Result dt = run("simulate", "scenes/meadow.xml", "--dt", "NaN");
        assertEquals(2, dt.code());
        assertTrue(dt.err().contains("--dt must be in [1e-5, 1]"), dt.err());
        Result size = run("render", "scenes/meadow.xml", "--frames", "1", "--out", "x", "--size", "10x10");
        assertEquals(2, size.code());
        assertTrue(size.err().contains("each side must be in [16, 8192]"), size.err());
        Result field = run("simulate", "scenes/meadow.xml", "--field", "maybe");
        assertEquals(2, field.code());
        assertTrue(field.err().contains("--field"), field.err());
        Result quality = run("render", "scenes/c1.xml", "--frames", "1", "--out", "x", "--quality", "ultra");
        assertEquals(2, quality.code());
        assertTrue(quality.err().contains("--quality") && quality.err().contains("expected low, medium or high"),
                quality.err());
    }

    @Test
    void checkAcceptsEveryShippedScene() throws Exception {
        String[] args;
        try (var s = java.nio.file.Files.list(java.nio.file.Path.of("scenes"))) {
            args = java.util.stream.Stream.concat(java.util.stream.Stream.of("check"),
                    s.map(Object::toString).filter(p -> p.endsWith(".xml")).sorted()).toArray(String[]::new);
        }
        Result r = run(args);
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("scenes/meadow.xml: ok"), r.out());
    }

    @Test
    void checkOnABrokenFilePrintsFileLineColumnAndExits2() {
        String bad = "jecosys-core/src/test/resources/org/jecosys/scene/bad/unknown-attribute.xml";
        Result r = run("check", "scenes/meadow.xml", bad);
        assertEquals(2, r.code());
        assertTrue(r.out().contains("scenes/meadow.xml: ok"));
        assertTrue(r.err().contains(bad + ":6:51: unknown attribute 'lenght' on <component>; did you mean 'length'?"),
                r.err());
        assertFalse(r.err().contains("Exception"), r.err());
        assertFalse(r.err().contains("\tat "), r.err());
    }

    @Test
    void theDefaultCommandIsViewOnTheDefaultScene() {
        // no display in tests: view falls back to rendering headless and says where
        System.setProperty(ViewCommand.FALLBACK_OUT, "target/cli-test/fallback");
        System.setProperty(ViewCommand.FALLBACK_FRAMES, "1");
        try {
            Result r = run();
            assertTrue(r.out().contains("Scene 'Meadow' (scenes/meadow.xml) is valid."), r.out());
            if (!org.jecosys.render.GlContext.hasDisplay()) {
                assertEquals(0, r.code(), r.err());
                assertTrue(r.out().contains("No display"), r.out());
                assertTrue(r.out().contains("target/cli-test/fallback"), r.out());
                assertTrue(java.nio.file.Files.exists(java.nio.file.Path.of("target/cli-test/fallback/frame-00001.png")));
                // a scene named on the command line goes to view too (a small one: the meadow was just drawn)
                Result named = run("scenes/c1.xml");
                assertEquals(r.code(), named.code(), named.err());
                assertTrue(named.out().contains("(scenes/c1.xml) is valid."), named.out());
            }
        } finally {
            System.clearProperty(ViewCommand.FALLBACK_OUT);
            System.clearProperty(ViewCommand.FALLBACK_FRAMES);
        }
    }

    @Test
    void renderWritesPngFramesAndMaps() throws Exception {
        java.nio.file.Path out = java.nio.file.Path.of("target/cli-test/render");
        java.nio.file.Path gif = out.resolve("strip.gif");
        Result r = run("render", "scenes/c1.xml", "--frames", "2", "--out", out.toString(), "--size", "96x64", "--maps",
                "--gif", gif.toString(), "--quality", "LOW");
        assertEquals(0, r.code(), r.err());
        for (String f : new String[] {"frame-00001.png", "frame-00002.png", "water.png", "nutrients.png",
                "species.png"}) {
            assertTrue(java.nio.file.Files.size(out.resolve(f)) > 100, f);
        }
        java.awt.image.BufferedImage img = javax.imageio.ImageIO.read(out.resolve("frame-00002.png").toFile());
        assertEquals(96, img.getWidth());
        assertEquals(64, img.getHeight());
        assertTrue(r.out().contains("Wrote 2 frame(s) of 96x64"), r.out());
        try (javax.imageio.stream.ImageInputStream in = javax.imageio.ImageIO.createImageInputStream(gif.toFile())) {
            javax.imageio.ImageReader reader = javax.imageio.ImageIO.getImageReadersBySuffix("gif").next();
            reader.setInput(in);
            assertEquals(2, reader.getNumImages(true), "one GIF frame per rendered frame");
            assertEquals(96, reader.read(1).getWidth());
        }
    }

    @Test
    void aMissingSceneIsBadInput() {
        Result r = run("view", "no/such/scene.xml");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("no/such/scene.xml: no such file"), r.err());
    }
}
