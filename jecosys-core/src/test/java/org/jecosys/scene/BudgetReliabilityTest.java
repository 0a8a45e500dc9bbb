package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.terrain.PlacementWork;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The scene check bounds time, not only memory (issue 36, faults 4 and 8): a scene whose placement
 * work ({@link PlacementWork}) or ground-cover blades per frame exceed the stated limits is refused
 * with a problem at FILE:LINE:COL of the attribute to blame, naming the limit; the issue's scene (a
 * 100 m footprint with count 0 beside 400,000 plants) and every shipped scene pass, with a margin.
 * Only definitions are checked: nothing is built, so each case takes milliseconds.
 */
@Tag("reliability")
class BudgetReliabilityTest {
    private static final String FILE = "budget.xml";

    /** A scene on a terrain of {@code size} metres with resource maps of {@code mapRes} cells; line 8 on is {@code body}. */
    private static String scene(double size, int mapRes, String body) {
        return "<scene version=\"1\" name=\"budget\" seed=\"3\">\n"
                + "<terrain sizeX=\"" + size + "\" sizeZ=\"" + size + "\" resolution=\"65\">\n"
                + "<water source=\"noise\" resolution=\"" + mapRes + "\" scale=\"20\"/>\n"
                + "<nutrients source=\"noise\" resolution=\"" + mapRes + "\" scale=\"25\"/>\n"
                + "</terrain>\n"
                + "<species id=\"g\"><lod/><component id=\"leaf\" type=\"leaf\" segments=\"3\" length=\"0.3\""
                + " baseWidth=\"0.01\" mass=\"0.001\" stiffness=\"1\" lodSegments=\"3\"/></species>\n"
                + "<species id=\"t\"><lod/><component id=\"leaf\" type=\"leaf\" segments=\"3\" length=\"0.3\""
                + " baseWidth=\"0.01\" mass=\"0.001\" stiffness=\"1\" lodSegments=\"3\"/></species>\n"
                + body + "</scene>\n";
    }

    private static SceneDef accepted(String xml) throws SceneLoadException {
        return SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), FILE, null);
    }

    /** The one refusal whose message has {@code marker}: located, in FILE:LINE:COL form. */
    private static SceneProblem refusal(String xml, String marker) {
        SceneLoadException e = assertThrows(SceneLoadException.class, () -> accepted(xml));
        for (SceneProblem p : e.problems()) {
            if (p.message().contains(marker)) {
                assertTrue(p.toString().startsWith(FILE + ":" + p.line() + ":" + p.column() + ": "), p.toString());
                return p;
            }
        }
        return fail("no problem says '" + marker + "': " + e.problems());
    }

    /** 1-based column of {@code attr=} on line {@code line} (1-based) of xml. */
    private static int column(String xml, int line, String attr) {
        String text = xml.split("\n", -1)[line - 1];
        int i = text.indexOf(" " + attr + "=");
        assertTrue(i >= 0, attr + " on line " + line + ": " + text);
        return i + 2;
    }

    @Test
    void aFootprintOverTheWholeResourceMapWhoseWaterIsNeverMetIsRefusedAtTheFootprint() {
        // each of its 5,040 candidates averages a 1024 x 1024 map that never has 0.9 over 100 m: minutes
        String xml = scene(200, 1024, "<distribution species=\"t\" count=\"1\" minWater=\"0.9\" footprint=\"100\"/>\n");
        SceneProblem p = refusal(xml, "placement budget");
        assertEquals(8, p.line(), p.toString());
        assertEquals(column(xml, 8, "footprint"), p.column(), "at the footprint: " + p);
        assertTrue(p.message().contains("more than the placement budget of 30,000,000,000 units of work"
                + " (SceneWorkBudget.MAX_PLACEMENT_WORK"), p.message());
        assertTrue(p.message().contains("up to 5,040 candidates"), p.message());
        assertTrue(p.message().contains("footprint 100 m"), p.message());
    }

    @Test
    void moreCandidatesThanTheBudgetAllowsAreRefusedAtTheCount() {
        String xml = scene(800, 64, "<distribution species=\"g\" count=\"8000000\" footprint=\"0.05\"/>\n");
        SceneProblem p = refusal(xml, "placement budget");
        assertEquals(8, p.line(), p.toString());
        assertEquals(column(xml, 8, "count"), p.column(), "at the count: " + p);
        assertTrue(p.message().contains("up to 320,005,000 candidates"), p.message());
    }

    @Test
    void aDensityOverTheBudgetIsRefusedAtTheDensity() {
        String xml = scene(800, 64, "<distribution species=\"g\" density=\"14\" footprint=\"0.05\"/>\n");
        SceneProblem p = refusal(xml, "placement budget");
        assertEquals(column(xml, 8, "density"), p.column(), "at the density: " + p);
    }

    @Test
    void theIssuesSceneA100MetreFootprintWithCountZeroBeside400000PlantsIsAccepted() throws SceneLoadException {
        String grass = "<distribution species=\"g\" count=\"400000\" footprint=\"0.05\" waterUse=\"0\" nutrientUse=\"0\"/>\n";
        String big = "<distribution species=\"t\" count=\"0\" footprint=\"100\"/>\n";
        SceneDef alone = accepted(scene(200, 128, grass));
        SceneDef beside = accepted(scene(200, 128, grass + big));
        double a = PlacementWork.estimate(alone.terrain(), alone.distributions(), alone.placements()).total();
        double b = PlacementWork.estimate(beside.terrain(), beside.distributions(), beside.placements()).total();
        assertTrue(b <= 1.05 * a, "the 100 m distribution adds its mask and its place in the order only: " + b + " vs " + a);
    }

    @Test
    void theIssuesCoverDenseAndFarOutIsRefusedWithTheLimit() {
        String xml = scene(80, 64, "<distribution species=\"g\" count=\"10\" footprint=\"0.05\"/>\n"
                + "<render>\n<groundCover amount=\"1\" density=\"20000\" reach=\"50\"/>\n</render>\n");
        SceneProblem p = refusal(xml, "ground cover");
        assertEquals(10, p.line(), p.toString());
        // the reach is 6.4 times the default's and the density 8: the tiles within reach multiply more
        assertEquals(column(xml, 10, "reach"), p.column(), "at the reach: " + p);
        assertTrue(p.message().contains("up to 81,920,000 blades per view in a frame"), p.message());
        assertTrue(p.message().contains("more than the limit of 4,000,000 blades per view"
                + " (RenderDef.GroundCover.MAX_BLADES_PER_VIEW"), p.message());
    }

    @Test
    void denseCoverAtTheDefaultReachIsRefusedAtTheDensity() {
        String xml = scene(80, 64, "<distribution species=\"g\" count=\"10\" footprint=\"0.05\"/>\n"
                + "<render>\n<groundCover amount=\"1\" density=\"20000\" reach=\"8\"/>\n</render>\n");
        SceneProblem p = refusal(xml, "ground cover");
        assertEquals(column(xml, 10, "density"), p.column(), "at the density: " + p);
        assertTrue(p.message().contains("up to 5,560,000 blades"), p.message());
    }

    @Test
    void ordinaryCoverReachingTooFarIsRefusedAtTheReach() {
        String xml = scene(80, 64, "<distribution species=\"g\" count=\"10\" footprint=\"0.05\"/>\n"
                + "<render>\n<groundCover amount=\"1\" density=\"2500\" reach=\"50\"/>\n</render>\n");
        SceneProblem p = refusal(xml, "ground cover");
        assertEquals(column(xml, 10, "reach"), p.column(), "at the reach: " + p);
        assertTrue(p.message().contains("up to 10,240,000 blades"), p.message());
    }

    @Test
    void coverWithinTheLimitOrTurnedOffIsAccepted() throws SceneLoadException {
        String d = "<distribution species=\"g\" count=\"10\" footprint=\"0.05\"/>\n";
        accepted(scene(80, 64, d + "<render>\n<groundCover amount=\"1\" density=\"10000\" reach=\"8\"/>\n</render>\n"));
        accepted(scene(80, 64, d + "<render>\n<groundCover amount=\"0\" density=\"20000\" reach=\"50\"/>\n</render>\n"));
        // a terrain smaller than the reach has fewer tiles than the reach's disc
        accepted(scene(10, 64, d + "<render>\n<groundCover amount=\"1\" density=\"20000\" reach=\"50\"/>\n</render>\n"));
    }

    @Test
    void everyShippedScenePassesWithAMargin() throws IOException, SceneLoadException {
        List<String> report = new ArrayList<>();
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(Path.of("scenes"), "*.xml")) {
            for (Path f : ds) {
                SceneDef s = SceneFiles.parse(f);
                double work = PlacementWork.estimate(s.terrain(), s.distributions(), s.placements()).total();
                long blades = s.render().groundCover().bladesPerViewAtMost(s.terrain().sizeX(), s.terrain().sizeZ());
                report.add(f.getFileName() + ": " + SceneWorkBudget.units(work) + ", " + blades + " blades");
                assertTrue(work <= SceneWorkBudget.MAX_PLACEMENT_WORK / 10, "a tenth of the placement budget: " + report);
                assertTrue(blades <= RenderDef.GroundCover.MAX_BLADES_PER_VIEW / 4, "a quarter of the cover's: " + report);
            }
        }
        assertTrue(report.size() >= 7, "the shipped scenes were found: " + report);
    }
}
