package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** XXE, external DTDs and entity expansion are refused before any entity is read or expanded. */
class HostileXmlTest {
    private static final String SECRET = "TOP-SECRET-7f3a";

    @TempDir
    Path tmp;

    private SceneLoadException load(String xml) {
        return assertThrows(SceneLoadException.class,
                () -> SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "hostile.xml", tmp));
    }

    @Test
    void externalEntityIsRejectedAndNothingOfTheFileLeaks() throws Exception {
        Path secret = tmp.resolve("secret.txt");
        Files.writeString(secret, SECRET);
        String xml = "<?xml version=\"1.0\"?>\n<!DOCTYPE scene [<!ENTITY xxe SYSTEM \"" + secret.toUri() + "\">]>\n"
                + "<scene version=\"1\" name=\"&xxe;\"><terrain sizeX=\"1\" sizeZ=\"1\"/></scene>\n";
        SceneLoadException ex = load(xml);
        assertEquals(2, ex.problems().get(0).line());
        assertTrue(ex.getMessage().contains("DOCTYPE is not allowed"), ex.getMessage());
        assertFalse(ex.getMessage().contains(SECRET));
    }

    @Test
    void externalDtdIsNeverFetched() {
        String xml = "<!DOCTYPE scene SYSTEM \"http://127.0.0.1:9/never.dtd\">\n<scene version=\"1\"/>";
        SceneLoadException ex = load(xml);
        assertTrue(ex.getMessage().contains("DOCTYPE is not allowed"), ex.getMessage());
    }

    @Test
    void parameterEntitiesAreRejected() {
        String xml = "<!DOCTYPE scene [<!ENTITY % p SYSTEM \"file:///etc/passwd\"> %p;]>\n<scene version=\"1\"/>";
        SceneLoadException ex = load(xml);
        assertEquals(1, ex.problems().get(0).line());
        assertFalse(ex.getMessage().contains("root:"));
    }

    @Test
    void billionLaughsFailsFastWithoutExpanding() {
        StringBuilder sb = new StringBuilder("<?xml version=\"1.0\"?>\n<!DOCTYPE lolz [\n<!ENTITY lol \"lol\">\n");
        sb.append("<!ENTITY lol1 \"&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;\">\n");
        for (int i = 2; i <= 9; i++) {
            sb.append("<!ENTITY lol").append(i).append(" \"");
            for (int k = 0; k < 10; k++) {
                sb.append("&lol").append(i - 1).append(';');
            }
            sb.append("\">\n");
        }
        sb.append("]>\n<scene version=\"1\" name=\"&lol9;\"><terrain sizeX=\"1\" sizeZ=\"1\"/></scene>\n");
        SceneLoadException ex = load(sb.toString());
        assertTrue(ex.getMessage().contains("DOCTYPE is not allowed"), ex.getMessage());
        assertFalse(ex.getMessage().contains("lollol"));
    }

    @Test
    void undeclaredEntityWithoutDoctypeIsAnError() {
        String xml = "<scene version=\"1\" name=\"&xxe;\"><terrain sizeX=\"1\" sizeZ=\"1\"/></scene>";
        SceneLoadException ex = load(xml);
        assertTrue(ex.getMessage().contains("xxe"), ex.getMessage());
    }

    @Test
    void predefinedEntitiesStillWork() throws Exception {
        String xml = "<scene version=\"1\" name=\"Tom &amp; Jerry &lt;3\"><terrain sizeX=\"1\" sizeZ=\"1\"/>"
                + SceneFilesTest.SPECIES + "</scene>";
        SceneDef d = SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "ok.xml", null);
        assertEquals("Tom & Jerry <3", d.name());
        assertTrue(SceneFiles.toXml(d).contains("name=\"Tom &amp; Jerry &lt;3\""));
    }
}
