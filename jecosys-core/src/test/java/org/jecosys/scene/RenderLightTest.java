package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.math.Rgb;
import org.jecosys.plant.VariationDef;
import org.junit.jupiter.api.Test;

/**
 * The render light, colour patches and per-species colour variation in scene files: absent means the
 * documented defaults, every value survives a save and load, out-of-range values get the schema's
 * message with file, line and column, and the shipped scenes save exactly as before (no new element
 * appears when nothing was set).
 */
class RenderLightTest {
    private static final String SCENE = """
            <scene version="1">
              <terrain sizeX="10" sizeZ="10"/>
              <species id="s">
                <lod/>
                <variation variants="2" hue="6.5" value="0.12" dryTips="0.4"/>
                <component id="leaf" type="leaf" segments="4" length="0.3" baseWidth="0.01" mass="0.001"
                    stiffness="0.5" lodSegments="4"/>
              </species>
              <distribution species="s"/>
              <render sky="#a0c0e0" antialiasing="8">
                <light sunAzimuth="-30" sunElevation="12.5" sunColour="#ffd090" sunIntensity="1.5"
                    skyZenith="#2050c0" ambient="#606870" contactShadow="0.7" fogStart="5" fogEnd="90"/>
                <patches scale="20" strength="0.6" seed="-7"/>
              </render>
            </scene>
            """;

    private static SceneDef parse(String xml) throws SceneLoadException {
        return SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "light.xml", null);
    }

    @Test
    void valuesAreReadInTheirUnits() throws Exception {
        SceneDef d = parse(SCENE);
        RenderDef.Light l = d.render().light();
        assertEquals(Math.toRadians(-30), l.sunAzimuth(), 1e-12, "angles are radians in the Def");
        assertEquals(Math.toRadians(12.5), l.sunElevation(), 1e-12);
        assertEquals(Rgb.parseHex("#ffd090"), l.sunColour());
        assertEquals(1.5, l.sunIntensity());
        assertEquals(Rgb.parseHex("#2050c0"), l.skyZenith());
        assertEquals(Rgb.parseHex("#606870"), l.ambient());
        assertEquals(0.7, l.contactShadow());
        assertEquals(5, l.fogStart());
        assertEquals(90, l.fogEnd());
        assertEquals(new RenderDef.Patches(20, 0.6, -7), d.render().patches());
        VariationDef v = d.species().get(0).variation();
        assertEquals(6.5, v.hue(), "hue s.d. stays in degrees");
        assertEquals(0.12, v.value());
        assertEquals(0.4, v.dryTips());
        assertEquals(Rgb.parseHex("#a0c0e0"), d.render().sky(), "sky stays the horizon colour");
        assertEquals(8, d.render().antialiasing());
        assertEquals(4, parse(SCENE.replace(" antialiasing=\"8\"", "")).render().antialiasing(),
                "4 samples per pixel unless the scene says otherwise");
    }

    @Test
    void roundTripThroughTheSceneFileIsExact() throws Exception {
        SceneDef d = parse(SCENE);
        String saved = SceneFiles.toXml(d);
        SceneDef back = parse(saved);
        assertEquals(d.render(), back.render());
        assertEquals(d.species(), back.species());
        assertEquals(saved, SceneFiles.toXml(back), "save(load(save(x))) is byte-identical");
        assertTrue(saved.contains("<light ") && saved.contains("<patches ") && saved.contains("dryTips=\"0.4\""),
                saved);
    }

    @Test
    void absentMeansTheDefaultsAndDefaultsAreNotWritten() throws Exception {
        SceneDef d = parse(SCENE.replaceAll("(?s)<render.*</render>", "").replace(" hue=\"6.5\" value=\"0.12\""
                + " dryTips=\"0.4\"", ""));
        assertEquals(RenderDef.defaults(), d.render());
        assertEquals(RenderDef.Light.DEFAULT, d.render().light());
        assertEquals(RenderDef.Patches.DEFAULT, d.render().patches());
        VariationDef v = d.species().get(0).variation();
        assertEquals(0, v.hue());
        assertEquals(0, v.value());
        assertEquals(0, v.dryTips());
        String saved = SceneFiles.toXml(d);
        assertFalse(saved.contains("<light") || saved.contains("<patches") || saved.contains("hue="), saved);
        // the documented defaults: sun high, behind and to the left of a camera looking along -Z
        RenderDef.Light l = RenderDef.Light.DEFAULT;
        double x = Math.cos(l.sunElevation()) * Math.cos(l.sunAzimuth());
        double z = Math.cos(l.sunElevation()) * Math.sin(l.sunAzimuth());
        assertTrue(x < 0 && z > 0 && Math.sin(l.sunElevation()) > 0.6, "behind-left and high: " + x + ", " + z);
        assertTrue(l.fogEnd() > l.fogStart());
    }

    @Test
    void shippedScenesSaveAsBefore() throws Exception {
        for (String name : new String[] {"c1.xml", "c2.xml", "c3.xml", "rose.xml", "meadow.xml"}) {
            Path file = SceneFilesTest.SCENES.resolve(name);
            SceneDef d = SceneFiles.parse(file);
            String saved = SceneFiles.toXml(d);
            if (!Files.readString(file).contains("<light")) {
                assertFalse(saved.contains("<light") || saved.contains("<patches"), name);
                assertEquals(RenderDef.Light.DEFAULT, d.render().light(), name);
            }
        }
    }

    @Test
    void badValuesGetTheSchemasMessage() {
        String[][] cases = {
            {"sunElevation=\"12.5\"", "sunElevation=\"95\"", "sunElevation"},
            {"sunAzimuth=\"-30\"", "sunAzimuth=\"400\"", "sunAzimuth"},
            {"contactShadow=\"0.7\"", "contactShadow=\"1.5\"", "contactShadow"},
            {"sunIntensity=\"1.5\"", "sunIntensity=\"-1\"", "sunIntensity"},
            {"sunColour=\"#ffd090\"", "sunColour=\"orange\"", "sunColour"},
            {"strength=\"0.6\"", "strength=\"2\"", "strength"},
            {"scale=\"20\"", "scale=\"0\"", "scale"},
            {"hue=\"6.5\"", "hue=\"90\"", "hue"},
            {"dryTips=\"0.4\"", "dryTips=\"-0.1\"", "dryTips"},
            {"antialiasing=\"8\"", "antialiasing=\"3\"", "antialiasing"},
        };
        for (String[] c : cases) {
            String xml = SCENE.replace(c[0], c[1]);
            assertNotEquals(SCENE, xml, c[0]);
            SceneLoadException e = assertThrows(SceneLoadException.class, () -> parse(xml), c[1]);
            String m = e.getMessage();
            assertTrue(m.contains("light.xml") && m.contains(c[2]) && m.matches("(?s).*:\\d+:\\d+.*"),
                    "file, line, column and attribute: " + m);
        }
        String crossed = SCENE.replace("fogEnd=\"90\"", "fogEnd=\"4\"");
        SceneLoadException e = assertThrows(SceneLoadException.class, () -> parse(crossed));
        assertTrue(e.getMessage().contains("fogEnd must be > fogStart"), e.getMessage());
    }

    @Test
    void defsCheckTheirRanges() {
        assertThrows(IllegalArgumentException.class, () -> new RenderDef.Light(0, Math.toRadians(91),
                new Rgb(1, 1, 1), 1, new Rgb(0, 0, 1), new Rgb(0.5f, 0.5f, 0.5f), 0.5, 1, 2, 1, 0));
        assertThrows(IllegalArgumentException.class, () -> new RenderDef.Patches(10, 1.01, 0));
        assertThrows(IllegalArgumentException.class, () -> VariationDef.NONE.withColour(61, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> VariationDef.NONE.withColour(0, 0.6, 0));
        VariationDef v = VariationDef.builder().variants(3).length(0.1).width(0.1).curvature(0.1).tilt(0.1)
                .responseTime(0.2).stiffness(0.2).build().withColour(5, 0.1, 1);
        assertEquals(VariationDef.builder().variants(3).length(0.1).width(0.1).curvature(0.1).tilt(0.1)
                .responseTime(0.2).stiffness(0.2).hue(5).value(0.1).dryTips(1).build(), v);
    }
}
