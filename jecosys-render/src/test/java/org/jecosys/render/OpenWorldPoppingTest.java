package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.file.Path;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.DrawQuality;
import org.jecosys.sim.OpenWorld;
import org.jecosys.sim.SimulationDef;
import org.jecosys.world.TilePlacer;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;

/**
 * Issue 39, "Done when": the popping measure of {@link PoppingTest} along an open world's walk. The
 * camera of {@code scenes/openworld.xml} walks three seconds at 10 m/s (90 frames, 960x540, wind off:
 * plants at rest, thinned at the low quality as on llvmpipe); tiles arrive at the radius (64 m) from
 * 16 m on, their renderers made a few a frame. Checked: the existing measure over the first second
 * (the length of the meadow's walk: the largest frame-to-frame change, the mean absolute difference of
 * the whole picture, at most 1.15x the median one, the meadow's bound) and over the whole walk; and at
 * each frame where tiles arrived, the change over the median of its 6 neighbours
 * ({@link ImageMetrics#localRatios}) at most {@link #ARRIVAL_BOUND}: an arriving tile does not make its
 * frame stand out. Prints every frame's change.
 * Tagged {@code slow} (many frames on llvmpipe): it runs in {@code mvn -B verify -Pnightly}.
 */
@Tag("slow")
class OpenWorldPoppingTest {
    private static final int W = 960;
    private static final int H = 540;
    private static final int FRAMES = 91;
    /** Largest change of a frame where tiles arrived, over its neighbours' median. */
    static final double ARRIVAL_BOUND = 1.03;

    @Test
    void noFrameOfTheOpenWorldsWalkChangesMuchMoreThanTheOthers() throws Exception {
        SceneDef scene = SceneFiles.parse(Path.of("scenes", "openworld.xml"));
        TilePlacer placer = RenderScenes.placer(scene);
        SimulationDef d = scene.simulationDef();
        SimulationDef still = new SimulationDef(d.terrain(), d.species(), d.distributions(), d.placements(), d.flows(),
                d.field().withEnabled(false), d.animation(), d.seed());
        RenderSettings settings = RenderSettings.of(scene.render());
        settings.setClear(true);
        settings.setTerrain(true);
        ByteBuffer px = MemoryUtil.memAlloc(4 * W * H);
        Img[] frames = new Img[FRAMES];
        int[] made = new int[FRAMES];
        try (OpenWorld w = OpenWorld.create(still, placer, scene.world().radius(), 2, 1, 8);
             GlContext gl = GlContext.headless(DebugOutput.ON);
             GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), W, H);
             OpenWorldRenderer r = new OpenWorldRenderer(gl, w, settings)) {
            DrawQuality q = DrawQuality.LOW;
            w.setThinning(q.thinStart(), q.thinEnd(), q.thinMinFraction());
            ViewCamera cam = new ViewCamera();
            cam.setOrientation(scene.camera().yaw(), scene.camera().pitch());
            cam.setLens(scene.camera().fovY(), W / (double) H, scene.camera().near(), scene.camera().far());
            cam.setPosition(0, scene.world().relief().height(0, 0) + 1.7, 0);
            w.load(cam);
            fb.bind();
            for (int k = 0; k < 256 && r.tileRenderers() < w.liveTiles(); k++) {
                r.render(cam, W, H);
            }
            for (int i = 0; i < FRAMES; i++) {
                double x = i * 10.0 / 30;
                cam.setPosition(x, scene.world().relief().height(x, 0) + 1.7, 0);
                w.step(1 / 30.0, cam);
                fb.bind();
                r.render(cam, W, H);
                fb.resolve();
                Screenshot.read(W, H, px);
                frames[i] = Img.of(px, W, H);
                made[i] = (int) r.renderersMade();
            }
            GlContexts.debug(gl).check("the open world's popping test");
            double[] changes = ImageMetrics.frameChanges(frames);
            double[] local = ImageMetrics.localRatios(changes, 3);
            double[] lm = ImageMetrics.largestAndMedian(java.util.Arrays.copyOf(changes, 30));
            double[] all = ImageMetrics.largestAndMedian(changes);
            double ratio = lm[0] / lm[1];
            StringBuilder each = new StringBuilder();
            int arrivals = 0;
            double worstArrival = 0;
            for (int i = 0; i < changes.length; i++) {
                boolean arrived = made[i + 1] > made[i];
                each.append(String.format(" %.2f%s", changes[i], arrived ? "+" + (made[i + 1] - made[i]) : ""));
                if (arrived) {
                    arrivals++;
                    worstArrival = Math.max(worstArrival, local[i]);
                }
            }
            System.out.println("[look] open world walk, each frame's change (+n: tile renderers made):" + each);
            System.out.printf("[look] open world walk: first second: largest frame change %.3f/255, median %.3f/255,"
                    + " ratio %.2f (<= 1.15); three seconds: ratio %.2f; largest change over its neighbours' median"
                    + " %.3f anywhere, %.3f where tiles arrived (%d frames, <= %.2f); %d tiles live, %d tile"
                    + " renderers made%n", lm[0], lm[1], ratio, all[0] / all[1],
                    ImageMetrics.largestAndMedian(local)[0], worstArrival, arrivals, ARRIVAL_BOUND, w.liveTiles(),
                    r.renderersMade());
            assertTrue(lm[1] > 0, "the walk does not move the picture");
            assertTrue(arrivals >= 2, "tiles arrived during the walk: " + arrivals + " frames");
            assertTrue(ratio <= 1.15, String.format("largest frame-to-frame change %.3f is %.2fx the median %.3f,"
                    + " want <= 1.15x", lm[0], ratio, lm[1]));
            assertTrue(worstArrival <= ARRIVAL_BOUND, String.format("a frame where tiles arrived changed %.3fx its"
                    + " neighbours' median, want <= %.2f", worstArrival, ARRIVAL_BOUND));
        } finally {
            MemoryUtil.memFree(px);
        }
    }
}
