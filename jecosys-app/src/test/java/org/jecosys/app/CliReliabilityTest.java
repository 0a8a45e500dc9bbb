package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.AtomicFiles;
import org.jecosys.scene.OutputFiles;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Simulation;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Reliability, third pass, at the command line: {@code simulate --dump} streams (its memory does not
 * grow with the output) and a write killed midway leaves no file under the final name (scene saves'
 * writer and the output writer of every CLI and bench file, see {@link CliOutputsTest}); {@code check}
 * refuses, with a location, every scene {@code simulate} refuses (a scene without species, a pipe, an
 * image outside the scene's folder), and the two agree on the fuzz corpus and its mutants.
 */
@Tag("reliability")
class CliReliabilityTest {
    @TempDir
    Path dir;

    private static final Path CORPUS = Path.of("jecosys-core/src/test/resources/org/jecosys/scene/SceneFuzzTestInputs/"
            + "loaderNeverFailsOtherwise");

    @Test
    void theDumpStreamsRowByRowWithMemoryIndependentOfItsSize() throws Exception {
        Scene scene = SceneFiles.read(Path.of("jecosys-core/src/test/resources/org/jecosys/sim/close-race-fixture.xml"));
        try (Simulation sim = Scenes.simulation(scene, 1, Progress.NONE)) {
            sim.stepFixed(ViewCamera.of(scene.def().camera(), 0, 16.0 / 9));
            com.sun.management.ThreadMXBean mx =
                    (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
            long id = Thread.currentThread().getId();
            long[] written = new long[1];
            OutputStream counting = new OutputStream() {
                @Override
                public void write(int b) {
                    written[0]++;
                }

                @Override
                public void write(byte[] b, int off, int len) {
                    written[0] += len;
                }
            };
            SimulateCommand.dump(sim, counting); // warm-up: classes, the encoder
            written[0] = 0;
            long before = mx.getThreadAllocatedBytes(id);
            SimulateCommand.dump(sim, counting);
            long allocated = mx.getThreadAllocatedBytes(id) - before;
            assertTrue(written[0] > 5_000_000, "the dump is large: " + written[0] + " bytes");
            // buffers of a few hundred kilobytes, not the output (a whole-file string is twice its size)
            assertTrue(allocated < 1_000_000, allocated + " bytes allocated to write " + written[0]);
        }
        Path csv = dir.resolve("state.csv");
        CliTest.Result r = CliTest.run("simulate", "jecosys-core/src/test/resources/org/jecosys/sim/close-race-fixture.xml",
                "--steps", "2", "--threads", "2", "--dump", csv.toString());
        assertEquals(0, r.code(), r.err());
        try (Stream<String> rows = Files.lines(csv)) {
            assertEquals(50_001, rows.count(), "a header and a row per component");
        }
    }

    @Test
    void aWriteKilledMidwayLeavesNoFileUnderTheFinalNameAndTheOldOneWhole() throws Exception {
        Path target = dir.resolve("dump.csv");
        // the scene save's writer, and the output writer of every CLI and bench file, streamed (--dump,
        // --json, --gif, tables.md, results.json, charts) and by path (frames, maps)
        String[][] runs = {{"atomic", null}, {"atomic", "old content\n"}, {"output", "old content\n"},
            {"output-file", null}};
        for (String[] run : runs) {
            String writer = run[0];
            String before = run[1];
            if (before != null) {
                Files.writeString(target, before);
            }
            Path java = Path.of(System.getProperty("java.home"), "bin", "java");
            Process p = new ProcessBuilder(java.toString(), "-cp", System.getProperty("java.class.path"),
                    KilledWriteMain.class.getName(), target.toString(), writer).redirectErrorStream(true).start();
            try (BufferedReader in = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
                assertEquals("writing", in.readLine(), writer);
                p.destroyForcibly(); // SIGKILL in the middle of the write
                assertTrue(p.waitFor(30, TimeUnit.SECONDS));
            }
            if (before == null) {
                assertFalse(Files.exists(target), writer + ": no file under the final name");
            } else {
                assertEquals(before, Files.readString(target), writer + ": the old file is whole");
            }
            List<Path> temporaries = temporaries();
            assertEquals(1, temporaries.size(), writer + ": the killed write's temporary file: " + temporaries);
            // the next write succeeds and removes what the killed one left
            if (writer.equals("atomic")) {
                AtomicFiles.write(target, "write", o -> o.write("new\n".getBytes(StandardCharsets.UTF_8)));
            } else {
                new OutputFiles().write(target, o -> o.write("new\n".getBytes(StandardCharsets.UTF_8)));
            }
            assertEquals("new\n", Files.readString(target));
            assertEquals(List.of(), temporaries(), writer);
            Files.delete(target);
        }
    }

    private List<Path> temporaries() throws Exception {
        try (Stream<Path> s = Files.list(dir)) {
            return s.filter(f -> f.getFileName().toString().startsWith(".dump.csv.")).toList();
        }
    }

    @Test
    void checkRefusesWithALocationWhatSimulateWouldRefuse() throws Exception {
        Path bare = dir.resolve("bare.xml");
        Files.writeString(bare, "<scene version=\"1\">\n  <terrain sizeX=\"10\" sizeZ=\"10\"/>\n</scene>\n");
        String[][] commands = {{"check", bare.toString()}, {"simulate", bare.toString()},
            {"render", bare.toString(), "--frames", "1", "--out", dir.resolve("frames").toString()}};
        for (String[] args : commands) {
            String command = args[0];
            CliTest.Result r = CliTest.run(args);
            assertEquals(2, r.code(), command + ": " + r.out() + r.err());
            assertTrue(r.err().contains(bare + ":1:1: <scene> has no <species>"), command + ": " + r.err());
            assertFalse(r.err().contains("\tat "), r.err());
        }
        Path fifo = dir.resolve("pipe.xml");
        assertEquals(0, new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor());
        CliTest.Result[] pipe = new CliTest.Result[1];
        Thread t = new Thread(() -> pipe[0] = CliTest.run("check", fifo.toString()));
        t.setDaemon(true);
        t.start();
        t.join(20_000);
        assertFalse(t.isAlive(), "check on a pipe blocked");
        assertEquals(2, pipe[0].code());
        assertTrue(pipe[0].err().contains(fifo + ": is not a regular file but a named pipe (FIFO)"), pipe[0].err());
        // an image outside the scene's folder: refused with a location, accepted with the flag
        Path folder = dir.resolve("scene");
        Files.createDirectories(folder);
        javax.imageio.ImageIO.write(new java.awt.image.BufferedImage(16, 16, java.awt.image.BufferedImage.TYPE_BYTE_GRAY),
                "png", dir.resolve("outside.png").toFile());
        Path scene = folder.resolve("s.xml");
        Files.writeString(scene, Files.readString(Path.of("scenes/c1.xml")).replace("<terrain ",
                "<terrain heightmap=\"../outside.png\" "));
        CliTest.Result refused = CliTest.run("check", scene.toString());
        assertEquals(2, refused.code(), refused.out());
        assertTrue(refused.err().matches("(?s).*" + java.util.regex.Pattern.quote(scene.toString())
                + ":\\d+:\\d+: attribute 'heightmap' of <terrain>: image '../outside.png' resolves to .*outside the "
                + "scene's folder.*--allow-outside-images.*"), refused.err());
        CliTest.Result allowed = CliTest.run("check", "--allow-outside-images", scene.toString());
        assertEquals(0, allowed.code(), allowed.err());
        CliTest.Result ran = CliTest.run("simulate", "--allow-outside-images", scene.toString(), "--steps", "2");
        assertEquals(0, ran.code(), ran.err());
    }

    @Test
    void checkAndSimulateAgreeOnTheFuzzCorpusAndItsMutants() throws Exception {
        List<Path> inputs = new ArrayList<>();
        try (Stream<Path> s = Files.list(CORPUS)) {
            s.filter(p -> p.toString().endsWith(".xml")).sorted().forEach(inputs::add);
        }
        assertTrue(inputs.size() >= 40, "corpus: " + inputs.size());
        // mutants of the corpus's meadow and of the small shipped scenes, aimed at what only a build used to find
        Random rnd = new Random(29);
        List<String> small = new ArrayList<>();
        for (Path p : new Path[] {CORPUS.resolve("meadow.xml"), Path.of("scenes/c1.xml"), Path.of("scenes/c2.xml"),
            Path.of("scenes/c3.xml"), Path.of("scenes/rose.xml")}) {
            small.add(Files.readString(p, StandardCharsets.ISO_8859_1));
        }
        for (int i = 0; i < 40; i++) {
            String m = mutate(small.get(i % small.size()), rnd);
            Path p = dir.resolve("mutant-" + i + ".xml");
            Files.writeString(p, m, StandardCharsets.ISO_8859_1);
            inputs.add(p);
        }
        int agreedValid = 0;
        int agreedRefused = 0;
        for (Path p : inputs) {
            CliTest.Result check = CliTest.run("check", p.toString());
            CliTest.Result sim = CliTest.run("simulate", p.toString(), "--steps", "2", "--threads", "2");
            assertEquals(check.code() == 0 ? 0 : 2, sim.code(), p + ": check " + check.code() + " " + check.err()
                    + "\nsimulate " + sim.code() + " " + sim.err());
            if (check.code() == 0) {
                agreedValid++;
            } else {
                assertEquals(2, check.code(), p + ": " + check.err());
                String first = check.err().lines().findFirst().orElse("");
                assertTrue(first.startsWith(p.toString() + ":"), "located: " + first);
                assertTrue(sim.err().contains(first), p + ": simulate says what check says: " + first + " / " + sim.err());
                agreedRefused++;
            }
        }
        assertTrue(agreedValid >= 5 && agreedRefused >= 40, "valid " + agreedValid + ", refused " + agreedRefused);
    }

    /** One of: every species removed, a line deleted, a number made extreme. */
    private static String mutate(String xml, Random rnd) {
        switch (rnd.nextInt(3)) {
            case 0 -> {
                return xml.replaceAll("(?s)<species.*?</species>", "");
            }
            case 1 -> {
                List<String> lines = new ArrayList<>(List.of(xml.split("\n", -1)));
                lines.remove(rnd.nextInt(lines.size()));
                return String.join("\n", lines);
            }
            default -> {
                String[] extremes = {"0", "1e9", "-1", "NaN", "1e-9", "100000"};
                java.util.regex.Matcher m = java.util.regex.Pattern.compile("=\"(-?[0-9.]+)\"").matcher(xml);
                List<int[]> spans = new ArrayList<>();
                while (m.find()) {
                    spans.add(new int[] {m.start(1), m.end(1)});
                }
                if (spans.isEmpty()) {
                    return xml;
                }
                int[] s = spans.get(rnd.nextInt(spans.size()));
                return xml.substring(0, s[0]) + extremes[rnd.nextInt(extremes.length)] + xml.substring(s[1]);
            }
        }
    }
}
