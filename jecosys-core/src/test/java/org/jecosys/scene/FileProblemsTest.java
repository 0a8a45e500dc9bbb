package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.terrain.ImageSource;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Reliability, fourth pass, fault 9: a problem about the scene file itself (a named pipe, a folder,
 * a file over the size limit, a missing file) has no place inside the file, so it is located by its
 * path only, {@code PATH: message}, never at a made-up {@code 0:0}; problems inside the file keep
 * {@code PATH:LINE:COL}.
 */
@Tag("reliability")
class FileProblemsTest {
    @TempDir
    Path dir;

    /** The one problem of a refused load, checked to be located by its path only. */
    private static SceneProblem byPathOnly(Path file, SceneLoadException e) {
        assertEquals(1, e.problems().size(), e.getMessage());
        SceneProblem p = e.problems().get(0);
        assertEquals(0, p.line(), p.toString());
        assertEquals(file + ": " + p.message(), p.toString());
        assertEquals(p.toString(), e.getMessage());
        assertFalse(e.getMessage().contains(":0:0"), e.getMessage());
        return p;
    }

    @Test
    void aNamedPipeIsRefusedByItsPathAndSaysWhatItIs() throws Exception {
        Path fifo = dir.resolve("pipe.xml");
        assertEquals(0, new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor());
        SceneLoadException e = assertThrows(SceneLoadException.class, () -> SceneFiles.read(fifo));
        assertEquals("is not a regular file but a named pipe (FIFO); scene files are regular files",
                byPathOnly(fifo, e).message());
    }

    @Test
    void aFolderAMissingFileAndAFileOverTheLimitAreRefusedByTheirPaths() throws Exception {
        Path folder = Files.createDirectory(dir.resolve("folder.xml"));
        assertTrue(byPathOnly(folder, assertThrows(SceneLoadException.class, () -> SceneFiles.parse(folder)))
                .message().startsWith("is a directory"));
        Path missing = dir.resolve("missing.xml");
        assertEquals("no such file",
                byPathOnly(missing, assertThrows(SceneLoadException.class, () -> SceneFiles.parse(missing))).message());
        Path big = dir.resolve("big.xml");
        try (RandomAccessFile f = new RandomAccessFile(big.toFile(), "rw")) {
            f.setLength(SceneFiles.MAX_FILE_BYTES + 1);
        }
        assertTrue(byPathOnly(big, assertThrows(SceneLoadException.class, () -> SceneFiles.parse(big)))
                .message().contains("scene files are limited to " + SceneFiles.MAX_FILE_BYTES + " bytes"));
    }

    @Test
    void aStreamOverTheLimitIsRefusedByItsName() {
        byte[] big = new byte[(int) SceneFiles.MAX_FILE_BYTES + 1];
        SceneLoadException e = assertThrows(SceneLoadException.class,
                () -> SceneFiles.read(new ByteArrayInputStream(big), "assets/big.xml", ImageSource.NONE));
        assertTrue(e.getMessage().startsWith("assets/big.xml: file is "), e.getMessage());
    }

    @Test
    void problemsInsideTheFileKeepTheirLineAndColumn() throws Exception {
        Path file = dir.resolve("bad.xml");
        Files.writeString(file, "<scene version=\"1\">\n  <terain/>\n</scene>\n");
        SceneLoadException e = assertThrows(SceneLoadException.class, () -> SceneFiles.parse(file));
        assertTrue(e.getMessage().startsWith(file + ":2:3: unknown element <terain>"), e.getMessage());
        assertEquals("f.xml:3:7: m", new SceneProblem("f.xml", 3, 7, "m").toString());
        assertEquals("f.xml: m", new SceneProblem("f.xml", 0, 0, "m").toString());
    }
}
