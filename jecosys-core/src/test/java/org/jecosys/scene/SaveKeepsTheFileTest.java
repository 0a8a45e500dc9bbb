package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Saving replaces the content, not the file: the mode is kept, a symbolic link keeps pointing at its
 * file (which gets the content), a target that is not a regular file is refused untouched, and
 * temporary files that killed saves left behind are removed.
 */
class SaveKeepsTheFileTest {
    private static SceneDef scene;

    @TempDir
    Path dir;

    @BeforeAll
    static void load() throws Exception {
        scene = SceneFiles.parse(Path.of("scenes/c1.xml"));
    }

    private static boolean posix() {
        return FileSystems.getDefault().supportedFileAttributeViews().contains("posix");
    }

    @Test
    void theModeOfTheFileIsKept() throws Exception {
        assumeTrue(posix(), "POSIX permissions");
        Path target = dir.resolve("c1.xml");
        Files.writeString(target, "old");
        Files.setPosixFilePermissions(target, PosixFilePermissions.fromString("rw-r-----"));
        SceneFiles.save(target, scene);
        assertEquals("rw-r-----", PosixFilePermissions.toString(Files.getPosixFilePermissions(target)));
        assertEquals(scene, SceneFiles.parse(target));
        Files.setPosixFilePermissions(target, PosixFilePermissions.fromString("rw-rw-r--"));
        SceneFiles.save(target, scene);
        assertEquals("rw-rw-r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(target)));
    }

    @Test
    void aSymbolicLinkIsFollowedAndStaysALink() throws Exception {
        Path real = Files.createDirectories(dir.resolve("real")).resolve("scene.xml");
        Files.writeString(real, "old");
        Path link = dir.resolve("link.xml");
        try {
            Files.createSymbolicLink(link, Path.of("real/scene.xml"));
        } catch (UnsupportedOperationException | IOException e) {
            assumeTrue(false, "symbolic links: " + e);
        }
        SceneFiles.save(link, scene);
        assertTrue(Files.isSymbolicLink(link), "the link is still a link");
        assertEquals(Path.of("real/scene.xml"), Files.readSymbolicLink(link));
        assertEquals(scene, SceneFiles.parse(real));
        assertEquals(List.of("link.xml", "real"), names(dir));
        assertEquals(List.of("scene.xml"), names(real.getParent()));
    }

    @Test
    void aTargetThatIsNotARegularFileIsRefusedUntouched() throws Exception {
        Path folder = Files.createDirectories(dir.resolve("folder.xml"));
        IOException ex = assertThrows(IOException.class, () -> SceneFiles.save(folder, scene));
        assertTrue(ex.getMessage().contains("not a regular file"), ex.getMessage());
        assertTrue(Files.isDirectory(folder));
        Path devNull = Path.of("/dev/null");
        if (Files.exists(devNull)) {
            Path link = dir.resolve("null.xml");
            Files.createSymbolicLink(link, devNull);
            IOException dev = assertThrows(IOException.class, () -> SceneFiles.save(link, scene));
            assertTrue(dev.getMessage().contains("/dev/null is not a regular file"), dev.getMessage());
            assertTrue(Files.isSymbolicLink(link), "the link to the device is untouched");
        }
        Path fifo = dir.resolve("pipe.xml");
        boolean made;
        try {
            made = new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor() == 0;
        } catch (IOException e) {
            made = false;
        }
        if (made) {
            IOException pipe = assertThrows(IOException.class, () -> SceneFiles.save(fifo, scene));
            assertTrue(pipe.getMessage().contains("not a regular file"), pipe.getMessage());
            assertFalse(Files.isRegularFile(fifo), "the pipe is still a pipe");
        }
        try (Stream<Path> s = Files.list(dir)) {
            assertTrue(s.noneMatch(p -> p.getFileName().toString().endsWith(".tmp")), "no temporary file left");
        }
    }

    @Test
    void temporaryFilesOfKilledSavesAreRemoved() throws Exception {
        Path target = dir.resolve("c1.xml");
        Files.writeString(target, "old");
        Process p = new ProcessBuilder("java", "-version").redirectErrorStream(true).start();
        p.getInputStream().readAllBytes();
        p.waitFor();
        long gone = p.pid(); // a process that has ended, as one killed during a save
        Path stale = dir.resolve(".c1.xml." + gone + ".k3x9.tmp");
        Path legacy = dir.resolve(".c1.xml.8072346021457398162.tmp"); // the random names of earlier versions
        Path live = dir.resolve(".c1.xml." + ProcessHandle.current().pid() + ".q1.tmp"); // a save running now
        Path other = dir.resolve(".other.xml." + gone + ".k3x9.tmp"); // another file's
        for (Path t : new Path[] {stale, legacy, live, other}) {
            Files.writeString(t, "partial", StandardCharsets.UTF_8);
        }
        SceneFiles.save(target, scene);
        assertFalse(Files.exists(stale));
        assertFalse(Files.exists(legacy));
        assertTrue(Files.exists(live), "a save of a live process is left alone");
        assertTrue(Files.exists(other), "only this target's temporary files are touched");
        assertEquals(scene, SceneFiles.parse(target));
    }

    private static List<String> names(Path d) throws IOException {
        try (Stream<Path> s = Files.list(d)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }
}
