package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.jecosys.math.Progress;
import org.jecosys.plant.PlantTextures;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code <component texture>} (issue 40): a scene names an image per component, read through the scene's
 * image source with the same confinement as heightmaps; the world carries it prepared
 * ({@link PlantTextures}); it is saved back; a missing file, a file that is not an image and an image
 * larger than {@link PlantTextures#MAX_SIDE} are refused at the component's line and column, and the
 * path leading out of the scene's folder too.
 */
class TextureSceneTest {
    @TempDir
    Path dir;

    /** A scene whose one component names {@code texture}, the component element on line 5. */
    private Path scene(String texture) throws Exception {
        Path file = dir.resolve("s/scene.xml");
        Files.createDirectories(file.getParent());
        Files.writeString(file, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<scene version=\"1\">\n"
                + "  <terrain sizeX=\"4\" sizeZ=\"4\" resolution=\"17\"/>\n  <species id=\"grass\">\n"
                + "    <lod/><component id=\"leaf\" type=\"leaf\" segments=\"3\" length=\"0.3\" baseWidth=\"0.01\""
                + " texture=\"" + texture + "\"\n"
                + "        mass=\"0.0004\" stiffness=\"0.2\" lodSegments=\"3\"/>\n  </species>\n"
                + "  <plant species=\"grass\" x=\"0\" z=\"0\"/>\n</scene>\n", StandardCharsets.UTF_8);
        return file;
    }

    private void png(String name, int w, int h) throws Exception {
        Path f = dir.resolve("s").resolve(name).normalize();
        Files.createDirectories(f.getParent());
        ImageIO.write(new BufferedImage(w, h, BufferedImage.TYPE_INT_ARGB), "png", f.toFile());
    }

    @Test
    void aTexturedComponentLoadsBuildsAndSavesBack() throws Exception {
        png("img/blade.png", 16, 64);
        Scene s = SceneFiles.read(scene("img/blade.png"));
        assertEquals("img/blade.png", s.def().species().get(0).components().get(0).texture());
        World w = World.build(s.def().simulationDef(), s.images(), 1, Progress.NONE);
        assertEquals(1, w.plants().textures().layers());
        assertEquals(64, w.plants().textures().side());
        assertTrue(SceneFiles.toXml(s.def()).contains("texture=\"img/blade.png\""), "saved with its texture");
        Path plain = dir.resolve("s/plain.xml");
        Files.writeString(plain, Files.readString(scene("x.png")).replace(" texture=\"x.png\"", ""));
        SceneDef def = SceneFiles.parse(plain);
        assertNull(def.species().get(0).components().get(0).texture());
        assertTrue(!SceneFiles.toXml(def).contains("texture="), "no texture, none written");
    }

    @Test
    void unusableTexturesAreRefusedAtTheComponentsLineAndColumn() throws Exception {
        png("wide.png", PlantTextures.MAX_SIDE + 1, 2);
        png("../outside.png", 4, 4);
        Files.writeString(dir.resolve("s/notes.png"), "not an image");
        String[][] refused = {
            {"missing.png", "missing.png"},
            {"wide.png", "at most " + PlantTextures.MAX_SIDE},
            {"notes.png", "notes.png"},
            {"../outside.png", "outside the scene's folder"},
        };
        for (String[] r : refused) {
            Path file = scene(r[0]);
            SceneLoadException e = assertThrows(SceneLoadException.class, () -> SceneFiles.read(file), r[0]);
            SceneProblem p = e.problems().get(0);
            assertEquals(5, p.line(), r[0] + ": " + p);
            assertTrue(p.column() > 1, r[0] + ": " + p);
            assertTrue(p.message().contains("texture") && p.message().contains(r[1]), r[0] + ": " + p);
        }
    }
}
