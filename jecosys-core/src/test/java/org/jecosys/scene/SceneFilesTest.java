package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import javax.xml.XMLConstants;
import javax.xml.transform.stream.StreamSource;
import javax.xml.validation.Schema;
import javax.xml.validation.SchemaFactory;
import javax.xml.validation.Validator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** Every shipped scene validates against the XSD, loads, and round-trips; the XSD matches the loader. */
class SceneFilesTest {
    static final Path SCENES = Path.of("scenes");
    static final Path XSD = SCENES.resolve("jecosys-scene.xsd");
    /** The smallest species a scene can run with (a scene needs at least one). */
    static final String SPECIES = "<species id=\"g\"><lod/><component id=\"l\" type=\"leaf\" segments=\"4\" length=\"0.2\" baseWidth=\"0.005\" mass=\"0.001\" stiffness=\"0.5\" dragArea=\"0.001\" lodSegments=\"4\"/></species>";

    static Stream<Path> sceneFiles() throws Exception {
        try (Stream<Path> s = Files.list(SCENES)) {
            List<Path> files = s.filter(p -> p.toString().endsWith(".xml")).sorted().toList();
            assertFalse(files.isEmpty(), "scenes/ holds scene files");
            return files.stream();
        }
    }

    static Schema schema() throws Exception {
        SchemaFactory f = SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI);
        f.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
        f.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
        return f.newSchema(XSD.toFile());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("sceneFiles")
    void validatesAgainstTheXsd(Path file) throws Exception {
        Validator v = schema().newValidator();
        v.validate(new StreamSource(file.toFile()));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("sceneFiles")
    void loadsAndRoundTrips(Path file) throws Exception {
        SceneDef a = SceneFiles.parse(file);
        String x1 = SceneFiles.toXml(a);
        SceneDef b = SceneFiles.parse(x1.getBytes(StandardCharsets.UTF_8), "saved", file.getParent());
        assertEquals(a, b, "load, save, load gives equal Defs");
        assertEquals(x1, SceneFiles.toXml(b), "save(load(save(x))) is byte-identical");
        schema().newValidator().validate(new StreamSource(new java.io.StringReader(x1)));
    }

    @Test
    void committedXsdIsTheGeneratedOne() throws Exception {
        assertEquals(SchemaXsd.generate(), Files.readString(XSD, StandardCharsets.UTF_8),
                "scenes/jecosys-scene.xsd is stale: run java -cp jecosys-core/target/classes org.jecosys.scene.SchemaXsd "
                        + "scenes/jecosys-scene.xsd");
    }

    @Test
    void xsdIsShippedInTheJar() throws Exception {
        try (InputStream in = SceneFiles.class.getResourceAsStream("jecosys-scene.xsd")) {
            assertNotNull(in, "org/jecosys/scene/jecosys-scene.xsd on the classpath");
            assertEquals(Files.readString(XSD, StandardCharsets.UTF_8), new String(in.readAllBytes(),
                    StandardCharsets.UTF_8));
        }
    }

    @Test
    void xsdDocumentsEveryAttributeWithItsUnitsAndRange() throws Exception {
        String xsd = Files.readString(XSD, StandardCharsets.UTF_8);
        assertTrue(xsd.contains("Spring constant PC of equation 4. Units: N/m. Allowed: a finite number in "
                + "[0.000000001, 1000000] N/m."));
        assertTrue(xsd.contains("<xs:element name=\"vortex\">"));
        checkDocumented(SceneSchema.ROOT, xsd);
    }

    private static void checkDocumented(ElementSpec e, String xsd) {
        assertTrue(xsd.contains("<xs:element name=\"" + e.name + "\""), e.name);
        for (AttrSpec a : e.attrs) {
            assertFalse(a.doc.isBlank(), e.name + "/" + a.name + " has documentation");
            assertTrue(xsd.contains("<xs:attribute name=\"" + a.name + "\""), a.name);
        }
        for (ElementSpec.Child c : e.children) {
            checkDocumented(c.spec, xsd);
        }
    }

    @Test
    void xsdRejectsWhatTheLoaderRejects() throws Exception {
        Validator v = schema().newValidator();
        String nan = "<scene version=\"1\"><terrain sizeX=\"NaN\" sizeZ=\"1\"/></scene>";
        org.junit.jupiter.api.Assertions.assertThrows(org.xml.sax.SAXException.class,
                () -> v.validate(new StreamSource(new java.io.StringReader(nan))));
        String order = "<scene version=\"1\"><field/><terrain sizeX=\"1\" sizeZ=\"1\"/></scene>";
        org.junit.jupiter.api.Assertions.assertThrows(org.xml.sax.SAXException.class,
                () -> v.validate(new StreamSource(new java.io.StringReader(order))));
    }

    @Test
    void anglesAreDegreesInFilesAndRadiansInDefs() throws Exception {
        String xml = "<scene version=\"1\"><terrain sizeX=\"1\" sizeZ=\"1\"/>" + SPECIES + "<camera pitch=\"-10\" fovY=\"45\"/>"
                + "</scene>";
        SceneDef d = SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "a.xml", null);
        assertEquals(Math.toRadians(-10), d.camera().pitch());
        assertEquals(Math.toRadians(45), d.camera().fovY());
        assertTrue(SceneFiles.toXml(d).contains("pitch=\"-10\" fovY=\"45\""));
    }

    @Test
    void defaultsFillWhatTheFileLeavesOut() throws Exception {
        String xml = "<scene version=\"1\"><terrain sizeX=\"10\" sizeZ=\"20\"/>" + SPECIES + "</scene>";
        SceneDef d = SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "d.xml", null);
        assertEquals(org.jecosys.field.ForceFieldDef.defaults(), d.field());
        assertEquals(org.jecosys.anim.AnimationDef.defaults(), d.animation());
        assertEquals(RenderDef.defaults(), d.render());
        assertEquals(org.jecosys.math.CameraDef.defaults(), d.camera());
        assertEquals(65, d.terrain().resolution());
        String xml2 = SceneFiles.toXml(d);
        assertTrue(xml2.startsWith("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<scene xmlns:xsi=\"http://www.w3.org/2001/"
                + "XMLSchema-instance\" xsi:noNamespaceSchemaLocation=\"jecosys-scene.xsd\"\n    version=\"1\">\n"
                + "  <terrain sizeX=\"10\" sizeZ=\"20\"/>\n  <species "), xml2);
        for (String left : new String[] {"<field", "<camera", "<animation", "<render", "<wind"}) {
            assertFalse(xml2.contains(left), "defaults are not written: " + left + "\n" + xml2);
        }
    }

    @Test
    void aVortexMayTurnClockwiseButASourceCannotBeNegative() throws Exception {
        String ok = "<scene version=\"1\"><terrain sizeX=\"1\" sizeZ=\"1\"/>" + SPECIES + "<wind><vortex id=\"v\" strength=\"-4\"/>"
                + "</wind></scene>";
        SceneDef d = SceneFiles.parse(ok.getBytes(StandardCharsets.UTF_8), "v.xml", null);
        assertEquals(-4, d.flows().get(0).strength());
        String bad = ok.replace("vortex", "source");
        SceneLoadException ex = org.junit.jupiter.api.Assertions.assertThrows(SceneLoadException.class,
                () -> SceneFiles.parse(bad.getBytes(StandardCharsets.UTF_8), "s.xml", null));
        assertTrue(ex.getMessage().contains("-4 is out of range; expected a finite number in [0, 1000000] m^2/s"),
                ex.getMessage());
    }
}
