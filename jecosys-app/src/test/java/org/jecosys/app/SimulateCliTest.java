package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** jecosys simulate: output, exit codes, --json keys and the --dump header. */
class SimulateCliTest {
    @TempDir
    Path dir;

    @Test
    void printsTheReportAndWritesJsonAndCsv() throws Exception {
        Path json = dir.resolve("r.json");
        Path csv = dir.resolve("s.csv");
        CliTest.Result r = CliTest.run("simulate", "scenes/c1.xml", "--steps", "120", "--threads", "2",
                "--json", json.toString(), "--dump", csv.toString());
        assertEquals(0, r.code(), r.err());
        for (String k : new String[] {"components            1460", "plants                80", "steps                 120",
                "median ms per step", "component updates/s", "allocated bytes/step", "state hash"}) {
            assertTrue(r.out().contains(k), k + " in " + r.out());
        }
        Matcher m = Pattern.compile("state hash +([0-9a-f]{16})").matcher(r.out());
        assertTrue(m.find());
        String text = Files.readString(json, StandardCharsets.UTF_8);
        for (String k : new String[] {"scene", "components", "plants", "steps", "medianMsPerStep",
                "componentUpdatesPerSecond", "allocatedBytesPerStep", "stateHash", "fieldCounters", "nodes", "leaves",
                "visibleNodes", "visibleLeaves", "effectiveNodes", "flowEvaluations"}) {
            assertTrue(text.contains("\"" + k + "\": "), k + " in " + text);
        }
        assertTrue(text.contains("\"stateHash\": \"" + m.group(1) + "\""));
        List<String> rows = Files.readAllLines(csv, StandardCharsets.UTF_8);
        assertEquals("plant,component,species,x,z,windX,windZ,forceX,forceZ,devX,devZ,velX,velZ,bend,azimuth,node,"
                + "nodeDepth", rows.get(0));
        assertEquals(1461, rows.size());
        assertEquals(17, rows.get(1).split(",").length);
    }

    @Test
    void anOpenWorldWalksItsPathWithTilesAroundTheCamera() throws Exception {
        Path json = dir.resolve("w.json");
        CliTest.Result one = CliTest.run("simulate", "scenes/openworld.xml", "--steps", "12", "--threads", "1",
                "--json", json.toString());
        assertEquals(0, one.code(), one.err());
        for (String k : new String[] {"(open world)", "tiles alive", "plants alive", "components alive",
                "tiles built", "p99 ms per step", "state hash"}) {
            assertTrue(one.out().contains(k), k + " in " + one.out());
        }
        assertTrue(Files.readString(json, StandardCharsets.UTF_8).contains("\"openWorld\": true"));
        // the same tiles whatever the workers: OpenWorldTest (1 and 3 animation workers, 1 and 2 tile workers)
        CliTest.Result dump = CliTest.run("simulate", "scenes/openworld.xml", "--steps", "1", "--dump",
                dir.resolve("d.csv").toString());
        assertEquals(2, dump.code(), dump.err());
        assertTrue(dump.err().contains("open world"), dump.err());
        Path frames = dir.resolve("frames");
        CliTest.Result render = CliTest.run("render", "scenes/openworld.xml", "--frames", "2", "--out", frames.toString(),
                "--size", "96x54");
        assertEquals(0, render.code(), render.err());
        assertTrue(render.out().contains("streamed along its path"), render.out());
        assertTrue(Files.size(frames.resolve("frame-00002.png")) > 0);
        CliTest.Result maps = CliTest.run("render", "scenes/openworld.xml", "--frames", "1", "--out", frames.toString(),
                "--maps");
        assertEquals(2, maps.code(), maps.err());
        assertTrue(maps.err().contains("--maps needs a scene of one square"), maps.err());
        CliTest.Result check = CliTest.run("check", "scenes/openworld.xml");
        assertEquals(0, check.code(), check.err());
        assertTrue(check.out().contains("ok (an open world of 16 m tiles within 64 m, 3 species"), check.out());
    }

    @Test
    void theHashDoesNotDependOnThreadsAndTheModeAndFieldFlagsWork() {
        String one = hash(CliTest.run("simulate", "scenes/c1.xml", "--steps", "60", "--threads", "1"));
        String three = hash(CliTest.run("simulate", "scenes/c1.xml", "--steps", "60", "--threads", "3"));
        assertEquals(one, three);
        CliTest.Result st = CliTest.run("simulate", "scenes/c1.xml", "--steps", "10", "--mode", "static",
                "--field", "off", "--dt", "0.02");
        assertEquals(0, st.code(), st.err());
        assertTrue(st.out().contains("mode static, field off"), st.out());
    }

    private static String hash(CliTest.Result r) {
        assertEquals(0, r.code(), r.err());
        Matcher m = Pattern.compile("state hash +([0-9a-f]{16})").matcher(r.out());
        assertTrue(m.find(), r.out());
        return m.group(1);
    }

    @Test
    void anUnwritableOutputFileIsBadInputFoundBeforeTheRun() {
        Path aFile = dir.resolve("a-file.txt");
        try {
            java.nio.file.Files.writeString(aFile, "x");
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        Path bad = aFile.resolve("no/such/folder/x.csv");
        CliTest.Result r = CliTest.run("simulate", "scenes/c1.xml", "--steps", "5", "--dump", bad.toString());
        assertEquals(2, r.code());
        assertTrue(r.err().contains("--dump " + bad + ": is in " + bad.getParent() + ", which cannot be made: " + aFile
                + " is a file, not a folder"), r.err());
        assertFalse(r.err().contains("\tat "), r.err());
        assertFalse(r.out().contains("state hash"), "nothing ran: " + r.out());
        CliTest.Result v = CliTest.run("simulate", "scenes/c1.xml", "--steps", "5", "--json", dir.toString(),
                "--verbose");
        assertEquals(2, v.code());
        assertTrue(v.err().contains("--json " + dir + ": is a folder"), v.err());
        assertFalse(v.out().contains("state hash"), "nothing ran: " + v.out());
    }

    @Test
    void aBadThreadCountIsBadInput() {
        CliTest.Result r = CliTest.run("simulate", "scenes/c1.xml", "--threads", "0");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("--threads must be in [1, 256]"), r.err());
    }
}
