package org.jecosys.gdx;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.badlogic.gdx.Files.FileType;
import com.badlogic.gdx.backends.lwjgl3.Lwjgl3Files;
import com.badlogic.gdx.files.FileHandle;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneLoadException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Scenes read through libGDX file handles of every desktop file type, their images from the scene's
 * siblings of the same type; image paths that leave the scene's folder are refused. No window: the
 * LWJGL 3 backend's file handles work without an application.
 */
class GdxScenesTest {
    private static final String CLASSPATH = "org/jecosys/gdx/tiny/tiny.xml";
    /** The same file on disk, relative to the reactor's root (the tests' working directory). */
    private static final String ON_DISK = "jecosys-gdx/src/test/resources/" + CLASSPATH;
    private static final Lwjgl3Files FILES = new Lwjgl3Files();

    @TempDir
    Path dir;

    private static void checkTiny(Scene scene, String name) throws IOException {
        assertEquals(name, scene.name(), "problems are reported under the handle's path");
        assertEquals("Tiny", scene.def().name());
        byte[] png = scene.images().read("img/ramp.png");
        assertTrue(png.length > 8 && png[1] == 'P' && png[2] == 'N' && png[3] == 'G', "the sibling image's bytes");
        byte[] blade = scene.images().read("img/blade.png");
        assertTrue(blade.length > 8 && blade[1] == 'P', "the leaf's texture, a sibling image too");
        // the flower's glTF head and its buffer came through the handle's siblings too
        org.jecosys.plant.MeshDef head = scene.def().species().get(1).components().get(1).mesh();
        assertEquals("img/head.gltf", head.path());
        assertEquals(9, head.geometry().vertexCount(), "the head's vertices, read from head.bin");
    }

    @Test
    void classpathInternalLocalAndAbsoluteScenesReadTheirSiblingImages() throws Exception {
        FileHandle classpath = FILES.classpath(CLASSPATH);
        checkTiny(GdxScenes.read(classpath), CLASSPATH);
        // internal: not in the working directory, so found on the classpath
        FileHandle internalCp = FILES.internal(CLASSPATH);
        assertEquals(FileType.Internal, internalCp.type());
        checkTiny(GdxScenes.read(internalCp), CLASSPATH);
        // internal and local: files under the working directory
        checkTiny(GdxScenes.read(FILES.internal(ON_DISK)), ON_DISK);
        checkTiny(GdxScenes.read(FILES.local(ON_DISK)), ON_DISK);
        // absolute: a copy in a folder of its own
        Files.createDirectories(dir.resolve("img"));
        Files.copy(Path.of(ON_DISK), dir.resolve("tiny.xml"));
        Files.copy(Path.of(ON_DISK).resolveSibling("img/ramp.png"), dir.resolve("img/ramp.png"));
        Files.copy(Path.of(ON_DISK).resolveSibling("img/blade.png"), dir.resolve("img/blade.png"));
        Files.copy(Path.of(ON_DISK).resolveSibling("img/head.gltf"), dir.resolve("img/head.gltf"));
        Files.copy(Path.of(ON_DISK).resolveSibling("img/head.bin"), dir.resolve("img/head.bin"));
        String abs = dir.resolve("tiny.xml").toString();
        checkTiny(GdxScenes.read(FILES.absolute(abs)), abs);
    }

    @Test
    void imagePathsAreConfinedToTheScenesFolder() throws Exception {
        assertEquals("img/ramp.png", org.jecosys.terrain.ImageSource.inFolder("img/ramp.png"));
        assertEquals("img/ramp.png", org.jecosys.terrain.ImageSource.inFolder("./img/../img//ramp.png"));
        assertEquals("img/ramp.png", org.jecosys.terrain.ImageSource.inFolder("img\\ramp.png"));
        for (String bad : new String[] {"../ramp.png", "img/../../ramp.png", "/etc/passwd", "C:/x.png", "", ".",
            "img/.."}) {
            assertThrows(IOException.class, () -> org.jecosys.terrain.ImageSource.inFolder(bad), bad);
        }
        // a scene that names an image out of its folder: refused with the scene's location
        Path sub = dir.resolve("scenes");
        Files.createDirectories(sub.resolve("img"));
        Files.copy(Path.of(ON_DISK).resolveSibling("img/ramp.png"), dir.resolve("ramp.png"));
        Files.copy(Path.of(ON_DISK).resolveSibling("img/blade.png"), sub.resolve("img/blade.png"));
        Files.copy(Path.of(ON_DISK).resolveSibling("img/head.gltf"), sub.resolve("img/head.gltf"));
        Files.copy(Path.of(ON_DISK).resolveSibling("img/head.bin"), sub.resolve("img/head.bin"));
        String xml = Files.readString(Path.of(ON_DISK), StandardCharsets.UTF_8).replace("img/ramp.png", "../ramp.png");
        Files.writeString(sub.resolve("out.xml"), xml, StandardCharsets.UTF_8);
        SceneLoadException e = assertThrows(SceneLoadException.class,
                () -> GdxScenes.read(FILES.absolute(sub.resolve("out.xml").toString())));
        assertTrue(e.getMessage().contains("out.xml:") && e.getMessage().contains("leads out of the scene's folder"),
                e.getMessage());
    }

    @Test
    void aMissingImageIsNamedWithTheScenesLocation() throws Exception {
        String xml = Files.readString(Path.of(ON_DISK), StandardCharsets.UTF_8).replace("img/ramp.png", "img/none.png");
        Files.writeString(dir.resolve("missing.xml"), xml, StandardCharsets.UTF_8);
        Files.createDirectories(dir.resolve("img"));
        Files.copy(Path.of(ON_DISK).resolveSibling("img/blade.png"), dir.resolve("img/blade.png"));
        Files.copy(Path.of(ON_DISK).resolveSibling("img/head.gltf"), dir.resolve("img/head.gltf"));
        Files.copy(Path.of(ON_DISK).resolveSibling("img/head.bin"), dir.resolve("img/head.bin"));
        SceneLoadException e = assertThrows(SceneLoadException.class,
                () -> GdxScenes.read(FILES.absolute(dir.resolve("missing.xml").toString())));
        assertTrue(e.getMessage().matches("(?s).*missing\\.xml:\\d+:\\d+:.*img/none\\.png.*"), e.getMessage());
    }
}
