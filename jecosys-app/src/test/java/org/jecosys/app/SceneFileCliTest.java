package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.scene.SceneFiles;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Reliability, fourth pass, at the command line: a scene path that is not a readable scene file (a
 * named pipe, a folder, a file over the size limit) is refused by every command that loads a scene
 * (check, simulate, render, view) with exit 2 and a problem located by its path only, no {@code 0:0}.
 */
@Tag("reliability")
class SceneFileCliTest {
    @TempDir
    Path dir;

    /** Every command that loads a scene, run on {@code scene}: exit 2 and {@code expected} printed. */
    private void everyCommandRefuses(Path scene, String expected) {
        String out = dir.resolve("frames").toString();
        String[][] commands = {
            {"check", scene.toString()},
            {"simulate", scene.toString(), "--steps", "1"},
            {"render", scene.toString(), "--frames", "1", "--out", out},
            {"view", scene.toString()},
        };
        for (String[] c : commands) {
            CliTest.Result r = CliTest.run(c);
            assertEquals(2, r.code(), c[0] + ": " + r.err());
            assertTrue(r.err().contains(expected), c[0] + ": " + r.err());
            assertFalse(r.err().contains(":0:0"), c[0] + ": " + r.err());
        }
    }

    @Test
    void aPipeAFolderAndAFileOverTheLimitAreNamedByTheirPathOnly() throws Exception {
        Path fifo = dir.resolve("pipe.xml");
        assertEquals(0, new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor());
        everyCommandRefuses(fifo, fifo + ": is not a regular file but a named pipe (FIFO)");
        Path folder = Files.createDirectory(dir.resolve("folder.xml"));
        everyCommandRefuses(folder, folder + ": is a directory");
        Path big = dir.resolve("big.xml");
        try (RandomAccessFile f = new RandomAccessFile(big.toFile(), "rw")) {
            f.setLength(SceneFiles.MAX_FILE_BYTES + 1);
        }
        everyCommandRefuses(big, big + ": file is " + (SceneFiles.MAX_FILE_BYTES + 1) + " bytes");
    }
}
