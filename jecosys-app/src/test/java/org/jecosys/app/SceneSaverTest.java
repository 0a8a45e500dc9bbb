package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.terrain.ResourceMapDef;
import org.jecosys.terrain.TerrainDef;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Where a save goes and when it asks first: shipped scenes, other files, changes on disk, bad targets. */
class SceneSaverTest {
    @TempDir
    Path dir;

    @Test
    void asksBeforeAShippedSceneAnotherFileOrAFileChangedOnDisk() throws Exception {
        Path shipped = Files.createDirectories(dir.resolve("jecosys/scenes"));
        Path meadow = Files.copy(Path.of("scenes/c1.xml"), shipped.resolve("c1.xml"));
        SceneSaver s = new SceneSaver(meadow, shipped);
        assertTrue(s.isShipped(meadow));
        assertTrue(s.isShipped(shipped.resolve("sub/new.xml")), "anything under scenes/");
        assertFalse(s.isShipped(dir.resolve("mine.xml")));
        assertTrue(s.plan().confirm(), "Save over a shipped scene asks");
        assertTrue(s.plan(shipped.resolve("new.xml")).confirm(), "a new file among the shipped scenes asks too");
        Path mine = dir.resolve("mine.xml");
        assertFalse(s.plan(mine).confirm(), "a new file elsewhere: no question");
        // a symbolic link to the shipped folder is still the shipped folder
        Path link = dir.resolve("link");
        try {
            Files.createSymbolicLink(link, shipped);
            assertTrue(s.isShipped(link.resolve("c1.xml")));
        } catch (UnsupportedOperationException | java.io.IOException e) {
            // no symbolic links on this file system
        }
        Files.copy(Path.of("scenes/c1.xml"), mine);
        SceneSaver own = new SceneSaver(mine, shipped);
        assertFalse(own.plan().confirm(), "Save over the open file, not shipped: no question");
        assertTrue(own.plan(dir.resolve("../" + dir.getFileName() + "/mine.xml")).target().endsWith("mine.xml"));
        Path other = Files.writeString(dir.resolve("other.xml"), "x");
        assertTrue(own.plan(other).confirm(), "Save As over another file asks");
        assertTrue(own.plan(other).question().contains("replaced"), own.plan(other).question());
        Files.setLastModifiedTime(mine, FileTime.fromMillis(Files.getLastModifiedTime(mine).toMillis() + 5000));
        assertTrue(own.plan().confirm(), "the open file changed on disk since it was opened");
        assertTrue(own.plan().question().contains("changed on disk"), own.plan().question());
        SceneDef def = SceneFiles.parse(mine);
        own.write(own.plan(), def);
        assertFalse(own.plan().confirm(), "after our own save, no question");
    }

    @Test
    void refusesTargetsThatCannotBeSceneFilesWithAClearMessage() {
        SceneSaver s = new SceneSaver(dir.resolve("a.xml"), null);
        assertTrue(assertThrows(IllegalArgumentException.class, () -> s.plan(dir)).getMessage().contains("folder"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> s.plan(dir.resolve("none/a.xml"))).getMessage()
                .contains("does not exist"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> s.plan(dir.resolve("a.txt"))).getMessage()
                .contains(".xml"));
        assertFalse(s.isShipped(dir.resolve("a.xml")), "no shipped folder known");
    }

    @Test
    void saveAsToAnotherFolderKeepsRelativePathsPointingAtTheSameFiles() throws Exception {
        SceneDef def = SceneFiles.parse(Path.of("scenes/c1.xml"));
        TerrainDef t = def.terrain();
        ResourceMapDef water = new ResourceMapDef(ResourceMapDef.Source.IMAGE, t.water().resolution(), 1, 1,
                "maps/water.png");
        TerrainDef nt = new TerrainDef(t.sizeX(), t.sizeZ(), t.resolution(), t.heightScale(), t.roughness(), t.seed(),
                "maps/height.png", water, t.nutrients());
        SceneDef withPaths = new SceneDef(def.version(), def.name(), def.seed(), nt, def.species(), def.distributions(),
                def.placements(), def.flows(), def.field(), def.camera(), def.animation(), def.render());
        Path from = dir.resolve("a/scenes");
        Path to = dir.resolve("b");
        SceneDef moved = SceneSaver.relocate(withPaths, from, to);
        assertEquals(from.resolve("maps/height.png").normalize(), to.resolve(moved.terrain().heightmap()).normalize());
        assertEquals("../a/scenes/maps/water.png", moved.terrain().water().image());
        assertEquals(t.nutrients(), moved.terrain().nutrients(), "a generated map has no path");
        assertEquals(withPaths, SceneSaver.relocate(withPaths, from, from));
    }
}
