package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.render.internal.SceneParts;
import org.jecosys.render.plant.PlantBatches;
import org.jecosys.render.plant.PlantRenderer;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * The core's pass of a multisampled target leaves out whole the plants that have no core where they
 * stand ({@link PlantBatches#coreless}, {@link PlantRenderer#setLeaveOutCoreless}): the meadow's start
 * view at 960x540 and 4 samples is the same picture, bit for bit, whether they are left out whole or
 * vertex by vertex in the shader, and a good share of the triangle levels' plants is left out.
 */
class CorelessListsTest {
    private static final int W = 960;
    private static final int H = 540;

    @Test
    void leavingOutCorelessPlantsWholeDrawsTheSamePicture() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            PlantRenderer plants = SceneParts.plants(s.renderer);
            ViewCamera cam = RenderScenes.camera(def, world, W, H);
            Frame frame = TestFrames.rest(world, cam);
            plants.setLeaveOutCoreless(false);
            Img all = s.render(frame, cam, true, true);
            plants.setLeaveOutCoreless(true);
            Img left = s.render(frame, cam, true, true);
            PlantBatches b = plants.batches();
            long whole = 0;
            long coreless = 0;
            long triangles = 0;
            for (int li = 0; li < b.listCount(); li++) {
                if (!b.lines(li)) {
                    whole += b.whole(li);
                    coreless += b.coreless(li);
                    triangles += (long) b.coreless(li) * b.primitivesPerPlant(li);
                }
            }
            int apart = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    apart += all.at(x, y) != left.at(x, y) ? 1 : 0;
                }
            }
            System.out.printf("[look] core pass: %d of %d whole near plants left out (%.1f%%, %d triangles); "
                    + "%d pixels differ%n", coreless, whole, 100.0 * coreless / whole, triangles, apart);
            assertEquals(0, apart, "pixels that differ when the coreless plants are left out whole");
            assertTrue(coreless >= whole / 5, "a fifth of the whole plants at least are coreless: " + coreless
                    + " of " + whole);
        }
    }
}
