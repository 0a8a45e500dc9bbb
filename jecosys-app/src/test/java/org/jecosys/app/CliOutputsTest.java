package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.stream.Stream;
import org.jecosys.scene.OutputFiles;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Reliability, fourth pass (issue 36, faults 2, 3, 6 and 7): every file the command line and the bench
 * write ({@code --gif}, the frames in {@code --out}, {@code --dump}, {@code --json}, the bench's
 * {@code tables.md}, {@code results.json} and charts) pointed at the scene itself, a pipe, a symbolic
 * link, a device and a file in a read-only folder is refused with exit 2 before any work, naming the
 * flag and the path, and the target is left as it was (type and bytes; a link's file too). Two outputs
 * of one run are never the same file, no output is an image the scene reads, and folders are made only
 * once the scene was accepted. The runs are in-process, on a copy of {@code scenes/c1.xml}, 16x16
 * pixels and one frame or step, so each refusal costs milliseconds. Tests run as root here: a
 * read-only folder is one without its owner's write bit, which the writer honours for root too.
 */
@Tag("reliability")
class CliOutputsTest {
    /** What a target is pointed at. */
    private enum Hostile { SCENE, FIFO, LINK, DEVICE, READ_ONLY }

    @TempDir
    Path dir;
    private Path scene;
    private final List<Path> readOnly = new ArrayList<>();

    @BeforeEach
    void copyTheScene() throws IOException {
        scene = dir.resolve("s.xml");
        Files.copy(Path.of("scenes/c1.xml"), scene);
    }

    @AfterEach
    void makeReadOnlyFoldersWritableAgain() throws IOException {
        for (Path p : readOnly) {
            Files.setPosixFilePermissions(p, PosixFilePermissions.fromString("rwxr-xr-x"));
        }
    }

    @Test
    void gifDumpAndJsonNeverReplaceTheSceneAPipeALinkADeviceOrAFileInAReadOnlyFolder() throws Exception {
        for (Hostile h : Hostile.values()) {
            for (String flag : new String[] {"--gif", "--dump", "--json"}) {
                List<Path> targets = h == Hostile.DEVICE ? List.of(Path.of("/dev/full"), Path.of("/dev/null"))
                        : List.of(named(h, flag.substring(2)));
                for (Path target : targets) {
                    String[] args = flag.equals("--gif")
                            ? new String[] {"render", scene.toString(), "--frames", "1", "--size", "16x16", "--out",
                                dir.resolve("frames").toString(), "--gif", target.toString()}
                            : new String[] {"simulate", scene.toString(), "--steps", "1", flag, target.toString()};
                    refusedBeforeWork(h + " " + flag, target, flag + " " + target + ": ", args);
                    assertFalse(Files.exists(dir.resolve("frames")), "no folder made for a refused run");
                }
            }
        }
    }

    @Test
    void framesInOutNeverReplaceTheSceneAPipeALinkADeviceOrAFileInAReadOnlyFolder() throws Exception {
        for (Hostile h : Hostile.values()) {
            Path out = dir.resolve("out-" + h);
            Path frame = inFolder(h, out, "frame-00001.png");
            if (frame == null) {
                continue; // no device node can be made here: --out /dev/null below is the device case
            }
            String sceneArg = h == Hostile.SCENE ? frame.toString() : scene.toString();
            refusedBeforeWork("frames " + h, frame, "--out " + out + ": " + (h == Hostile.READ_ONLY ? "is read-only"
                    : frame + " "),
                    "render", sceneArg, "--frames", "1", "--size", "16x16", "--out", out.toString());
        }
        // every frame the run will write is checked, not only the first; and --out itself at each target
        Path out = dir.resolve("second");
        Path second = inFolder(Hostile.FIFO, out, "frame-00002.png");
        refusedBeforeWork("second frame", second, "--out " + out + ": " + second + " is a pipe (FIFO)",
                "render", scene.toString(), "--frames", "2", "--size", "16x16", "--out", out.toString());
        for (Path folder : new Path[] {scene, named(Hostile.FIFO, "out"), Path.of("/dev/null")}) {
            refusedBeforeWork("--out " + folder, folder, "--out " + folder + ": is ",
                    "render", scene.toString(), "--frames", "1", "--size", "16x16", "--out", folder.toString());
        }
    }

    @Test
    void theBenchsReportsNeverReplaceASceneAPipeALinkADeviceOrAFileInAReadOnlyFolder() throws Exception {
        for (Hostile h : Hostile.values()) {
            // the scene case: tables.md a hard link of a scene file the bench reads (same file system as scenes/)
            Path out = h == Hostile.SCENE ? Path.of("target/cli-outputs-test/bench-scene") : dir.resolve("bench-" + h);
            String name = h == Hostile.FIFO ? "results.json" : "tables.md";
            Path report = inFolder(h, out, name);
            if (report == null) {
                continue; // no device node can be made here: --out /dev/null below is the device case
            }
            try {
                refusedBeforeWork("bench " + h, report, "--out " + out + ": " + (h == Hostile.READ_ONLY ? "is read-only"
                        : report + " "),
                        "bench", "--quick", "--only", "Tables 1-4", "--out", out.toString());
            } finally {
                if (h == Hostile.SCENE) {
                    Files.delete(report);
                }
            }
        }
        // a chart named like a link, the charts folder a link, and --out itself a file or a device
        Path out = dir.resolve("bench-charts");
        Path chart = inFolder(Hostile.LINK, out.resolve("charts"), "table1.png");
        refusedBeforeWork("bench chart", chart, "--out " + out + ": " + chart + " is a symbolic link",
                "bench", "--quick", "--only", "Tables 1-4", "--out", out.toString());
        Path linked = dir.resolve("bench-linked");
        Files.createDirectories(linked);
        Files.createSymbolicLink(linked.resolve("charts"), Files.createDirectories(dir.resolve("elsewhere")));
        refusedBeforeWork("bench charts folder", linked.resolve("charts"), "--out " + linked + ": "
                + linked.resolve("charts") + " is a symbolic link", "bench", "--quick", "--only", "Tables 1-4",
                "--out", linked.toString());
        for (Path folder : new Path[] {scene, Path.of("/dev/null")}) {
            refusedBeforeWork("bench --out " + folder, folder, "--out " + folder + ": is ",
                    "bench", "--quick", "--only", "Tables 1-4", "--out", folder.toString());
        }
    }

    @Test
    void twoOutputsOfOneRunAreNeverTheSameFile() throws Exception {
        Path x = dir.resolve("x.out");
        Files.writeString(x, "old");
        refusedBeforeWork("--dump X --json X", x, "--dump " + x + ": is the same file as --json " + x,
                "simulate", scene.toString(), "--steps", "1", "--json", x.toString(), "--dump", x.toString());
        Path out = dir.resolve("frames");
        Path frame = out.resolve("frame-00001.png");
        CliTest.Result r = CliTest.run("render", scene.toString(), "--frames", "1", "--size", "16x16", "--out",
                out.toString(), "--gif", frame.toString());
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("--gif " + frame + ": is the same file as " + frame + ", which --out writes"), r.err());
        // the same file under another spelling: through a link to the folder, and a map with --maps
        Files.createDirectories(dir.resolve("real"));
        Path alias = Files.createSymbolicLink(dir.resolve("alias"), dir.resolve("real"));
        CliTest.Result linked = CliTest.run("render", scene.toString(), "--frames", "1", "--size", "16x16", "--maps",
                "--out", dir.resolve("real").toString(), "--gif", alias.resolve("./water.png").toString());
        assertEquals(2, linked.code(), linked.err());
        assertTrue(linked.err().contains("is the same file as " + dir.resolve("real/water.png")), linked.err());
        assertEquals(List.of(), list(dir.resolve("real")), "nothing written");
        assertFalse(Files.exists(out), "no folder made");
    }

    @Test
    void noOutputIsAnImageTheSceneReads() throws Exception {
        Path folder = Files.createDirectories(dir.resolve("with-image"));
        // a heightmap named like the water map that --maps writes
        Path image = folder.resolve("water.png");
        javax.imageio.ImageIO.write(new java.awt.image.BufferedImage(16, 16, java.awt.image.BufferedImage.TYPE_BYTE_GRAY),
                "png", image.toFile());
        Path s = folder.resolve("s.xml");
        Files.writeString(s, Files.readString(scene).replace("<terrain ", "<terrain heightmap=\"water.png\" "));
        refusedBeforeWork("image", image, "--dump " + image + ": is an image the scene reads",
                "simulate", s.toString(), "--steps", "1", "--dump", image.toString());
        refusedBeforeWork("image as a map", image, "--out " + folder + ": " + image + " is an image the scene reads",
                "render", s.toString(), "--frames", "1", "--size", "16x16", "--maps", "--out", folder.toString());
    }

    @Test
    void foldersAreMadeOnlyOnceTheSceneWasAccepted() throws Exception {
        Path bare = dir.resolve("bare.xml");
        Files.writeString(bare, "<scene version=\"1\">\n  <terrain sizeX=\"10\" sizeZ=\"10\"/>\n</scene>\n");
        Path fresh = dir.resolve("fresh");
        CliTest.Result sim = CliTest.run("simulate", bare.toString(), "--steps", "1",
                "--dump", fresh.resolve("a/x.csv").toString(), "--json", fresh.resolve("b/x.json").toString());
        assertEquals(2, sim.code(), sim.err());
        assertTrue(sim.err().contains("<scene> has no <species>"), sim.err());
        CliTest.Result render = CliTest.run("render", bare.toString(), "--frames", "1", "--size", "16x16",
                "--out", fresh.resolve("c").toString(), "--gif", fresh.resolve("d/x.gif").toString());
        assertEquals(2, render.code(), render.err());
        assertFalse(Files.exists(fresh), "no folder made for a refused scene");
        // an accepted scene: the folders are made, the files written
        CliTest.Result ok = CliTest.run("simulate", scene.toString(), "--steps", "1",
                "--dump", fresh.resolve("a/x.csv").toString(), "--json", fresh.resolve("b/x.json").toString());
        assertEquals(0, ok.code(), ok.err());
        assertTrue(Files.size(fresh.resolve("a/x.csv")) > 0 && Files.size(fresh.resolve("b/x.json")) > 0);
        assertEquals(List.of(), temporaries(fresh.resolve("a")));
    }

    @Test
    void theWriterRefusesAtWriteTimeWhatAppearedAfterTheChecks() throws Exception {
        OutputFiles files = new OutputFiles();
        for (Hostile h : new Hostile[] {Hostile.FIFO, Hostile.LINK, Hostile.READ_ONLY}) {
            Path target = named(h, "late");
            String before = snapshot(target);
            IOException e = assertThrows(IOException.class, () -> files.write(target, o -> o.write(1)), h.name());
            assertTrue(e.getMessage().startsWith("cannot write " + target + ": "), e.getMessage());
            IOException f = assertThrows(IOException.class,
                    () -> files.writeFile(target, t -> Files.writeString(t, "new")), h.name());
            assertTrue(f.getMessage().startsWith("cannot write " + target + ": "), f.getMessage());
            assertEquals(before, snapshot(target), h + ": untouched");
            assertEquals(List.of(), temporaries(target.getParent()), h.name());
        }
        for (String device : new String[] {"/dev/full", "/dev/null"}) {
            IOException e = assertThrows(IOException.class, () -> files.write(Path.of(device), o -> o.write(1)));
            assertTrue(e.getMessage().contains("is a character device, not a regular file"), e.getMessage());
        }
    }

    @Test
    void everyFileTheAppAndTheBenchWriteGoesThroughTheOutputWriter() throws Exception {
        // a raw write anywhere in jecosys-app's code would bypass the checks: each one found must be an
        // encoder writing OutputFiles' temporary file, a chart drawn into a stream, or the viewer's scene save
        java.util.regex.Pattern write = java.util.regex.Pattern.compile("Files\\.(write|writeString|newOutputStream|"
                + "newBufferedWriter|copy|move|createFile|createTempFile)\\(|new (FileOutputStream|FileWriter|"
                + "RandomAccessFile)|ImageIO\\.(write|createImageOutputStream)\\(|stbi_write_|AtomicFiles\\.write\\(|"
                + "Pixels\\.writePng\\(|TerrainMaps\\.write|saveBitmap\\(|SceneFiles\\.save");
        List<String> found = new ArrayList<>();
        List<Path> sources;
        try (Stream<Path> s = Files.walk(Path.of("jecosys-app/src/main/java"))) {
            sources = s.filter(p -> p.toString().endsWith(".java")).toList();
        }
        assertTrue(sources.size() > 40, "sources: " + sources.size());
        for (Path source : sources) {
            List<String> lines = Files.readAllLines(source);
            for (int i = 0; i < lines.size(); i++) {
                String line = lines.get(i);
                if (!write.matcher(line).find()) {
                    continue;
                }
                found.add(source.getFileName() + ":" + (i + 1));
                boolean allowed = line.contains("temporary") || line.contains("saveBitmap(chart, png, ")
                        || line.contains("SceneFiles.save(");
                assertTrue(allowed, source + ":" + (i + 1) + " writes a file without OutputFiles: " + line.trim());
            }
        }
        assertTrue(found.size() >= 8, "the writes the scan should see: " + found);
    }

    /**
     * Runs {@code args}; exit 2 with {@code message} on stderr (the flag and the path), no stack trace,
     * nothing built or written, and {@code target} exactly as it was.
     */
    private void refusedBeforeWork(String what, Path target, String message, String... args) throws IOException {
        String before = snapshot(target);
        List<Path> folder = list(target.getParent());
        long t0 = System.nanoTime();
        CliTest.Result r = CliTest.run(args);
        double ms = (System.nanoTime() - t0) / 1e6;
        assertEquals(2, r.code(), what + ": " + r.out() + r.err());
        assertTrue(r.err().contains(message), what + ": expected '" + message + "' in: " + r.err());
        assertFalse(r.err().contains("\tat "), what + ": " + r.err());
        assertFalse(r.out().contains("Building") || r.out().contains("state hash") || r.out().contains("wrote"),
                what + ": nothing ran: " + r.out());
        assertEquals(before, snapshot(target), what + ": the target is untouched");
        assertEquals(folder, list(target.getParent()), what + ": nothing written beside it");
        System.out.printf("[outputs] %s refused in %.0f ms: %s%n", what, ms, r.err().lines().findFirst().orElse(""));
    }

    /** A target named {@code name} of the hostile kind, in a folder of its own (DEVICE: made by mknod). */
    private Path named(Hostile h, String name) throws IOException {
        if (h == Hostile.SCENE) {
            return scene;
        }
        return inFolder(h, dir.resolve(h.name().toLowerCase(java.util.Locale.ROOT) + "-" + name), name);
    }

    /**
     * {@code folder/name} made into the hostile kind (SCENE: a copy of the scene, or for the bench a hard
     * link of {@code scenes/c1.xml}, which it reads); null for DEVICE where this process may not make one.
     */
    private Path inFolder(Hostile h, Path folder, String name) throws IOException {
        Files.createDirectories(folder);
        Path p = folder.resolve(name);
        switch (h) {
            case SCENE -> {
                if (name.equals("tables.md")) {
                    Files.deleteIfExists(p); // left by an interrupted run
                    Files.createLink(p, Path.of("scenes/c1.xml"));
                } else {
                    Files.copy(scene, p);
                }
            }
            case FIFO -> assertEquals(0, exec("mkfifo", p.toString()), "mkfifo " + p);
            case LINK -> {
                Path victim = Files.writeString(dir.resolve("victim-" + folder.getFileName() + "-" + name), "victim");
                Files.createSymbolicLink(p, victim);
            }
            case DEVICE -> {
                if (exec("mknod", p.toString(), "c", "1", "3") != 0) {
                    return null;
                }
            }
            case READ_ONLY -> {
                Files.writeString(p, "old output");
                Files.setPosixFilePermissions(folder, PosixFilePermissions.fromString("r-xr-xr-x"));
                readOnly.add(folder);
            }
            default -> throw new IllegalArgumentException(h.name());
        }
        return p;
    }

    private static int exec(String... command) throws IOException {
        try {
            return new ProcessBuilder(command).redirectErrorStream(true).start().waitFor();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
    }

    /** A target's type (and link target), and its bytes when it is a regular file (a link's file's too). */
    private static String snapshot(Path p) throws IOException {
        int type = (Integer) Files.getAttribute(p, "unix:mode", LinkOption.NOFOLLOW_LINKS) & 0170000;
        StringBuilder s = new StringBuilder(Integer.toOctalString(type));
        if (Files.isSymbolicLink(p)) {
            Path to = Files.readSymbolicLink(p);
            s.append(" -> ").append(to).append(": ").append(snapshot(p.resolveSibling(to)));
        } else if (Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
            s.append(' ').append(Base64.getEncoder().encodeToString(Files.readAllBytes(p)));
        }
        return s.toString();
    }

    private static List<Path> list(Path folder) throws IOException {
        if (!Files.isDirectory(folder) || folder.startsWith("/dev")) {
            return List.of();
        }
        try (Stream<Path> s = Files.list(folder)) {
            return s.sorted().toList();
        }
    }

    private static List<Path> temporaries(Path folder) throws IOException {
        return list(folder).stream().filter(p -> p.getFileName().toString().endsWith(".tmp")).toList();
    }

}
