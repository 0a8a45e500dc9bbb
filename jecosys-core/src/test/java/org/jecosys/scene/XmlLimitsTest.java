package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Reliability, fourth pass, fault 5: many small elements no longer exhaust the heap. The reader
 * stops, located, at the element that crosses the element limit, the attribute limit or what this
 * heap allows, before building the rest of the file; the limits refuse no valid scene (they are
 * above the schema's own maxima, and a scene near them loads) and are far above the shipped ones.
 */
@Tag("reliability")
class XmlLimitsTest {
    /** Empty elements per line of the generated file. */
    static final int PER_LINE = 64;

    @TempDir
    Path dir;

    /**
     * The file: {@code <scene version="1">}, then lines of 64 empty {@code <a/>} elements up
     * to just under {@link SceneFiles#MAX_FILE_BYTES} (2,088,960 of them), and no closing tag, so a
     * reader that went on to the end would report malformed XML rather than the limit.
     */
    static Path manyEmptyElements(Path dir) throws IOException {
        Path file = dir.resolve("many.xml");
        String head = "<scene version=\"1\">\n";
        String line = "<a/>".repeat(PER_LINE) + "\n";
        long lines = (SceneFiles.MAX_FILE_BYTES - head.length()) / line.length();
        try (Writer w = new BufferedWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8))) {
            w.write(head);
            for (long i = 0; i < lines; i++) {
                w.write(line);
            }
        }
        assertTrue(Files.size(file) <= SceneFiles.MAX_FILE_BYTES);
        assertTrue(lines * PER_LINE > 2_000_000, "elements: " + lines * PER_LINE);
        return file;
    }

    @Test
    void twoMillionEmptyElementsAreRefusedAtTheOneThatCrossesTheLimit() throws Exception {
        Path file = manyEmptyElements(dir);
        SceneLoadException e = assertThrows(SceneLoadException.class, () -> SceneFiles.parse(file));
        assertEquals(1, e.problems().size(), e.getMessage());
        // the root is element 1, so the <a/> with 0-based index MAX_ELEMENTS - 1 is one too many
        int k = SceneFiles.MAX_ELEMENTS - 1;
        SceneProblem p = e.problems().get(0);
        assertEquals(2 + k / PER_LINE, p.line(), p.toString());
        assertEquals(k % PER_LINE * 4 + 1, p.column(), p.toString());
        assertEquals(file + ":" + p.line() + ":" + p.column() + ": <a>: more than 300,000 elements in one scene file "
                + "(the limit; no valid scene has more); reading stopped here", p.toString());
    }

    @Test
    void aSmallHeapStopsTheReaderEarlierAndTheProblemNamesTheHeap() throws Exception {
        Path file = manyEmptyElements(dir);
        byte[] bytes = Files.readAllBytes(file);
        String text = new String(bytes, StandardCharsets.UTF_8);
        long heap = 128L << 20;
        SceneLoadException e = assertThrows(SceneLoadException.class,
                () -> new XmlReader("many.xml", text, bytes.length, heap).read());
        SceneProblem p = e.problems().get(0);
        String m = p.message();
        assertTrue(m.startsWith("<a>: reading stopped at element "), m);
        assertTrue(m.contains("the Java heap of 128 MiB") && m.contains("-Xmx"), m);
        // the budget: 80% of the heap, less the program's 48 MiB and the text (its bytes, two per character)
        long budget = (long) (heap * SceneBudget.HEAP_SHARE) - SceneBudget.BASELINE_BYTES - bytes.length
                - 2L * text.length();
        // the root with its one attribute (version="1"), then empty elements until the first one past it
        long root = XmlReader.BYTES_PER_ELEMENT + XmlReader.BYTES_PER_ATTRIBUTE + XmlReader.BYTES_PER_CHAR;
        long stop = (budget - root) / XmlReader.BYTES_PER_ELEMENT + 2;
        assertTrue(stop < SceneFiles.MAX_ELEMENTS, "stops before the count limit: " + stop);
        assertEquals(2 + (stop - 2) / PER_LINE, p.line(), p.toString());
        assertTrue(m.contains("element " + SceneBudget.count(stop) + " (with 1 attribute so far)"), m);
    }

    @Test
    void attributesAreLimitedInTotalAndLocatedAtTheirElement() throws Exception {
        int perElement = 999; // the parser's own limit per element is 1,000
        StringBuilder line = new StringBuilder("<a");
        for (int i = 0; i < perElement; i++) {
            line.append(" a").append(Integer.toString(i, 36)).append("=\"\"");
        }
        line.append("/>\n");
        // the root has one attribute; the k-th <a> (1-based) crosses the limit
        int k = (SceneFiles.MAX_ATTRIBUTES - 1) / perElement + 1;
        Path file = dir.resolve("attributes.xml");
        try (Writer w = new BufferedWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8))) {
            w.write("<scene version=\"1\">\n");
            for (int i = 0; i < k + 10; i++) {
                w.write(line.toString());
            }
            w.write("</scene>\n");
        }
        SceneLoadException e = assertThrows(SceneLoadException.class, () -> SceneFiles.parse(file));
        assertEquals(1, e.problems().size(), e.getMessage());
        assertEquals(file + ":" + (1 + k) + ":1: <a>: more than 700,000 attributes in one scene file, all elements "
                + "together (the limit; no valid scene has more); reading stopped here", e.getMessage());
    }

    @Test
    void attributesAreLocatedByOnePassOverTheirTagAcrossLinesAndValuesWithLineBreaks() throws Exception {
        String xml = "<scene version=\"1\" name=\"two\nlines\"\r\n    bogus=\"1\">\n  <terrain sizeX=\"10\"\n"
                + "      sizeZ=\"x\" other='2'/>\n</scene>\n";
        SceneLoadException e = assertThrows(SceneLoadException.class,
                () -> SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "at.xml", null));
        assertTrue(e.getMessage().startsWith("at.xml:3:5: unknown attribute 'bogus' on <scene>"), e.getMessage());
        assertTrue(e.getMessage().contains("\nat.xml:5:7: attribute 'sizeZ' of <terrain>"), e.getMessage());
        assertTrue(e.getMessage().contains("\nat.xml:5:17: unknown attribute 'other' on <terrain>"), e.getMessage());
    }

    /** The most elements (index 0) and attributes (1) the schema's counts allow under {@code e}. */
    private static long[] schemaMaxima(ElementSpec e) {
        long elements = 1;
        long attributes = e.attrs.size();
        long widestElements = 0;
        long widestAttributes = 0;
        for (ElementSpec.Child c : e.children) {
            long[] m = schemaMaxima(c.spec);
            if (e.choice) { // any of the kinds, maxChildren in all
                widestElements = Math.max(widestElements, m[0]);
                widestAttributes = Math.max(widestAttributes, m[1]);
            } else {
                elements += c.max * m[0];
                attributes += c.max * m[1];
            }
        }
        if (e.choice) {
            elements += e.maxChildren * widestElements;
            attributes += e.maxChildren * widestAttributes;
        }
        return new long[] {elements, attributes};
    }

    @Test
    void theLimitsAreAboveTheSchemasMaximaAndFarAboveTheShippedScenes() throws Exception {
        long[] schema = schemaMaxima(SceneSchema.ROOT);
        assertEquals(276_638, schema[0], "the schema's most elements, as the limit's doc says");
        assertEquals(627_025, schema[1], "the schema's most attributes, as the limit's doc says");
        assertTrue(SceneFiles.MAX_ELEMENTS >= schema[0] && SceneFiles.MAX_ATTRIBUTES >= schema[1]);
        int scenes = 0;
        try (DirectoryStream<Path> shipped = Files.newDirectoryStream(Path.of("scenes"), "*.xml")) {
            for (Path f : shipped) {
                byte[] bytes = Files.readAllBytes(f);
                XmlNode root = new XmlReader(f.toString(), new String(bytes, StandardCharsets.UTF_8), bytes.length,
                        Runtime.getRuntime().maxMemory()).read();
                long[] n = count(root);
                assertTrue(n[0] <= 100 && n[1] <= 600, f + ": " + n[0] + " elements, " + n[1] + " attributes");
                scenes++;
            }
        }
        assertEquals(9, scenes, "the shipped scenes");
    }

    private static long[] count(XmlNode n) {
        long[] c = {1, n.attrs.size()};
        for (XmlNode child : n.children) {
            long[] k = count(child);
            c[0] += k[0];
            c[1] += k[1];
        }
        return c;
    }

    @Test
    void aSceneNearTheSchemasMostElementsLoads() throws Exception {
        // 256 flows with a path of 1,024 waypoints each: 262,000 elements beside the rest of the scene
        Path file = dir.resolve("paths.xml");
        try (Writer w = new BufferedWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8))) {
            w.write("<scene version=\"1\">\n<terrain sizeX=\"20\" sizeZ=\"20\"/>\n" + SceneFilesTest.SPECIES + "<wind>\n");
            for (int f = 0; f < SceneSchema.MAX_FLOWS; f++) {
                w.write("<uniform id=\"u" + f + "\" strength=\"1\"><path>\n");
                for (int k = 0; k < SceneSchema.MAX_WAYPOINTS; k++) {
                    w.write("<waypoint x=\"" + k % 97 + "\" z=\"" + k % 89 + "\"/>\n");
                }
                w.write("</path></uniform>\n");
            }
            w.write("</wind>\n</scene>\n");
        }
        SceneDef scene = SceneFiles.parse(file);
        assertEquals(SceneSchema.MAX_FLOWS, scene.flows().size());
        assertEquals(SceneSchema.MAX_WAYPOINTS, scene.flows().get(SceneSchema.MAX_FLOWS - 1).motion().waypoints().size());
    }
}
