package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.render.GlContext.DebugOutput;
import java.nio.ByteBuffer;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.junit.jupiter.api.Tag;

/**
 * Multisampled framebuffers (scene C1, headless): every object they make is tracked and released; a
 * 4-sample render has partly covered pixels along the plants' edges where a single-sampled one
 * jumps from plant to background (less total variation along the rows); the resolve filter's tent
 * makes the picture smoother still than the plain average of the samples, and leaves the sky's
 * gradient alone.
 */
@Tag("lwjgl-compat")
class GlFramebufferTest {
    private static final int W = 320;
    private static final int H = 200;

    @Test
    void multisamplingAndTheResolveFilter() {
        World world = RenderScenes.build(RenderScenes.load("c1.xml"));
        ViewCamera cam = RenderScenes.camera(RenderScenes.load("c1.xml"), world, W, H);
        Frame frame = TestFrames.rest(world, cam);
        ByteBuffer single = MemoryUtil.memAlloc(4 * W * H);
        ByteBuffer box = MemoryUtil.memAlloc(4 * W * H);
        ByteBuffer tent = MemoryUtil.memAlloc(4 * W * H);
        try (GlContext gl = GlContext.headless(DebugOutput.ON)) {
            GlCensus before = GlCensus.take();
            try (SceneRenderer r = new SceneRenderer(gl, world, RenderSettings.standalone())) {
                try (GlFramebuffer fb = new GlFramebuffer(gl.tracker(), W, H)) {
                    fb.bind();
                    r.render(frame, cam, W, H);
                    fb.resolve();
                    Pixels.read(W, H, single);
                }
                int live = gl.tracker().live();
                try (GlFramebuffer fb = new GlFramebuffer(gl.tracker(), W, H, 4)) {
                    assertEquals(4, fb.samples());
                    assertEquals(11, gl.tracker().live() - live, "framebuffer, 3 renderbuffers (colour, detail mask, depth), 2 resolve targets and their detail,"
                            + " the filter's program and vertex array");
                    fb.bind();
                    r.render(frame, cam, W, H);
                    fb.setResolveFilter(0);
                    fb.resolve();
                    Pixels.read(W, H, box);
                    fb.setResolveFilter(1);
                    fb.resolve();
                    Pixels.read(W, H, tent);
                    // resolveTo copies the same picture into another framebuffer (a window's, say)
                    try (GlFramebuffer window = new GlFramebuffer(gl.tracker(), W, H)) {
                        fb.resolveTo(window.id());
                        ByteBuffer copy = MemoryUtil.memAlloc(4 * W * H);
                        try {
                            Pixels.read(W, H, copy);
                            assertEquals(tent, copy, "resolveTo shows what resolve reads");
                        } finally {
                            MemoryUtil.memFree((java.nio.Buffer) copy);
                        }
                    }
                    gl.debug().check("multisampled rendering and resolving");
                    assertThrows(IllegalArgumentException.class, () -> fb.setResolveFilter(2.5f));
                }
                assertEquals(live, gl.tracker().live(), "closing releases every object");
            }
            assertEquals(before, GlCensus.take(), "the driver knows no object left over");
            assertThrows(IllegalArgumentException.class, () -> new GlFramebuffer(gl.tracker(), W, H, 0));
        }
        try {
            double tvSingle = variation(single);
            double tvBox = variation(box);
            // without samples the plants' thin parts and edges are blended by their coverage: no rougher
            assertTrue(tvSingle < 1.2 * tvBox, "the single-sampled picture is no rougher than 4 samples: total "
                    + "variation " + tvSingle + " vs " + tvBox);
            double tvTent = variation(tent);
            assertTrue(tvTent < 0.85 * tvBox, "the tent smooths: total variation " + tvTent + " vs " + tvBox);
            // the sky's top row is a smooth gradient: the filter leaves it within a level
            for (int x = 1; x < W - 1; x++) {
                assertEquals(Pixels.blue(box, W, x, H - 2), Pixels.blue(tent, W, x, H - 2), 1.0, "sky at " + x);
            }
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) single);
            MemoryUtil.memFree((java.nio.Buffer) box);
            MemoryUtil.memFree((java.nio.Buffer) tent);
        }
    }

    private static double variation(ByteBuffer px) {
        double sum = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 1; x < W; x++) {
                sum += Math.abs(Pixels.green(px, W, x, y) - Pixels.green(px, W, x - 1, y));
            }
        }
        return sum;
    }
}
