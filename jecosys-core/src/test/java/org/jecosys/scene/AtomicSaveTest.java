package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Saving is atomic: a failure after any number of bytes leaves the original intact and no temp file. */
class AtomicSaveTest {
    @TempDir
    Path dir;

    /** Throws once {@code limit} bytes have been written. */
    static final class FailAfter extends FilterOutputStream {
        private long left;

        FailAfter(OutputStream out, long limit) {
            super(out);
            this.left = limit;
        }

        @Override
        public void write(int b) throws IOException {
            if (left-- <= 0) {
                throw new IOException("injected failure");
            }
            out.write(b);
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            for (int i = 0; i < len; i++) {
                write(b[off + i]);
            }
        }
    }

    private List<Path> listing() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.sorted().toList();
        }
    }

    @Test
    void failureAfterAnyNumberOfBytesLeavesTheOriginalUntouched() throws Exception {
        SceneDef original = SceneFiles.parse(Path.of("scenes/meadow.xml"));
        Path target = dir.resolve("meadow.xml");
        byte[] before = "<!-- the user's own file -->\n".getBytes(StandardCharsets.UTF_8);
        Files.write(target, before);
        SceneDef edited = new SceneDef(original.version(), "Edited meadow", original.seed() + 1, original.terrain(),
                original.species(), original.distributions(), original.placements(), original.flows(),
                original.field(), original.camera(), original.animation(), original.render());
        int size = SceneFiles.toXml(edited).getBytes(StandardCharsets.UTF_8).length;
        int tried = 0;
        for (long n = 0; n < size; n = n < 64 ? n + 1 : n * 3 / 2) {
            long limit = n;
            IOException ex = assertThrows(IOException.class,
                    () -> SceneFiles.save(target, edited, out -> new FailAfter(out, limit)));
            assertTrue(ex.getMessage().contains(target.toString()), ex.getMessage());
            assertArrayEquals(before, Files.readAllBytes(target), "original intact after failing at byte " + n);
            assertEquals(List.of(target), listing(), "no temp file left after failing at byte " + n);
            tried++;
        }
        assertTrue(tried > 70);
        SceneFiles.save(target, edited);
        assertEquals(edited, SceneFiles.parse(target));
        assertEquals(List.of(target), listing());
    }

    @Test
    void saveIntoAMissingFolderFailsClearly() {
        Path target = dir.resolve("missing/sub/scene.xml");
        SceneDef d;
        try {
            d = SceneFiles.parse(Path.of("scenes/meadow.xml"));
        } catch (SceneLoadException e) {
            throw new AssertionError(e);
        }
        IOException ex = assertThrows(IOException.class, () -> SceneFiles.save(target, d));
        assertTrue(Files.notExists(target));
        assertTrue(ex.getMessage() != null && !ex.getMessage().isBlank());
    }
}
