package org.jecosys.gdx;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.badlogic.gdx.assets.loaders.FileHandleResolver;
import com.badlogic.gdx.backends.lwjgl3.Lwjgl3Files;
import com.badlogic.gdx.files.FileHandle;
import com.badlogic.gdx.utils.GdxRuntimeException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.Simulation;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The asset loader's GL-free half, as libGDX's AssetManager calls it: loadAsync reads the scene and
 * builds the simulation (on the loader thread in a game; here on the test's), a load unloaded before
 * loadSync closes what was built, and a bad scene fails with its location. loadSync (GL) runs in the
 * example's test.
 */
class PlantLayerLoaderTest {
    private static final String NAME = "org/jecosys/gdx/tiny/tiny.xml";
    /** Classpath files, as ClasspathFileHandleResolver resolves them in a running application. */
    private static final FileHandleResolver CLASSPATH = new Lwjgl3Files()::classpath;

    @TempDir
    Path dir;

    @Test
    void loadAsyncBuildsTheSimulationAndUnloadingBeforeLoadSyncClosesIt() {
        PlantLayerLoader loader = new PlantLayerLoader(CLASSPATH);
        FileHandle file = loader.resolve(NAME);
        PlantLayerLoader.Parameters p = new PlantLayerLoader.Parameters();
        p.workers = 2;
        loader.loadAsync(null, NAME, file, p);
        Simulation sim = loader.pending(NAME);
        assertNotNull(sim, "built by loadAsync");
        assertEquals(2, sim.inspect().workers());
        assertTrue(sim.plantCount() > 0);
        assertEquals(1, sim.world().plants().textures().layers(), "the leaf's texture, read through the resolver");
        assertEquals("img/blade.png", sim.world().plants().textures().path(0));
        org.jecosys.plant.LodMesh flower = sim.world().plants().species().get(1).mesh(0);
        assertTrue(flower.vertexFromFile(flower.vertexCount() - 1), "the flower's glTF head, read through the resolver");
        loader.unloadAsync(null, NAME, file, p);
        assertNull(loader.pending(NAME));
        IllegalStateException closed = assertThrows(IllegalStateException.class,
                () -> sim.step(0.1, new ViewCamera()));
        assertEquals("the simulation is closed", closed.getMessage());
        GdxRuntimeException e = assertThrows(GdxRuntimeException.class, () -> loader.loadSync(null, NAME, file, p));
        assertTrue(e.getMessage().contains("not built"), e.getMessage());
    }

    @Test
    void aBadSceneFailsWithItsLocation() throws Exception {
        Path bad = dir.resolve("bad.xml");
        Files.writeString(bad, "<?xml version=\"1.0\"?>\n<scene version=\"1\">\n  <terrain sizeX=\"-3\"/>\n</scene>\n",
                StandardCharsets.UTF_8);
        PlantLayerLoader loader = new PlantLayerLoader(CLASSPATH);
        FileHandle file = new Lwjgl3Files().absolute(bad.toString());
        GdxRuntimeException e = assertThrows(GdxRuntimeException.class,
                () -> loader.loadAsync(null, bad.toString(), file, null));
        assertTrue(e.getMessage().contains("bad.xml:3:"), e.getMessage());
        assertNull(loader.pending(bad.toString()));
    }
}
