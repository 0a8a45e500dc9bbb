package org.jecosys;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * jecosys-bom, which a game imports to align the JEcoSys modules and LWJGL, stands outside the
 * reactor's inheritance (so importing it brings nothing else): it must name the same version, the same
 * LWJGL and the same JOML as the parent pom the library is built and tested with, and manage every
 * published module.
 */
class BomTest {
    private static String value(String pom, String element) {
        Matcher m = Pattern.compile("<" + Pattern.quote(element) + ">([^<]+)</" + Pattern.quote(element) + ">").matcher(pom);
        assertTrue(m.find(), element + " in the pom");
        return m.group(1).strip();
    }

    @Test
    void theBomNamesTheVersionsTheLibraryIsBuiltAndTestedWith() throws Exception {
        String parent = Files.readString(Path.of("pom.xml"));
        String bom = Files.readString(Path.of("jecosys-bom/pom.xml"));
        assertEquals(value(parent, "version"), value(bom, "version"), "project version");
        assertEquals(value(parent, "version"), value(bom, "jecosys.version"), "the managed modules' version");
        assertEquals(value(parent, "lwjgl.version"), value(bom, "lwjgl.version"), "LWJGL");
        assertEquals(value(parent, "joml.version"), value(bom, "joml.version"), "JOML");
        for (String module : new String[] {"jecosys-core", "jecosys-render", "jecosys-gdx", "jecosys-jme"}) {
            assertTrue(bom.contains("<artifactId>" + module + "</artifactId>"), module + " is managed");
            assertTrue(parent.contains("<module>" + module + "</module>"), module + " is built");
        }
        assertTrue(bom.contains("<artifactId>lwjgl-bom</artifactId>") && bom.contains("<scope>import</scope>"),
                "LWJGL's own BOM is imported, so every LWJGL artifact (an engine's too) gets one version");
        assertTrue(!bom.contains("<parent>"), "no parent: importing the BOM brings nothing else");
    }
}
