package org.jecosys.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The benchmark suite at smoke size: every section runs and the report has its structure (tables
 * with the paper's columns, results.json, charts). Speeds are never checked here.
 */
class BenchSmokeTest {
    @TempDir
    Path out;

    /**
     * Every section but the render scale (its smoke alone takes 20 to 35 s on 2 cores: the meadow built and
     * drawn on both resolve paths and five looks; {@link #renderScaleSmoke} runs it, tagged slow).
     */
    @Test
    void smokeRunWritesAllThreeOutputs() throws Exception {
        ByteArrayOutputStream progress = new ByteArrayOutputStream();
        BenchSuite suite = BenchSuite.standard(Path.of("scenes"));
        int before = suite.sections().size();
        suite.sections().removeIf(s -> s instanceof RenderScaleSection);
        assertEquals(before - 1, suite.sections().size(), "the render-scale section left out");
        Report r = suite.run(Mode.SMOKE, out, new PrintStream(progress, true, StandardCharsets.UTF_8));
        System.out.print(progress.toString(StandardCharsets.UTF_8)); // each section's time, in the test's output
        assertEquals(List.of(), r.failures());
        String md = Files.readString(out.resolve("tables.md"));
        String json = Files.readString(out.resolve("results.json"));
        for (String title : new String[] {"Table 1", "Table 2", "Table 3", "Table 4", "Pre-computation",
                "Force-field update", "Table 5", "Table 6: force-field performance (simulation only",
                "Table 6: force-field performance (rendered at 1280x720", "Table 7: animation algorithm performance "
                + "(simulation only", "Table 7: animation algorithm performance (rendered", "Scale curve"}) {
            assertTrue(md.contains("### " + title), title);
        }
        assertTrue(md.contains("## Machine") && md.contains("- CPU: "));
        // the open world's tiles along a walk: checkpoints with the heap after GC and the tiles alive
        Table walk = r.tables().stream().filter(t -> t.id().equals("streaming")).findFirst().orElseThrow();
        assertEquals(2, walk.rows().size(), "two checkpoints in the smoke run");
        // the open world's simulation along a walk: two checkpoints, tiles and components alive
        Table world = r.tables().stream().filter(t -> t.id().equals("open-world")).findFirst().orElseThrow();
        assertEquals(2, world.rows().size(), "two checkpoints of the open world's walk in the smoke run");
        for (List<Object> row : walk.rows()) {
            int tiles = ((Number) row.get(2)).intValue();
            assertTrue(tiles > 20 && tiles <= 100, "tiles alive within 100 m of the view: " + tiles);
        }
        for (String key : new String[] {"\"table1\"", "\"table2\"", "\"table3\"", "\"table4\"", "\"machine\"",
                "\"fieldScale\"", "\"precompute\"", "\"table5\"", "\"table6a\"", "\"table6b\"", "\"table7a\"",
                "\"table7b\"", "\"scale\"", "\"paperScenes\"", "\"glRenderer\": \"llvmpipe"}) {
            assertTrue(json.contains(key), key);
        }
        for (String chart : new String[] {"table1.png", "table2.png", "field-scale.png", "table7.png",
                "scale-updates.png", "scale-step.png"}) {
            Path png = out.resolve("charts").resolve(chart);
            assertTrue(Files.size(png) > 1000, chart);
            assertEquals(0x89, Files.readAllBytes(png)[0] & 0xff, chart + " is a PNG");
        }
        assertTrue(progress.toString(StandardCharsets.UTF_8).contains("bench: [1/"));
        for (Table t : r.tables()) {
            for (List<Object> row : t.rows()) {
                assertEquals(t.headers().size(), row.size(), t.id());
            }
        }
    }

    /** The render-scale section's smoke: the meadow on every resolve path, its fixed step and its looks. */
    @Test
    @org.junit.jupiter.api.Tag("slow")
    void renderScaleSmoke() throws Exception {
        ByteArrayOutputStream progress = new ByteArrayOutputStream();
        BenchSuite suite = BenchSuite.standard(Path.of("scenes"));
        suite.sections().removeIf(s -> !(s instanceof RenderScaleSection));
        assertEquals(1, suite.sections().size(), "the render-scale section alone");
        Report r = suite.run(Mode.SMOKE, out, new PrintStream(progress, true, StandardCharsets.UTF_8));
        System.out.print(progress.toString(StandardCharsets.UTF_8));
        assertEquals(List.of(), r.failures());
        String md = Files.readString(out.resolve("tables.md"));
        String json = Files.readString(out.resolve("results.json"));
        // render scale: the meadow on every resolve path the context runs, transform feedback always
        assertTrue(md.contains("### Render scale"), "render scale");
        assertTrue(md.contains(org.jecosys.render.ResolvePath.TRANSFORM_FEEDBACK.description()), "the 3.3 path named");
        assertTrue(json.contains("\"renderScale\"") && json.contains("/ TRANSFORM_FEEDBACK\""), "render scale raw");
        // the plants' draw calls: some, and at most two per species and level (plants drawn whole, plants
        // in a transition band)
        int lists = 0;
        for (org.jecosys.plant.SpeciesDef sp : org.jecosys.scene.SceneFiles.parse(Path.of("scenes", "meadow.xml"))
                .simulationDef().species()) {
            lists += sp.lods().size();
        }
        Table scale = r.tables().stream().filter(t -> t.id().equals("render-scale")).findFirst().orElseThrow();
        int callsColumn = scale.headers().indexOf("plant draw calls");
        assertTrue(callsColumn >= 0, "plant draw calls column");
        for (List<Object> row : scale.rows()) {
            long calls = ((Number) row.get(callsColumn)).longValue();
            assertTrue(calls > 0 && calls <= 2L * lists, "plant draw calls " + calls + " for " + lists + " lists");
        }
        // the GPU work counted per frame (pipeline statistics): present and positive for every scene
        for (String column : new String[] {"VS invocations / frame", "FS invocations / frame", "primitives / frame",
            "fragments / pixel", "2nd view: decision, lists and records, Java ms"}) {
            int c = scale.headers().indexOf(column);
            assertTrue(c >= 0, column + " column");
            for (List<Object> row : scale.rows()) {
                assertTrue(((Number) row.get(c)).doubleValue() > 0, column + " of " + row.get(0) + ": " + row.get(c));
            }
        }
        // the meadow's fixed step without rendering, and its look switched (the shadows on both paths)
        Table step = r.tables().stream().filter(x -> x.id().equals("render-scale-step")).findFirst().orElseThrow();
        assertTrue(((Number) step.rows().get(0).get(2)).doubleValue() > 0, "ms per fixed step");
        Table looks = r.tables().stream().filter(x -> x.id().equals("render-looks")).findFirst().orElseThrow();
        assertEquals(List.of("ground", "map", "off", "ground", "off"), looks.rows().stream().map(x -> x.get(1)).toList());
        for (List<Object> row : looks.rows()) {
            for (int c = 2; c < row.size(); c++) {
                assertTrue(((Number) row.get(c)).doubleValue() > 0, "looks " + row.get(0) + "/" + row.get(1) + " " + c);
            }
        }
    }

    @Test
    void modelTablesEqualThePaper() throws Exception {
        ModelTables m = new ModelTables(Path.of("scenes"));
        for (List<Object> row : m.table2().rows()) {
            assertEquals(row.get(2), row.get(3), "LOD1 of " + row.get(0));
            assertEquals(row.get(4), row.get(5), "LOD2 of " + row.get(0));
            assertEquals(row.get(6), row.get(7), "LOD3 of " + row.get(0));
        }
        for (List<Object> row : m.table1().rows()) {
            assertEquals(row.get(2), row.get(3), "rose level " + row.get(0));
        }
        for (List<Object> row : m.table4().rows()) {
            assertEquals(row.get(1), row.get(2));
            assertEquals(row.get(3), row.get(4));
            assertEquals(row.get(5), row.get(6));
        }
    }

    @Test
    void jsonWriterEscapesAndNullsNonFiniteNumbers() {
        String s = Json.write(java.util.Map.of("a\"b", List.of(1, 2.5, Double.NaN, "x\ny")));
        assertEquals("{\n  \"a\\\"b\": [1, 2.5, null, \"x\\ny\"]\n}\n", s);
    }

    @Test
    void jsonWriterWritesArraysOfNumbersAsLists() {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        m.put("d", new double[] {1.5, Double.NaN, 2});
        m.put("f", new float[] {0.25f});
        m.put("i", new int[] {1, 2});
        m.put("l", new long[] {});
        assertEquals("{\n  \"d\": [1.5, null, 2],\n  \"f\": [0.25],\n  \"i\": [1, 2],\n  \"l\": []\n}\n",
                Json.write(m));
    }
}
