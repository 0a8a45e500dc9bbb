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
 * Issue 39, "Done when": the popping measure of {@link PoppingTest} along an open world's walk, no worse
 * than along the meadow's walk. The measure (over one second, the largest frame-to-frame change, the
 * mean absolute difference of the whole picture, over the median one) grows with the walking speed
 * whatever the scene: near plants stream past faster, and how much a frame changes follows how many of
 * them, and which (flowers against grass), are near the eye. The meadow's own walk reads about 1.04 at
 * its 1.4 m/s and 1.14 at 10 m/s. So the two walks are compared at equal speed: the streaming walk's
 * 10 m/s and the meadow's 1.4 m/s, one second each (the meadow's walk walked faster where needed).
 * <p>
 * The open world: the camera of {@code scenes/openworld.xml} walks east (960x540, wind off: plants at
 * rest, thinned at the low quality as on llvmpipe); tiles arrive at the radius (64 m) from 16 m on,
 * their renderers made a few a frame. At 10 m/s it walks three seconds, so that tiles arrive: at each
 * frame where they did, the change over the median of its 6 neighbours
 * ({@link ImageMetrics#localRatios}) is at most {@link #ARRIVAL_BOUND}: an arriving tile does not make
 * its frame stand out. Prints every frame's change.
 * Tagged {@code slow} (many frames on llvmpipe): it runs in {@code mvn -B verify -Pnightly}.
 */
@Tag("slow")
class OpenWorldPoppingTest {
    private static final int W = 960;
    private static final int H = 540;
    /** The streaming walk's speed, m/s ({@code scenes/openworld.xml}'s path). */
    private static final double STREAMING_SPEED = 10;
    /** Largest change of a frame where tiles arrived, over its neighbours' median. */
    static final double ARRIVAL_BOUND = 1.03;

    @Test
    void atTheStreamingWalksSpeedNoFrameChangesMoreThanAlongTheMeadowsWalk() throws Exception {
        Walk ow = walk(STREAMING_SPEED, 91);
        double ratio = ow.firstSecondRatio();
        double meadow = ratio(PoppingTest.meadowWalk(STREAMING_SPEED));
        double[] local = ImageMetrics.localRatios(ow.changes, 3);
        StringBuilder each = new StringBuilder();
        int arrivals = 0;
        double worstArrival = 0;
        for (int i = 0; i < ow.changes.length; i++) {
            boolean arrived = ow.made[i + 1] > ow.made[i];
            each.append(String.format(" %.2f%s", ow.changes[i], arrived ? "+" + (ow.made[i + 1] - ow.made[i]) : ""));
            if (arrived) {
                arrivals++;
                worstArrival = Math.max(worstArrival, local[i]);
            }
        }
        double[] all = ImageMetrics.largestAndMedian(ow.changes);
        System.out.println("[look] open world walk at 10 m/s, each frame's change (+n: tile renderers made):" + each);
        System.out.printf("[look] open world walk at 10 m/s: first second: ratio %.3f, the meadow's walk at 10 m/s"
                + " %.3f; three seconds: ratio %.2f; largest change over its neighbours' median %.3f anywhere, %.3f"
                + " where tiles arrived (%d frames, <= %.2f); %d tiles live, %d tile renderers made%n", ratio,
                meadow, all[0] / all[1], ImageMetrics.largestAndMedian(local)[0], worstArrival, arrivals,
                ARRIVAL_BOUND, ow.live, ow.renderersMade);
        assertTrue(arrivals >= 2, "tiles arrived during the walk: " + arrivals + " frames");
        assertTrue(ratio <= meadow, String.format("at 10 m/s the open world's largest frame change is %.3fx the"
                + " median, the meadow's walk's %.3fx; want no worse", ratio, meadow));
        assertTrue(ratio <= 1.15, String.format("largest frame change %.3fx the median, want <= 1.15x", ratio));
        assertTrue(worstArrival <= ARRIVAL_BOUND, String.format("a frame where tiles arrived changed %.3fx its"
                + " neighbours' median, want <= %.2f", worstArrival, ARRIVAL_BOUND));
    }

    @Test
    void atTheMeadowsWalkingSpeedNoFrameChangesMoreThanAlongTheMeadowsWalk() throws Exception {
        double speed = RenderScenes.load("meadow.xml").camera().pathSpeed();
        double ratio = walk(speed, 31).firstSecondRatio();
        double meadow = ratio(PoppingTest.meadowWalk(speed));
        System.out.printf("[look] open world walk at the meadow's %.1f m/s: ratio %.3f, the meadow's walk %.3f%n",
                speed, ratio, meadow);
        assertTrue(ratio <= meadow, String.format("at %.1f m/s the open world's largest frame change is %.3fx the"
                + " median, the meadow's walk's %.3fx; want no worse", speed, ratio, meadow));
    }

    private static double ratio(double[] changes) {
        double[] lm = ImageMetrics.largestAndMedian(changes);
        assertTrue(lm[1] > 0, "the walk does not move the picture");
        return lm[0] / lm[1];
    }

    /**
     * A walk's frame changes and the tile renderers made by each frame.
     *
     * @param changes       frame-to-frame changes, /255
     * @param made          tile renderers made after each frame
     * @param live          tiles live at the end
     * @param renderersMade tile renderers made in all
     */
    private record Walk(double[] changes, int[] made, int live, long renderersMade) {
        double firstSecondRatio() {
            return ratio(java.util.Arrays.copyOf(changes, 30));
        }
    }

    /** The open world's walk east from the origin at {@code speed} m/s, 30 frames a second. */
    private static Walk walk(double speed, int frameCount) throws Exception {
        SceneDef scene = SceneFiles.parse(Path.of("scenes", "openworld.xml"));
        TilePlacer placer = RenderScenes.placer(scene);
        SimulationDef d = scene.simulationDef();
        SimulationDef still = new SimulationDef(d.terrain(), d.species(), d.distributions(), d.placements(), d.flows(),
                d.field().withEnabled(false), d.animation(), d.seed());
        RenderSettings settings = RenderSettings.of(scene.render());
        settings.setClear(true);
        settings.setTerrain(true);
        ByteBuffer px = MemoryUtil.memAlloc(4 * W * H);
        Img[] frames = new Img[frameCount];
        int[] made = new int[frameCount];
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
            for (int i = 0; i < frameCount; i++) {
                double x = i * speed / 30;
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
            return new Walk(ImageMetrics.frameChanges(frames), made, w.liveTiles(), r.renderersMade());
        } finally {
            MemoryUtil.memFree(px);
        }
    }
}
