package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** The corpus of bad scene files: each fails with its exact FILE:LINE:COL and message. */
class BadSceneTest {
    record Expectation(String file, int line, int column, String fragment) {
        @Override
        public String toString() {
            return file;
        }
    }

    static Path dir() throws URISyntaxException {
        return Path.of(BadSceneTest.class.getResource("bad/expectations.txt").toURI()).getParent();
    }

    static List<Expectation> expectations() throws IOException, URISyntaxException {
        List<Expectation> out = new ArrayList<>();
        for (String line : Files.readAllLines(dir().resolve("expectations.txt"), StandardCharsets.UTF_8)) {
            if (line.isBlank() || line.startsWith("#")) {
                continue;
            }
            String[] p = line.split("\\|", 4);
            out.add(new Expectation(p[0], Integer.parseInt(p[1]), Integer.parseInt(p[2]), p[3]));
        }
        return out;
    }

    static Stream<Expectation> cases() throws IOException, URISyntaxException {
        return expectations().stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void failsAtItsLineAndColumnWithAClearMessage(Expectation e) throws Exception {
        Path file = dir().resolve(e.file());
        SceneLoadException ex = assertThrows(SceneLoadException.class, () -> SceneFiles.parse(file));
        SceneProblem first = ex.problems().get(0);
        assertEquals(file.toString(), first.file());
        assertEquals(e.line(), first.line(), () -> "line of: " + first);
        assertEquals(e.column(), first.column(), () -> "column of: " + first);
        assertTrue(first.message().contains(e.fragment()), () -> "message of: " + first);
        assertTrue(ex.getMessage().startsWith(file + ":" + e.line() + ":" + e.column() + ": "));
        assertFalse(ex.getMessage().contains("Exception"), "no exception names in user messages");
        assertFalse(ex.getMessage().contains("\tat "), "no stack traces in user messages");
    }

    @Test
    void everyCorpusFileHasAnExpectation() throws Exception {
        Set<String> files = new TreeSet<>();
        try (Stream<Path> s = Files.list(dir())) {
            s.filter(p -> p.toString().endsWith(".xml")).forEach(p -> files.add(p.getFileName().toString()));
        }
        Set<String> expected = new TreeSet<>();
        for (Expectation e : expectations()) {
            expected.add(e.file());
        }
        assertEquals(files, expected);
        assertTrue(files.size() >= 40, "the corpus covers every kind of bad input");
    }

    @Test
    void collectsSeveralProblemsInOneRun() {
        String xml = """
                <scene version="1">
                  <terrain sizeX="-1" sizeZ="NaN" roughness="2"/>
                </scene>
                """;
        SceneLoadException ex = assertThrows(SceneLoadException.class,
                () -> SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "three.xml", null));
        assertEquals(3, ex.problems().size());
        assertEquals(List.of("sizeX", "sizeZ", "roughness"), ex.problems().stream()
                .map(p -> p.message().replaceAll(".*attribute '([a-zA-Z]+)'.*", "$1")).toList());
    }

    @Test
    void missingFileAndDirectoryAreClearProblems() throws Exception {
        Path missing = dir().resolve("no-such-scene.xml");
        SceneLoadException a = assertThrows(SceneLoadException.class, () -> SceneFiles.parse(missing));
        assertTrue(a.getMessage().endsWith("no such file"));
        SceneLoadException b = assertThrows(SceneLoadException.class, () -> SceneFiles.parse(dir()));
        assertTrue(b.getMessage().contains("is a directory"));
    }

    @Test
    void filesOverTheSizeLimitAreRejectedBeforeParsing() throws Exception {
        Path big = Files.createTempFile("big", ".xml");
        try {
            byte[] chunk = new byte[1 << 20];
            java.util.Arrays.fill(chunk, (byte) ' ');
            try (var out = Files.newOutputStream(big)) {
                out.write("<scene version=\"1\">".getBytes(StandardCharsets.UTF_8));
                for (int i = 0; i < 9; i++) {
                    out.write(chunk);
                }
                out.write("</scene>".getBytes(StandardCharsets.UTF_8));
            }
            SceneLoadException ex = assertThrows(SceneLoadException.class, () -> SceneFiles.parse(big));
            assertTrue(ex.getMessage().contains("limited to " + SceneFiles.MAX_FILE_BYTES + " bytes"));
        } finally {
            Files.deleteIfExists(big);
        }
    }
}
