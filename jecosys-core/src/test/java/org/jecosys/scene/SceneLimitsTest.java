package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/**
 * The loader's limits are located and named: nesting depth and attributes per element at the line
 * where they are exceeded (not 0:0), the problem list says when it stopped, and range problems point
 * at the attribute in the attribute's units.
 */
class SceneLimitsTest {
    private static SceneLoadException refused(String xml) {
        return assertThrows(SceneLoadException.class,
                () -> SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "limits.xml", null));
    }

    @Test
    void nestingTooDeepIsReportedWhereItHappens() {
        StringBuilder sb = new StringBuilder("<scene version=\"1\">\n");
        for (int i = 0; i < 5000; i++) {
            sb.append("<a>\n");
        }
        SceneProblem p = refused(sb.toString()).problems().get(0);
        assertEquals(1001, p.line(), p.toString());
        assertEquals(1, p.column(), p.toString());
        assertTrue(p.message().contains("nested more than 1000 levels deep (the limit)"), p.message());
    }

    @Test
    void tooManyAttributesAreReportedAtTheFirstOneTooMany() {
        StringBuilder sb = new StringBuilder("<scene version=\"1\"\n");
        for (int i = 0; i < 200_000; i++) {
            sb.append("  a").append(i).append("=\"1\"\n");
        }
        sb.append("/>\n");
        SceneProblem p = refused(sb.toString()).problems().get(0);
        assertEquals(1001, p.line(), p.toString());
        assertEquals(3, p.column(), p.toString());
        assertTrue(p.message().contains("more than 1000 attributes on one element (the limit)"), p.message());
    }

    @Test
    void theProblemListSaysWhenItStopped() {
        StringBuilder sb = new StringBuilder("<scene version=\"1\">\n<terrain sizeX=\"1\" sizeZ=\"1\"/>\n");
        for (int i = 0; i < 80; i++) {
            sb.append("<plant species=\"s").append(i).append("\" x=\"0\" z=\"0\"/>\n");
        }
        sb.append("</scene>\n");
        SceneLoadException ex = refused(sb.toString());
        assertEquals(SceneValidator.MAX_PROBLEMS + 1, ex.problems().size());
        SceneProblem last = ex.problems().get(SceneValidator.MAX_PROBLEMS);
        assertTrue(last.message().startsWith("stopped after 50 problems (the limit)"), last.toString());
        assertEquals(53, last.line(), last.toString());
    }

    @Test
    void aRangeProblemPointsAtTheAttributeInItsOwnUnits() {
        String xml = "<scene version=\"1\">\n<terrain sizeX=\"1\" sizeZ=\"1\"/>\n"
                + "<species id=\"s\" maxBend=\"0.05\">\n<lod/>\n"
                + "<component id=\"c\" type=\"leaf\" segments=\"1\" length=\"0.1\" baseWidth=\"0.01\" mass=\"0.1\" "
                + "stiffness=\"1\" lodSegments=\"1\"/>\n</species>\n</scene>\n";
        SceneProblem p = refused(xml).problems().get(0);
        assertEquals(3, p.line(), p.toString());
        assertEquals(17, p.column(), "at maxBend, not at <species>: " + p);
        assertTrue(p.message().contains("expected a finite number in [0.1, 90] degrees"), p.message());
    }
}
