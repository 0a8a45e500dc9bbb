package org.jecosys.jme;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.asset.AssetLoadException;
import com.jme3.asset.AssetManager;
import com.jme3.asset.DesktopAssetManager;
import com.jme3.asset.plugins.FileLocator;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.scene.Scene;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Scenes through jME's asset manager: from the classpath and from a folder a FileLocator serves, with
 * their images located relative to the scene's folder; paths out of it refused; a bad scene names its
 * location; scenes are not cached. No window: jME's asset manager needs none.
 */
class SceneAssetLoaderTest {
    private static final String CLASSPATH = "org/jecosys/jme/tiny/tiny.xml";

    @TempDir
    Path dir;

    private static AssetManager assets() {
        DesktopAssetManager assets = new DesktopAssetManager(true); // jME's desktop defaults: the classpath locator
        assets.registerLoader(SceneAssetLoader.class, SceneAssetLoader.EXTENSION);
        return assets;
    }

    private static void checkTiny(Scene scene, String name) throws IOException {
        assertEquals(name, scene.name());
        assertEquals("Tiny", scene.def().name());
        byte[] png = scene.images().read("img/ramp.png");
        assertTrue(png.length > 8 && png[1] == 'P' && png[2] == 'N' && png[3] == 'G', "the sibling image's bytes");
        // the leaf's texture comes through the asset manager too, and the world built from the scene draws it
        assertEquals("img/blade.png", scene.def().species().get(0).components().get(0).texture());
        org.jecosys.sim.World w = org.jecosys.sim.World.build(scene.def().simulationDef(), scene.images(), 1,
                org.jecosys.math.Progress.NONE);
        assertEquals(1, w.plants().textures().layers());
        assertEquals(128, w.plants().textures().side());
        // the flower's glTF head and its buffer came through the asset manager, and the world draws it
        assertEquals("img/head.gltf", scene.def().species().get(1).components().get(1).mesh().path());
        assertTrue(w.plants().species().get(1).mesh(0).vertexFromFile(w.plants().species().get(1).mesh(0).vertexCount() - 1),
                "the head's triangles at the near level");
    }

    private Path copyTiny(Path folder) throws IOException {
        Path src = Path.of("jecosys-jme/src/test/resources", CLASSPATH);
        Files.createDirectories(folder.resolve("img"));
        Files.copy(src, folder.resolve("tiny.xml"));
        Files.copy(src.resolveSibling("img/ramp.png"), folder.resolve("img/ramp.png"));
        Files.copy(src.resolveSibling("img/blade.png"), folder.resolve("img/blade.png"));
        Files.copy(src.resolveSibling("img/head.gltf"), folder.resolve("img/head.gltf"));
        Files.copy(src.resolveSibling("img/head.bin"), folder.resolve("img/head.bin"));
        return folder.resolve("tiny.xml");
    }

    @Test
    void classpathAndFolderScenesReadTheirSiblingImagesAndAreNotCached() throws Exception {
        AssetManager assets = assets();
        Scene a = assets.loadAsset(new SceneKey(CLASSPATH));
        checkTiny(a, CLASSPATH);
        assertNotSame(a, assets.loadAsset(new SceneKey(CLASSPATH)), "loaded again, not cached");
        copyTiny(dir.resolve("Scenes/meadows"));
        assets.registerLocator(dir.toString(), FileLocator.class);
        checkTiny(assets.loadAsset(new SceneKey("Scenes/meadows/tiny.xml")), "Scenes/meadows/tiny.xml");
    }

    @Test
    void imagePathsOutOfTheScenesFolderAndBadScenesAreRefusedWithTheirLocation() throws Exception {
        assertEquals("img/ramp.png", org.jecosys.terrain.ImageSource.inFolder("./img/../img//ramp.png"));
        for (String bad : new String[] {"../ramp.png", "img/../../ramp.png", "/etc/passwd", "C:\\x.png", ""}) {
            assertThrows(IOException.class, () -> org.jecosys.terrain.ImageSource.inFolder(bad), bad);
        }
        Path tiny = copyTiny(dir.resolve("Scenes"));
        Files.copy(tiny.resolveSibling("img/ramp.png"), dir.resolve("ramp.png"));
        String xml = Files.readString(tiny, StandardCharsets.UTF_8);
        Files.writeString(dir.resolve("Scenes/out.xml"), xml.replace("img/ramp.png", "../ramp.png"));
        Files.writeString(dir.resolve("Scenes/missing.xml"), xml.replace("img/ramp.png", "img/none.png"));
        Files.writeString(dir.resolve("Scenes/bad.xml"), xml.replace("sizeX=\"8\"", "sizeX=\"-8\""));
        AssetManager assets = assets();
        assets.registerLocator(dir.toString(), FileLocator.class);
        AssetLoadException out = assertThrows(AssetLoadException.class,
                () -> assets.loadAsset(new SceneKey("Scenes/out.xml")));
        assertTrue(out.getMessage().matches("(?s)Scenes/out\\.xml:\\d+:\\d+:.*leads out of the scene's folder.*"),
                out.getMessage());
        AssetLoadException missing = assertThrows(AssetLoadException.class,
                () -> assets.loadAsset(new SceneKey("Scenes/missing.xml")));
        assertTrue(missing.getMessage().matches("(?s)Scenes/missing\\.xml:\\d+:\\d+:.*Scenes/img/none\\.png.*"),
                missing.getMessage());
        AssetLoadException bad = assertThrows(AssetLoadException.class,
                () -> assets.loadAsset(new SceneKey("Scenes/bad.xml")));
        assertTrue(bad.getMessage().matches("(?s)Scenes/bad\\.xml:5:\\d+:.*sizeX.*"), bad.getMessage());
    }

    /** A game's own loader for {@code .xml} assets, standing for its materials or UI files. */
    public static final class GameXmlLoader implements com.jme3.asset.AssetLoader {
        @Override
        public Object load(com.jme3.asset.AssetInfo info) throws IOException {
            try (java.io.InputStream in = info.openStream()) {
                return "game:" + new String(in.readAllBytes(), StandardCharsets.UTF_8).strip();
            }
        }
    }

    @Test
    void theSceneLoaderTakesSceneKeysAndJecosysXmlFilesButNoOtherXmlAsset() throws Exception {
        copyTiny(dir.resolve("Scenes"));
        Files.copy(dir.resolve("Scenes/tiny.xml"), dir.resolve("Scenes/tiny.jecosys.xml"));
        Files.writeString(dir.resolve("Scenes/menu.xml"), "<menu/>");
        DesktopAssetManager assets = new DesktopAssetManager(true);
        assets.registerLoader(GameXmlLoader.class, "xml");
        assets.registerLoader(SceneAssetLoader.class, SceneAssetLoader.EXTENSION);
        assets.registerLocator(dir.toString(), FileLocator.class);
        assertEquals("game:<menu/>", assets.loadAsset(new com.jme3.asset.AssetKey<>("Scenes/menu.xml")),
                "the game's own .xml loader still loads its .xml assets");
        checkTiny(assets.loadAsset(new SceneKey("Scenes/tiny.xml")), "Scenes/tiny.xml");
        Object byName = assets.loadAsset(new com.jme3.asset.AssetKey<>("Scenes/tiny.jecosys.xml"));
        assertTrue(byName instanceof Scene, "a NAME.jecosys.xml file reaches the scene loader: " + byName);
        assertEquals(SceneAssetLoader.EXTENSION, new SceneKey("a/b.XML").getExtension());
    }
}
