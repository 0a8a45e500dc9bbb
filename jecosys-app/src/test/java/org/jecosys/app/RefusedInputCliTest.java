package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.zip.CRC32;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Input that cannot run is refused before anything is built: {@code check} exits 2 with
 * FILE:LINE:COL at the attribute that asks too much and names the limit (no stack trace, no
 * OutOfMemoryError); images are bounded by their header and corrupt ones named; degenerate values
 * are refused and the smallest allowed ones simulate without NaN; output paths are checked first;
 * an unknown command lists the commands. Every case is small and quick (tests run with -Xmx2g).
 */
class RefusedInputCliTest {
    @TempDir
    Path dir;

    /** C1's terrain and one grass species, with {@code extra} before the wind and {@code flows} in it. */
    private Path scene(String name, String terrain, String speciesAndDistributions, String flows) throws Exception {
        String xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                + "<scene version=\"1\" name=\"abuse\" seed=\"3\">\n"
                + "  " + terrain + "\n"
                + speciesAndDistributions
                + "  <wind>\n" + flows + "  </wind>\n"
                + "  <camera x=\"0\" y=\"1.7\" z=\"11\" pitch=\"-12\"/>\n"
                + "</scene>\n";
        Path p = dir.resolve(name);
        Files.writeString(p, xml, StandardCharsets.UTF_8);
        return p;
    }

    private static final String TERRAIN = "<terrain sizeX=\"24\" sizeZ=\"24\" resolution=\"33\" heightScale=\"0.6\"/>";
    private static final String GRASS = "  <species id=\"grass\" maxBend=\"68.8\">\n"
            + "    <lod maxDistance=\"10\"/>\n    <lod primitive=\"lines\"/>\n"
            + "    <component id=\"leaf\" type=\"leaf\" count=\"4\" segments=\"4\" length=\"0.4\" baseWidth=\"0.006\"\n"
            + "        mass=\"0.0004\" stiffness=\"0.2\" dragArea=\"0.002\" lodSegments=\"4 2\"/>\n"
            + "  </species>\n";
    private static final String BREEZE = "    <uniform id=\"breeze\" strength=\"2\" direction=\"20\"/>\n";

    private static void refusedAt(CliTest.Result r, Path file, int line, String... fragments) {
        assertEquals(2, r.code(), r.out() + r.err());
        assertTrue(r.err().contains(file + ":" + line + ":"), "located at line " + line + ": " + r.err());
        for (String f : fragments) {
            assertTrue(r.err().contains(f), f + " in " + r.err());
        }
        assertFalse(r.err().contains("Exception") || r.err().contains("Error:") || r.err().contains("\tat "),
                "no exception or stack trace: " + r.err());
    }

    @Test
    void scenesThatCannotFitInTheHeapAreRefusedByCheckAtTheAttributeThatAsksTooMuch() throws Exception {
        Path count = scene("count.xml", "<terrain sizeX=\"100000\" sizeZ=\"100000\"/>", GRASS
                + "  <distribution species=\"grass\" count=\"10000000\" footprint=\"0.1\"/>\n", BREEZE);
        CliTest.Result r = CliTest.run("check", count.toString());
        refusedAt(r, count, 10, "needs about", "10,000,000 plants", "Java heap", "-Xmx");
        assertTrue(r.err().contains(count + ":10:33: "), "at the count attribute: " + r.err());

        Path density = scene("density.xml", "<terrain sizeX=\"100000\" sizeZ=\"100000\"/>", GRASS
                + "  <distribution species=\"grass\" density=\"10000\"/>\n", BREEZE);
        CliTest.Result d = CliTest.run("check", density.toString());
        refusedAt(d, density, 10, "needs about");
        assertTrue(d.err().contains(density + ":10:33: "), "at the density attribute: " + d.err());

        StringBuilder many = new StringBuilder();
        for (int s = 0; s < 64; s++) {
            many.append("  <species id=\"s").append(s).append("\" poses=\"64\">\n    <lod primitive=\"lines\"/>\n")
                    .append("    <variation variants=\"64\"/>\n");
            for (int c = 0; c < 32; c++) {
                many.append("    <component id=\"c").append(c).append("\" type=\"leaf\" count=\"256\" segments=\"32\" ")
                        .append("length=\"1\" baseWidth=\"0.01\" mass=\"0.01\" stiffness=\"1\" lodSegments=\"32\"/>\n");
            }
            many.append("  </species>\n");
        }
        Path species = scene("species.xml", TERRAIN, many.toString(), BREEZE);
        refusedAt(CliTest.run("check", species.toString()), species, 4, "pose tables", "needs about");

        // 256 distributions of ten million plants: counted without int overflow, beyond int indexes
        StringBuilder dists = new StringBuilder(GRASS);
        for (int k = 0; k < 256; k++) {
            dists.append("  <distribution species=\"grass\" count=\"10000000\" footprint=\"0.001\"/>\n");
        }
        Path overflow = scene("overflow.xml", "<terrain sizeX=\"100000\" sizeZ=\"100000\"/>", dists.toString(), BREEZE);
        CliTest.Result o = CliTest.run("check", overflow.toString());
        refusedAt(o, overflow, 10, "2,560,000,000 plants", "at most 2,147,483,639");
        assertFalse(o.err().contains("-1734967296") || o.out().contains("-"), o.out() + o.err());
    }

    @Test
    void aDenseDistributionOnASmallTerrainIsCappedAndRunsQuickly() throws Exception {
        Path dense = scene("dense.xml", "<terrain sizeX=\"100\" sizeZ=\"100\"/>", GRASS
                + "  <distribution species=\"grass\" density=\"10000\"/>\n", BREEZE);
        CliTest.Result c = CliTest.run("check", dense.toString());
        assertEquals(0, c.code(), c.err());
        CliTest.Result r = CliTest.run("simulate", dense.toString(), "--steps", "2", "--threads", "2");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("capped at 10000000"), r.err());
        // the work is bounded by what the footprints let fit (40 candidates per plant that fits), not by
        // the 10,000,000 asked for
        Matcher examined = Pattern.compile("found in (\\d+) candidates").matcher(r.err());
        assertTrue(examined.find(), r.err());
        long candidates = Long.parseLong(examined.group(1));
        assertTrue(candidates < 5_000_000, "candidates examined: " + candidates);
        Matcher m = Pattern.compile("plants +(\\d+)").matcher(r.out());
        assertTrue(m.find(), r.out());
        int plants = Integer.parseInt(m.group(1));
        assertTrue(plants > 10_000 && plants < 400_000, "what the footprints let fit: " + plants);
    }

    /** A PNG whose header says 40000 x 40000 pixels, a few hundred bytes long. */
    private Path hugePng() throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        out.write(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'});
        ByteArrayOutputStream ihdr = new ByteArrayOutputStream();
        DataOutputStream h = new DataOutputStream(ihdr);
        h.writeInt(40_000);
        h.writeInt(40_000);
        h.write(new byte[] {8, 0, 0, 0, 0}); // 8-bit grey
        chunk(out, "IHDR", ihdr.toByteArray());
        chunk(out, "IDAT", new byte[] {0x78, (byte) 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01});
        chunk(out, "IEND", new byte[0]);
        Path p = dir.resolve("huge.png");
        Files.write(p, bytes.toByteArray());
        return p;
    }

    private static void chunk(DataOutputStream out, String type, byte[] data) throws Exception {
        out.writeInt(data.length);
        byte[] t = type.getBytes(StandardCharsets.US_ASCII);
        out.write(t);
        out.write(data);
        CRC32 crc = new CRC32();
        crc.update(t);
        crc.update(data);
        out.writeInt((int) crc.getValue());
    }

    @Test
    void imagesAreBoundedByTheirHeaderAndCorruptOnesAreNamedByCheck() throws Exception {
        hugePng();
        Path huge = scene("huge.xml", "<terrain sizeX=\"24\" sizeZ=\"24\" heightmap=\"huge.png\"/>", GRASS, BREEZE);
        refusedAt(CliTest.run("check", huge.toString()), huge, 3, "huge.png", "40000 x 40000", "8192 pixels a side");

        BufferedImage img = new BufferedImage(256, 256, BufferedImage.TYPE_BYTE_GRAY);
        for (int y = 0; y < 256; y++) {
            for (int x = 0; x < 256; x++) {
                img.getRaster().setSample(x, y, 0, (x * 7 + y * 13) & 0xff);
            }
        }
        Path good = dir.resolve("good.png");
        ImageIO.write(img, "png", good.toFile());
        byte[] all = Files.readAllBytes(good);
        Files.write(dir.resolve("truncated.png"), Arrays.copyOf(all, all.length / 2));
        Path truncated = scene("truncated.xml", TERRAIN.replace("/>", ">\n    <water source=\"image\" "
                + "image=\"truncated.png\"/>\n  </terrain>"), GRASS, BREEZE);
        CliTest.Result c = CliTest.run("check", truncated.toString());
        refusedAt(c, truncated, 4, "truncated.png");
        CliTest.Result s = CliTest.run("simulate", truncated.toString(), "--steps", "1");
        refusedAt(s, truncated, 4, "truncated.png");

        Path ok = scene("ok.xml", "<terrain sizeX=\"24\" sizeZ=\"24\" heightmap=\"good.png\" heightScale=\"1\"/>", GRASS,
                BREEZE);
        assertEquals(0, CliTest.run("check", ok.toString()).code());
    }

    @Test
    void degenerateGustsAreRefusedAndTheSmallestAllowedOnesSimulateWithoutNaN() throws Exception {
        String dist = GRASS + "  <distribution species=\"grass\" count=\"40\" footprint=\"0.3\"/>\n";
        for (String tiny : List.of("1e-100", "4.9e-324", "0")) {
            Path bad = scene("gust.xml", TERRAIN, dist, "    <gust id=\"g\" strength=\"3\" noiseScale=\"" + tiny + "\"/>\n");
            refusedAt(CliTest.run("check", bad.toString()), bad, 12, "noiseScale", "[0.001, 100000] metres");
        }
        Path smallest = scene("smallest.xml", TERRAIN, dist,
                "    <gust id=\"g\" strength=\"1000000\" noiseScale=\"0.001\" noiseFrequency=\"10000\"/>\n"
                        + "    <source id=\"s\" x=\"0\" z=\"0\" strength=\"1000000\" coreRadius=\"0.001\"/>\n"
                        + "    <vortex id=\"v\" x=\"1\" z=\"1\" strength=\"-1000000\" coreRadius=\"0.001\"/>\n");
        Path csv = dir.resolve("dump.csv");
        CliTest.Result r = CliTest.run("simulate", smallest.toString(), "--steps", "20", "--threads", "1",
                "--dump", csv.toString());
        assertEquals(0, r.code(), r.err());
        List<String> rows = Files.readAllLines(csv, StandardCharsets.UTF_8);
        assertTrue(rows.size() > 100, "rows " + rows.size());
        for (String row : rows) {
            assertFalse(row.contains("NaN") || row.contains("Infinity"), row);
        }
    }

    @Test
    void outputPathsAreCheckedBeforeAnyWork() throws Exception {
        Path file = dir.resolve("a-file");
        Files.writeString(file, "not a folder");
        CliTest.Result render = CliTest.run("render", "scenes/c1.xml", "--frames", "1", "--out", file.toString());
        assertEquals(2, render.code());
        assertTrue(render.err().contains("--out " + file + ": is a file, not a folder"), render.err());
        assertFalse(render.out().contains("Building"), "nothing was built: " + render.out());
        CliTest.Result sub = CliTest.run("render", "scenes/c1.xml", "--frames", "1", "--out",
                file.resolve("sub").toString());
        assertEquals(2, sub.code());
        assertTrue(sub.err().contains("is a file"), sub.err());
        CliTest.Result gif = CliTest.run("render", "scenes/c1.xml", "--frames", "1", "--out", dir.toString(),
                "--gif", dir.toString());
        assertEquals(2, gif.code());
        assertTrue(gif.err().contains("--gif " + dir + ": is a folder"), gif.err());
        CliTest.Result bench = CliTest.run("bench", "--quick", "--out", file.toString());
        assertEquals(2, bench.code());
        assertTrue(bench.err().contains("--out " + file + ": is a file, not a folder"), bench.err());
        assertEquals("not a folder", Files.readString(file));
        // a folder that cannot be made (under a file) is bad input; a missing one is made
        CliTest.Result json = CliTest.run("simulate", "scenes/c1.xml", "--json", file.resolve("no/x.json").toString());
        assertEquals(2, json.code());
        assertTrue(json.err().contains("is a file"), json.err());
        assertFalse(json.out().contains("state hash"), json.out());
    }

    @Test
    void anUnknownCommandIsAnErrorListingTheCommands() throws Exception {
        CliTest.Result r = CliTest.run("simulat", "scenes/c1.xml");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("unknown command 'simulat'"), r.err());
        assertTrue(r.err().contains("view, check, simulate, render, bench"), r.err());
        assertFalse(r.err().contains("simulat: no such file"), "not taken as a scene: " + r.err());
        // a scene file is still the default command's argument
        CliTest.Result missing = CliTest.run("no-such-scene.xml");
        assertEquals(2, missing.code());
        assertTrue(missing.err().contains("no-such-scene.xml: no such file"), missing.err());
    }
}
