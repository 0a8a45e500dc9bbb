package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.jecosys.scene.SceneFiles;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Reliability, fourth pass, fault 5, at the command line: an 8 MiB scene file of about 2.09 million
 * empty elements (under the size limit) ran {@code check} out of memory at 224 MB of heap. Now, in a
 * JVM of 128 MB, {@code check} refuses it with exit 2 and a located message naming the limit, with
 * no stack trace. The time it takes is printed, not asserted (the hang timeout is generous).
 */
@Tag("reliability")
class ManyElementsCliTest {
    @TempDir
    Path dir;

    @Test
    void checkRefusesTwoMillionEmptyElementsAt128MegabytesOfHeap() throws Exception {
        Path file = dir.resolve("many.xml");
        String head = "<scene version=\"1\">\n";
        String line = "<a/>".repeat(64) + "\n";
        long lines = (SceneFiles.MAX_FILE_BYTES - head.length()) / line.length();
        try (Writer w = new BufferedWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8))) {
            w.write(head);
            for (long i = 0; i < lines; i++) {
                w.write(line);
            }
            w.write("</scene>\n");
        }
        assertTrue(Files.size(file) <= SceneFiles.MAX_FILE_BYTES && lines * 64 > 2_000_000);

        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        ProcessBuilder pb = new ProcessBuilder(java.toString(), "-Xmx128m", "-cp", System.getProperty("java.class.path"),
                Main.class.getName(), "check", file.toString()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("out.txt").toFile());
        long start = System.nanoTime();
        Process p = pb.start();
        boolean finished = p.waitFor(60, TimeUnit.SECONDS);
        double seconds = (System.nanoTime() - start) / 1e9;
        if (!finished) {
            p.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
        String out = Files.readString(dir.resolve("out.txt"), StandardCharsets.UTF_8);
        assertTrue(finished, "check finished within 60 s: " + out);
        System.out.printf(Locale.ROOT, "check of %,d empty elements at -Xmx128m: exit %d in %.2f s%n", lines * 64,
                p.exitValue(), seconds);
        assertEquals(2, p.exitValue(), out);
        assertTrue(out.startsWith(file + ":"), out);
        assertTrue(out.matches("(?s)\\S+:\\d+:\\d+: <a>: reading stopped at element [\\d,]+ .*"), out);
        assertTrue(out.contains("the Java heap of 128 MiB") && out.contains("-Xmx")
                && out.contains("at most 300,000 elements"), out);
        assertFalse(out.contains("OutOfMemoryError") || out.contains("Exception") || out.contains("\tat "), out);
    }
}
