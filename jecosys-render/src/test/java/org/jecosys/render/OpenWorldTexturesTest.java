package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.OpenWorld;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An open world whose grass is textured ({@code <component texture>} in {@code scenes/openworld.xml}, a
 * 12 m radius): {@code Scenes.openWorld(scene, ...)} reads the image from the scene's checked bytes, every
 * tile shares the model's textures, and the open-world renderer draws the tiles with the textured
 * programs and one image array shared by the tiles' renderers: no GL error (debug output on) and a
 * tile's renderer makes as many GL objects as in the same world untextured (no programs or image array
 * of its own).
 */
class OpenWorldTexturesTest {
    private static final int W = 192;
    private static final int H = 108;

    @TempDir
    Path dir;

    @Test
    void theTilesDrawTheScenesImagesFromOneSharedArray() throws Exception {
        String plain = Files.readString(Path.of("scenes", "openworld.xml")).replace("radius=\"64\"", "radius=\"12\"");
        String xml = plain.replace("colour=\"#5fa834\" lodSegments",
                "colour=\"#5fa834\" texture=\"textures/grass-blade.png\" lodSegments");
        assertTrue(xml.contains("texture="), "the grass is textured");
        Files.createDirectories(dir.resolve("textures"));
        Files.copy(Path.of("scenes", "textures", "grass-blade.png"), dir.resolve("textures/grass-blade.png"));
        Files.writeString(dir.resolve("openworld.xml"), xml);
        Files.writeString(dir.resolve("plain.xml"), plain);
        long plainPerTile = perTile(SceneFiles.read(dir.resolve("plain.xml")), 0);
        long texturedPerTile = perTile(SceneFiles.read(dir.resolve("openworld.xml")), 1);
        System.out.printf("[look] open world: %d GL objects per tile renderer textured, %d plain%n", texturedPerTile,
                plainPerTile);
        assertEquals(plainPerTile, texturedPerTile, "a textured tile makes no programs or image array of its own");
    }

    /** GL objects a tile's renderer makes, in an open world of {@code scene} ({@code layers} images). */
    private static long perTile(Scene scene, int layers) throws Exception {
        RenderSettings settings = RenderSettings.of(scene.def().render());
        settings.setClear(true);
        settings.setTerrain(true);
        try (OpenWorld w = Scenes.openWorld(scene, 2, 1);
             GlContext gl = GlContext.headless(DebugOutput.ON);
             GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), W, H);
             OpenWorldRenderer r = new OpenWorldRenderer(gl, w, settings)) {
            assertEquals(layers, w.plants().textures().layers());
            ViewCamera cam = new ViewCamera();
            cam.setOrientation(Math.PI / 2, Math.toRadians(-10));
            cam.setLens(Math.toRadians(60), W / (double) H, 0.1, 500);
            cam.setPosition(0, scene.def().world().relief().height(0, 0) + 1.7, 0);
            w.setThinning(4, 16, 0.15);
            w.load(cam);
            fb.bind();
            r.render(cam, W, H);
            long before = GlContexts.tracker(gl).live();
            int made = r.renderersMade();
            for (int k = 0; k < 64 && r.tileRenderers() < w.liveTiles(); k++) {
                r.render(cam, W, H);
            }
            int more = r.renderersMade() - made;
            long perTile = more == 0 ? 0 : (GlContexts.tracker(gl).live() - before) / more;
            assertTrue(more > 0, "tile renderers were made after the first frame");
            GlContexts.debug(gl).check("an open world with " + layers + " images");
            return perTile;
        }
    }
}
