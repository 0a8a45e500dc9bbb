package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.OpenWorld;
import org.junit.jupiter.api.Test;

/**
 * The open world in a scene file ({@code <world>}): the shipped {@code scenes/openworld.xml} is checked,
 * streams along its camera path and is written back as read; what cannot stream is refused at its
 * line and column (a count, a hand-placed plant, a water limit, tiles too small for the footprints,
 * a radius over 64 tiles).
 */
class OpenWorldSceneTest {
    private static final String HEAD = "<scene version=\"1\" seed=\"3\">\n<terrain sizeX=\"20\" sizeZ=\"20\"/>\n";
    private static final String SPECIES = SceneFilesTest.SPECIES + "\n";

    private static SceneLoadException refused(String xml) {
        return assertThrows(SceneLoadException.class,
                () -> SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "w.xml", null));
    }

    @Test
    void theShippedOpenWorldStreamsAlongItsPath() throws Exception {
        SceneDef scene = SceneFiles.parse(Path.of("scenes", "openworld.xml"));
        assertTrue(scene.isOpenWorld());
        assertEquals(16, scene.world().tileSize());
        assertEquals(64, scene.world().radius());
        try (OpenWorld w = Scenes.openWorld(scene, 2, 1)) {
            ViewCamera c = new ViewCamera();
            c.setOrientation(scene.camera().yaw(), scene.camera().pitch());
            c.setLens(scene.camera().fovY(), 16.0 / 9, scene.camera().near(), scene.camera().far());
            for (int s = 0; s < 20; s++) {
                c.setPosition(s * 0.3, scene.world().relief().height(s * 0.3, 0) + 1.7, 0);
                w.stepFixed(c);
            }
            w.settle();
            w.stepFixed(c);
            assertTrue(w.liveTiles() >= 40, "tiles within 64 m: " + w.liveTiles());
            double perSquareMetre = w.livePlants() / (w.liveTiles() * 256.0);
            assertTrue(perSquareMetre > 4.5 && perSquareMetre < 7, "the meadow's density: " + perSquareMetre);
            assertTrue(w.animatedComponents() > 0);
        }
        assertThrows(IllegalArgumentException.class,
                () -> Scenes.openWorld(SceneFiles.parse(Path.of("scenes", "meadow.xml")), 1, 1));
    }

    @Test
    void anOpenWorldIsWrittenBackAsRead() throws Exception {
        SceneDef scene = SceneFiles.parse(Path.of("scenes", "openworld.xml"));
        String xml = SceneWriter.toXml(scene);
        assertTrue(xml.contains("<world "), xml);
        SceneDef again = SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "again.xml", null);
        assertEquals(scene, again);
        assertFalse(SceneFiles.parse(Path.of("scenes", "meadow.xml")).isOpenWorld());
    }

    @Test
    void whatCannotStreamIsRefusedWhereItIsWritten() {
        String world = "<world/>\n";
        String ok = "<distribution species=\"g\" count=\"-1\" density=\"2\"/>\n";
        SceneLoadException e = refused(HEAD + world + SPECIES + "<distribution species=\"g\" count=\"100\"/>\n</scene>");
        assertTrue(e.getMessage().contains("w.xml:5:") && e.getMessage().contains("grows plants by density"),
                e.getMessage());
        e = refused(HEAD + world + SPECIES + ok + "<plant species=\"g\" x=\"1\" z=\"1\"/>\n</scene>");
        assertTrue(e.getMessage().contains("w.xml:6:") && e.getMessage().contains("places no plants by hand"),
                e.getMessage());
        e = refused(HEAD + world + SPECIES + "<distribution species=\"g\" count=\"-1\" minWater=\"0.3\"/>\n</scene>");
        assertTrue(e.getMessage().contains("w.xml:5:") && e.getMessage().contains("'minWater'"), e.getMessage());
        e = refused(HEAD + "<world tileSize=\"4\"/>\n" + SPECIES
                + "<distribution species=\"g\" count=\"-1\" density=\"0.1\" footprint=\"3\"/>\n</scene>");
        assertTrue(e.getMessage().contains("w.xml:3:") && e.getMessage().contains("<world>"), e.getMessage());
        e = refused(HEAD + "<world tileSize=\"4\" radius=\"300\"/>\n" + SPECIES + ok + "</scene>");
        assertTrue(e.getMessage().contains("w.xml:3:") && e.getMessage().contains("more than 64 tiles"),
                e.getMessage());
        e = refused(HEAD + world + SPECIES + "</scene>");
        assertTrue(e.getMessage().contains("at least one <distribution>"), e.getMessage());
    }
}
