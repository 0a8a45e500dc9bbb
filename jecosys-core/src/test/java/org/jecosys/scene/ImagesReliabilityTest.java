package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import org.jecosys.math.Progress;
import org.jecosys.sim.Simulation;
import org.jecosys.terrain.ImageSource;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Reliability, faults 4 to 7 of the third pass: an image is read once and the bytes checked are the
 * bytes decoded (a swap after load cannot reach the build, and the API that reads the folder again
 * refuses an image too large for the heap instead of running out of memory); image paths stay inside
 * the scene's folder tree unless the caller allows more; a scene without species and a scene path
 * that is not a regular file are refused at load, with a location.
 */
@Tag("reliability")
class ImagesReliabilityTest {
    @TempDir
    Path dir;

    private static final String GRASS = "  <species id=\"grass\">\n    <lod/>\n"
            + "    <component id=\"leaf\" type=\"leaf\" count=\"3\" segments=\"3\" length=\"0.3\" baseWidth=\"0.005\"\n"
            + "        mass=\"0.0004\" stiffness=\"0.2\" dragArea=\"0.002\" lodSegments=\"3\"/>\n  </species>\n"
            + "  <distribution species=\"grass\" count=\"20\" footprint=\"0.5\"/>\n";

    /** A scene in {@code folder} whose heightmap is {@code heightmap}, the attribute on line 3. */
    private static Path scene(Path folder, String heightmap) throws Exception {
        Files.createDirectories(folder);
        Path file = folder.resolve("scene.xml");
        Files.writeString(file, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<scene version=\"1\">\n"
                + "  <terrain sizeX=\"10\" sizeZ=\"10\" resolution=\"17\" heightScale=\"2\" heightmap=\"" + heightmap
                + "\"/>\n" + GRASS + "</scene>\n", StandardCharsets.UTF_8);
        return file;
    }

    @Test
    void imagePathsOutsideTheScenesFolderAreRefusedWithALocationUnlessAllowed() throws Exception {
        Path outside = dir.resolve("outside");
        Files.createDirectories(outside);
        Files.write(outside.resolve("hm.png"), Pngs.grey(16, 16, 200));
        Path folder = dir.resolve("scenes");
        Files.createDirectories(folder.resolve("real"));
        Files.write(folder.resolve("real/in.png"), Pngs.grey(16, 16, 100));
        Files.createSymbolicLink(folder.resolve("link-out.png"), outside.resolve("hm.png"));
        Files.createSymbolicLink(folder.resolve("passwd.png"), Path.of("/etc/passwd"));
        Files.createSymbolicLink(folder.resolve("dir-out"), outside);
        Files.createSymbolicLink(folder.resolve("link-in.png"), folder.resolve("real/in.png"));
        String[][] refused = {
            {"../outside/hm.png", "outside the scene's folder"},
            {outside.resolve("hm.png").toString(), "absolute path"},
            {"link-out.png", "outside the scene's folder"},
            {"passwd.png", "outside the scene's folder"},
            {"dir-out/hm.png", "outside the scene's folder"},
            {"real/../../outside/hm.png", "outside the scene's folder"},
        };
        for (String[] r : refused) {
            Path file = scene(folder, r[0]);
            SceneLoadException e = assertThrows(SceneLoadException.class, () -> SceneFiles.read(file), r[0]);
            SceneProblem p = e.problems().get(0);
            assertEquals(3, p.line(), r[0] + ": " + p);
            assertTrue(p.column() > 1, r[0] + ": " + p);
            assertTrue(p.message().contains("heightmap") && p.message().contains(r[1])
                    && p.message().contains("--allow-outside-images"), r[0] + ": " + p);
            if (!r[0].equals("passwd.png")) {
                // allowed by the caller: the outside file is really used (level 200 of 255, 2 m relief)
                Scene s = SceneFiles.read(file, ImageSource.anywhere(folder));
                try (Simulation sim = Scenes.simulation(s, 1, Progress.NONE)) {
                    assertEquals(2 * 200 / 255.0, sim.world().terrain().heightfield().height(0, 0), 1e-3, r[0]);
                }
            }
        }
        for (String inside : new String[] {"real/in.png", "link-in.png", "./real/../real/in.png"}) {
            Scene s = SceneFiles.read(scene(folder, inside));
            try (Simulation sim = Scenes.simulation(s, 1, Progress.NONE)) {
                assertEquals(2 * 100 / 255.0, sim.world().terrain().heightfield().height(0, 0), 1e-3, inside);
            }
        }
    }

    @Test
    void theBuildDecodesTheBytesThatWereCheckedNotAFileSwappedLater() throws Exception {
        Path file = scene(dir, "hm.png");
        Files.write(dir.resolve("hm.png"), Pngs.grey(64, 64, 100));
        Scene scene = SceneFiles.read(file);
        Files.write(dir.resolve("hm.png"), Pngs.grey(64, 64, 250)); // swapped after the check
        try (Simulation sim = Scenes.simulation(scene, 1, Progress.NONE)) {
            assertEquals(2 * 100 / 255.0, sim.world().terrain().heightfield().height(1, 1), 1e-3);
        }
        // and from a stream with the game's own resolver, the same
        byte[] xml = Files.readAllBytes(file);
        Scene streamed = SceneFiles.read(new ByteArrayInputStream(xml), "assets/scene.xml",
                ImageSource.of(Map.of("hm.png", Pngs.grey(8, 8, 50))));
        try (Simulation sim = Scenes.simulation(streamed, 1, Progress.NONE)) {
            assertEquals(2 * 50 / 255.0, sim.world().terrain().heightfield().height(1, 1), 1e-3);
        }
        SceneLoadException missing = assertThrows(SceneLoadException.class, () -> SceneFiles.read(
                new ByteArrayInputStream(xml), "assets/scene.xml", ImageSource.NONE));
        assertTrue(missing.problems().get(0).toString().startsWith("assets/scene.xml:3:"), missing.getMessage());
    }

    @Test
    void anImageSwappedForTheLargestOneNeverEndsInOutOfMemoryAt512MegabytesOfHeap() throws Exception {
        Path file = scene(dir, "hm.png");
        Files.write(dir.resolve("hm.png"), Pngs.grey(64, 64, 100));
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Process p = new ProcessBuilder(java.toString(), "-Xmx512m", "-cp", System.getProperty("java.class.path"),
                SwappedImageMain.class.getName(), file.toString()).redirectErrorStream(true).start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the child JVM finished");
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, p.exitValue(), out);
        assertTrue(out.contains("checked bytes: built, height 0.78431"), out);
        assertTrue(out.contains("folder again: refused: image 'hm.png' is 8192 x 8192 pixels: decoding it needs about"),
                out);
    }

    @Test
    void aSceneWithNoSpeciesIsRefusedAtLoadWithItsLocation() throws Exception {
        Path file = dir.resolve("bare.xml");
        Files.writeString(file, "<?xml version=\"1.0\"?>\n<scene version=\"1\">\n  <terrain sizeX=\"10\" sizeZ=\"10\"/>\n"
                + "</scene>\n");
        SceneLoadException e = assertThrows(SceneLoadException.class, () -> SceneFiles.read(file));
        SceneProblem p = e.problems().get(0);
        assertEquals(2, p.line(), p.toString());
        assertTrue(p.message().contains("no <species>"), p.toString());
    }

    @Test
    void aScenePathThatIsAPipeIsRefusedWithoutOpeningIt() throws Exception {
        Path fifo = dir.resolve("pipe.xml");
        Process mk = new ProcessBuilder("mkfifo", fifo.toString()).start();
        assertEquals(0, mk.waitFor());
        AtomicReference<Throwable> outcome = new AtomicReference<>();
        Thread t = new Thread(() -> {
            try {
                SceneFiles.read(fifo);
            } catch (Throwable e) {
                outcome.set(e);
            }
        });
        t.setDaemon(true);
        t.start();
        t.join(10_000);
        assertFalse(t.isAlive(), "reading a FIFO blocked");
        assertTrue(outcome.get() instanceof SceneLoadException, String.valueOf(outcome.get()));
        assertTrue(outcome.get().getMessage().contains("not a regular file"), outcome.get().getMessage());
        // and an image that is a pipe, likewise
        Process mk2 = new ProcessBuilder("mkfifo", dir.resolve("hm.png").toString()).start();
        assertEquals(0, mk2.waitFor());
        Path file = scene(dir, "hm.png");
        SceneLoadException e = assertThrows(SceneLoadException.class, () -> SceneFiles.read(file));
        assertTrue(e.getMessage().contains("not a regular file"), e.getMessage());
    }
}
