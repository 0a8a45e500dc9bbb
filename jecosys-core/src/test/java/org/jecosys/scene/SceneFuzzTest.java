package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;

/**
 * Fuzzes the loader: for any bytes the only allowed outcomes are a valid scene (which then
 * round-trips through save) or the loader's own {@link SceneLoadException} with located problems.
 * Any other exception fails the test. Under plain {@code mvn -B verify} it replays the committed
 * corpus in {@code SceneFuzzTestInputs/loaderNeverFailsOtherwise}; {@code JAZZER_FUZZ=1} fuzzes.
 */
class SceneFuzzTest {
    @FuzzTest(maxDuration = "60s")
    void loaderNeverFailsOtherwise(byte[] input) throws Exception {
        SceneDef scene;
        try {
            scene = SceneFiles.parse(input, "fuzz.xml", null);
        } catch (SceneLoadException e) {
            assertFalse(e.problems().isEmpty());
            for (SceneProblem p : e.problems()) {
                assertEquals("fuzz.xml", p.file());
                assertFalse(p.message().isBlank());
            }
            return;
        }
        String xml = SceneFiles.toXml(scene);
        assertEquals(scene, SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "again.xml", null));
    }
}
