package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import org.jecosys.math.Rgb;
import org.junit.jupiter.api.Test;

/**
 * {@code <render><groundCover>} in scene files: read in its units, absent means none (the paper's bare
 * ground), saved and loaded exactly, bad values refused with file, line, column and the range, and the
 * shipped meadow has cover while the paper's scenes have none.
 */
class GroundCoverSceneTest {
    private static final String SCENE = """
            <scene version="1">
              <terrain sizeX="10" sizeZ="10"/>
              <species id="s">
                <lod/>
                <component id="leaf" type="leaf" segments="4" length="0.3" baseWidth="0.01" mass="0.001"
                    stiffness="0.5" lodSegments="4"/>
              </species>
              <distribution species="s"/>
              <render>
                <groundCover amount="0.8" height="0.05" density="1200" reach="6" spread="2.5" colour="#407020"
                    dryColour="#a09050"/>
              </render>
            </scene>
            """;

    private static SceneDef parse(String xml) throws SceneLoadException {
        return SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "cover.xml", null);
    }

    @Test
    void valuesAreReadAndSavedExactly() throws Exception {
        SceneDef d = parse(SCENE);
        assertEquals(new RenderDef.GroundCover(0.8, 0.05, 1200, 6, 2.5, Rgb.parseHex("#407020"),
                Rgb.parseHex("#a09050")), d.render().groundCover());
        String saved = SceneFiles.toXml(d);
        assertTrue(saved.contains("<groundCover "), saved);
        SceneDef back = parse(saved);
        assertEquals(d.render(), back.render());
        assertEquals(saved, SceneFiles.toXml(back));
        RenderDef.GroundCover plain = parse(SCENE.replaceAll("(?s)<groundCover.*?/>", "<groundCover/>"))
                .render().groundCover();
        assertEquals(1, plain.amount(), "an empty element asks for full cover with the documented defaults");
        assertEquals(RenderDef.GroundCover.NONE.height(), plain.height());
    }

    @Test
    void absentMeansBareGroundAndIsNotWritten() throws Exception {
        SceneDef d = parse(SCENE.replaceAll("(?s)<render>.*</render>", ""));
        assertFalse(d.render().groundCover().enabled());
        assertFalse(SceneFiles.toXml(d).contains("groundCover"));
        for (String name : new String[] {"c1.xml", "c2.xml", "c3.xml", "rose.xml"}) {
            assertFalse(SceneFiles.parse(SceneFilesTest.SCENES.resolve(name)).render().groundCover().enabled(), name);
        }
        assertTrue(SceneFiles.parse(SceneFilesTest.SCENES.resolve("meadow.xml")).render().groundCover().enabled());
    }

    @Test
    void badValuesGetTheSchemasMessage() {
        String[][] cases = {
            {"amount=\"0.8\"", "amount=\"1.5\"", "amount"},
            {"height=\"0.05\"", "height=\"0\"", "height"},
            {"density=\"1200\"", "density=\"-1\"", "density"},
            {"reach=\"6\"", "reach=\"51\"", "reach"},
            {"spread=\"2.5\"", "spread=\"NaN\"", "spread"},
            {"colour=\"#407020\"", "colour=\"green\"", "colour"},
        };
        for (String[] c : cases) {
            String xml = SCENE.replace(c[0], c[1]);
            SceneLoadException e = assertThrows(SceneLoadException.class, () -> parse(xml), c[1]);
            String m = e.getMessage();
            assertTrue(m.contains("cover.xml") && m.contains(c[2]) && m.matches("(?s).*:\\d+:\\d+.*"),
                    "file, line, column and attribute: " + m);
        }
    }
}
