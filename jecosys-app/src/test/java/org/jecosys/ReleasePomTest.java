package org.jecosys;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;

/**
 * What a release publishes (docs/release.md): the library modules and the BOM, each with a name, a
 * description and the metadata a repository such as Maven Central asks for (url, licence, developers,
 * scm); the library modules with sources and Javadoc jars; the application and the examples not at
 * all. Every module of the reactor is on one of the two lists, so a new module needs a decision.
 */
class ReleasePomTest {
    private static final List<String> LIBRARIES = List.of("jecosys-core", "jecosys-render", "jecosys-gdx", "jecosys-jme");
    private static final Set<String> NOT_PUBLISHED = Set.of("jecosys-app", "examples/game", "examples/gdx", "examples/jme");

    private static Element pom(String dir) throws Exception {
        DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
        f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        Document doc = f.newDocumentBuilder().parse(Path.of(dir, "pom.xml").toFile());
        return doc.getDocumentElement();
    }

    /** The direct child elements of {@code parent} named {@code name}. */
    private static List<Element> children(Element parent, String name) {
        List<Element> out = new ArrayList<>();
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getTagName().equals(name)) {
                out.add(e);
            }
        }
        return out;
    }

    /** The text at a path of direct children, e.g. "scm/url"; "" when absent. */
    private static String text(Element root, String path) {
        Element e = root;
        for (String step : path.split("/")) {
            List<Element> c = children(e, step);
            if (c.isEmpty()) {
                return "";
            }
            e = c.get(0);
        }
        return e.getTextContent().strip();
    }

    /** The build's plugins (not its pluginManagement) by artifactId. */
    private static Element plugin(Element project, String artifactId) {
        for (Element build : children(project, "build")) {
            for (Element plugins : children(build, "plugins")) {
                for (Element p : children(plugins, "plugin")) {
                    if (text(p, "artifactId").equals(artifactId)) {
                        return p;
                    }
                }
            }
        }
        return null;
    }

    private static boolean deploySkipped(Element project) {
        Element deploy = plugin(project, "maven-deploy-plugin");
        return deploy != null && text(deploy, "configuration/skip").equals("true");
    }

    @Test
    void theParentCarriesTheMetadataEveryModuleInherits() throws Exception {
        Element parent = pom(".");
        for (String path : new String[] {"url", "licenses/license/name", "licenses/license/url", "developers/developer/name",
                "scm/connection", "scm/developerConnection", "scm/url"}) {
            assertFalse(text(parent, path).isEmpty(), path + " in the parent pom");
        }
        // a child keeps the project's URLs, instead of getting .../jecosys-core appended to each
        assertEquals("false", parent.getAttribute("child.project.url.inherit.append.path"));
        Element scm = children(parent, "scm").get(0);
        for (String a : new String[] {"connection", "developerConnection", "url"}) {
            assertEquals("false", scm.getAttribute("child.scm." + a + ".inherit.append.path"), "scm " + a);
        }
    }

    @Test
    void theBomRepeatsTheParentsMetadata() throws Exception {
        Element parent = pom(".");
        Element bom = pom("jecosys-bom");
        for (String path : new String[] {"name", "description"}) {
            assertFalse(text(bom, path).isEmpty(), path + " of jecosys-bom");
        }
        for (String path : new String[] {"url", "licenses/license/name", "licenses/license/url", "developers/developer/name",
                "scm/connection", "scm/developerConnection", "scm/url"}) {
            assertEquals(text(parent, path), text(bom, path), path + " of jecosys-bom (it has no parent to inherit from)");
        }
        assertFalse(deploySkipped(bom), "jecosys-bom is published");
    }

    @Test
    void theLibrariesArePublishedWithSourcesAndJavadoc() throws Exception {
        for (String module : LIBRARIES) {
            Element pom = pom(module);
            assertEquals(module, text(pom, "artifactId"));
            assertFalse(text(pom, "name").isEmpty(), "name of " + module);
            assertFalse(text(pom, "description").isEmpty(), "description of " + module);
            assertTrue(plugin(pom, "maven-source-plugin") != null, module + " builds its sources jar");
            assertTrue(plugin(pom, "maven-javadoc-plugin") != null, module + " builds its Javadoc jar");
            assertFalse(deploySkipped(pom), module + " is published");
        }
    }

    @Test
    void everyLibraryHasAStableModuleName() throws Exception {
        for (String module : LIBRARIES) {
            Path descriptor = Path.of(module, "src/main/module/module-info.java");
            Element jar = plugin(pom(module), "maven-jar-plugin");
            String automatic = jar == null ? "" : text(jar, "configuration/archive/manifestEntries/Automatic-Module-Name");
            String expected = "org.jecosys." + module.substring("jecosys-".length());
            if (Files.exists(descriptor)) {
                assertTrue(Files.readString(descriptor).contains("module " + expected + " {"),
                        descriptor + " declares module " + expected);
                assertEquals("", automatic, module + " has a descriptor, so no Automatic-Module-Name");
            } else {
                assertEquals(expected, automatic, module + ": a module descriptor or an Automatic-Module-Name");
            }
        }
    }

    @Test
    void theAppAndTheExamplesAreNotPublished() throws Exception {
        for (String module : NOT_PUBLISHED) {
            assertTrue(deploySkipped(pom(module)), module + " skips deploy");
        }
    }

    @Test
    void everyModuleIsPublishedOrSaysItIsNot() throws Exception {
        Element modules = children(pom("."), "modules").get(0);
        for (Element m : children(modules, "module")) {
            String module = m.getTextContent().strip();
            assertTrue(module.equals("jecosys-bom") || LIBRARIES.contains(module) || NOT_PUBLISHED.contains(module),
                    module + ": add it to the published libraries or to the modules not published");
        }
    }
}
