package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.file.Path;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.render.plant.PlantPrograms;
import org.jecosys.render.plant.PlantRenderer;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.OpenWorld;
import org.jecosys.sim.WorldTile;
import org.jecosys.world.TilePlacer;
import org.junit.jupiter.api.Test;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.system.MemoryUtil;

/**
 * The renderers of worlds that share a plant model and take one {@link PlantPrograms} (an open world's
 * tiles) read the model's pose tables and meshes from it instead of uploading their own: the second
 * tile's renderer makes fewer GL objects than the first, draws its tile exactly as a renderer with its
 * own programs and tables does, still does so after the first is closed, and closing everything
 * releases every object.
 */
class SharedSpeciesTest {
    private static final int W = 160;
    private static final int H = 120;

    @Test
    void tileRenderersShareTheModelsTablesAndMeshesAndDrawTheSame() throws Exception {
        SceneDef scene = SceneFiles.parse(Path.of("scenes", "openworld.xml"));
        TilePlacer placer = RenderScenes.placer(scene);
        ByteBuffer px = MemoryUtil.memAlloc(4 * W * H);
        try (OpenWorld w = OpenWorld.create(scene.simulationDef(), placer, 12, 1, 1, 8);
             GlContext gl = GlContext.headless(DebugOutput.ON);
             GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), W, H)) {
            ViewCamera cam = new ViewCamera();
            cam.setLens(Math.toRadians(60), W / (double) H, 0.1, 200);
            cam.setPosition(0, scene.world().relief().height(0, 0) + 1.7, 0);
            w.stepFixed(cam);
            w.settle();
            WorldTile a = null;
            WorldTile b = null;
            for (int k = 0; k < w.liveTiles(); k++) {
                WorldTile t = w.tile(k);
                if (t.world().plantCount() > 0) {
                    if (a == null) {
                        a = t;
                    } else if (b == null) {
                        b = t;
                    }
                }
            }
            assertTrue(a != null && b != null, "two tiles with plants");
            // looking down at b's middle from 8 m
            double size = 16;
            double cx = (b.i() + 0.5) * size;
            double cz = (b.j() + 0.5) * size;
            cam.setPosition(cx, scene.world().relief().height(cx, cz) + 8, cz + 4);
            cam.setOrientation(0, Math.toRadians(-62));
            fb.bind();
            int base = gl.tracker().live();
            PlantPrograms programs = PlantPrograms.compile(gl, null, w.plants().textures());
            int compiled = gl.tracker().live();
            PlantRenderer ra = new PlantRenderer(gl, a.world(), programs);
            int afterA = gl.tracker().live();
            PlantRenderer rb = new PlantRenderer(gl, b.world(), programs);
            int afterB = gl.tracker().live();
            System.out.printf("[shared] GL objects: the programs %d, the first tile's renderer %d (the model's tables"
                    + " and meshes with it), the second's %d%n", compiled - base, afterA - compiled, afterB - afterA);
            assertTrue(afterB - afterA < afterA - compiled, "the second tile's renderer makes fewer objects: "
                    + (afterB - afterA) + " against " + (afterA - compiled));
            byte[] alone;
            try (PlantRenderer own = new PlantRenderer(gl, b.world())) {
                alone = draw(own, b, cam, px);
            }
            byte[] shared = draw(rb, b, cam, px);
            int plant = 0;
            for (int i = 0; i < alone.length; i += 4) {
                plant += alone[i + 1] != 0 ? 1 : 0;
            }
            assertTrue(plant > W * H / 20, "the tile's plants are in the picture: " + plant + " pixels");
            assertArrayEquals(alone, shared, "the shared tables and meshes draw the tile as its own do");
            ra.close();
            assertArrayEquals(alone, draw(rb, b, cam, px), "the first tile's renderer closed, the second draws on");
            rb.close();
            programs.close();
            GlContexts.debug(gl).check("the shared species test");
            assertEquals(base, gl.tracker().live(), "every GL object released");
        } finally {
            MemoryUtil.memFree(px);
        }
    }

    private static byte[] draw(PlantRenderer r, WorldTile t, ViewCamera cam, ByteBuffer px) {
        GL11C.glViewport(0, 0, W, H);
        GL11C.glClearColor(0, 0, 0, 1);
        GL11C.glClear(GL11C.GL_COLOR_BUFFER_BIT | GL11C.GL_DEPTH_BUFFER_BIT);
        GL11C.glEnable(GL11C.GL_DEPTH_TEST);
        r.draw(t.simulation().latestFrame(), cam, H);
        Pixels.read(W, H, px);
        byte[] out = new byte[W * H * 4];
        px.get(0, out);
        return out;
    }
}
