package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.PassTimes.Pass;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * Issue 42: the GPU time of each pass ({@link SceneRenderer#setPassTiming}). C1 at 480x270 on llvmpipe,
 * 40 frames, each finished before the next (so every query is ready when its slot comes round): frames
 * are measured pass by pass and, every fourth, whole; none is dropped; the passes C1 draws take time and
 * the shadow map (the ground path on llvmpipe) none; the median sum of the passes is within 25% of the
 * median whole frame (the bench reports the figure); a timed frame allocates nothing; off again, there
 * are no times.
 */
class PassTimesTest {
    private static final int W = 480;
    private static final int H = 270;

    @Test
    void eachPassIsTimedWithoutWaitingAndTheyAddUpToTheFrame() {
        SceneDef def = RenderScenes.load("c1.xml");
        World world = RenderScenes.build(def);
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        try (GlContext gl = GlContext.headless(DebugOutput.ON);
             GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), W, H, 4);
             SceneRenderer r = new SceneRenderer(gl, world, RenderScenes.settings(def))) {
            ViewCamera cam = RenderScenes.camera(def, world, W, H);
            Frame frame = TestFrames.rest(world, cam);
            assertNull(r.passTimes(), "no times while timing is off");
            r.setPassTiming(true);
            int frames = 40;
            double[] sums = new double[frames];
            double[] wholes = new double[frames];
            int ns = 0;
            int nw = 0;
            long lastPass = 0;
            long lastWhole = 0;
            long allocated = -1;
            fb.bind();
            for (int i = 0; i < frames; i++) {
                long a0 = threads.getCurrentThreadAllocatedBytes();
                r.render(frame, cam, W, H);
                long a1 = threads.getCurrentThreadAllocatedBytes();
                if (i == frames - 1) {
                    allocated = a1 - a0;
                }
                gl.finish();
                PassTimes t = r.passTimes();
                if (t.passFrames() > lastPass) {
                    lastPass = t.passFrames();
                    sums[ns++] = t.passSumNanos();
                }
                if (t.wholeFrames() > lastWhole) {
                    lastWhole = t.wholeFrames();
                    wholes[nw++] = t.frameNanos();
                }
            }
            PassTimes t = r.passTimes();
            StringBuilder each = new StringBuilder();
            for (Pass p : Pass.values()) {
                each.append(' ').append(p).append(' ').append(String.format("%.2f", t.nanos(p) / 1e6)).append(" ms;");
            }
            double sum = median(Arrays.copyOf(sums, ns));
            double whole = median(Arrays.copyOf(wholes, nw));
            System.out.printf("[look] C1 pass times (last frame):%s median sum %.2f ms, median whole frame %.2f ms"
                    + " (%d and %d frames, %d dropped), %d bytes allocated by a timed frame%n", each, sum / 1e6,
                    whole / 1e6, ns, nw, t.dropped(), allocated);
            assertTrue(ns >= 20 && nw >= 5, "frames measured: " + ns + " by pass, " + nw + " whole");
            assertEquals(0, t.dropped(), "finished frames are ready when their slot comes round");
            for (Pass p : new Pass[] {Pass.RESOLVE, Pass.NEAR_PLANTS, Pass.GROUND, Pass.SKY, Pass.FAR_PLANTS}) {
                assertTrue(t.nanos(p) > 0, p + " takes time:" + each);
            }
            assertEquals(0, t.nanos(Pass.SHADOW_MAP), "no shadow map on the ground path");
            assertTrue(Math.abs(sum - whole) <= 0.25 * whole, String.format("the passes add up to %.2f ms, the"
                    + " frame %.2f ms", sum / 1e6, whole / 1e6));
            assertEquals(0, allocated, "a timed frame allocates nothing");
            r.setPassTiming(false);
            assertNull(r.passTimes());
            GlContexts.debug(gl).check("pass timing");
        }
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s.length == 0 ? Double.NaN : s.length % 2 == 1 ? s[s.length / 2] : 0.5 * (s[s.length / 2 - 1] + s[s.length / 2]);
    }
}
