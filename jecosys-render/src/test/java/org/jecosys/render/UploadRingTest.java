package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * Issue 42, "no stall in a frame": where the GL has buffer storage (llvmpipe's 4.5 here) the plants'
 * per-frame uploads (instance records, render states, the list table) are written into a persistently
 * mapped ring of three fenced regions, never re-specified. C1 at 480x270, 30 frames of a travelling breeze,
 * each finished before the next as a swap chain paces a game's frames, on both resolve paths: the ring is
 * used, no frame found its region still being read (0 waits), a frame allocates nothing, the GL reports no
 * error. Then 20 frames back to back, never finished: llvmpipe rasterises on the CPU far behind the
 * frames it is given, so frames wait for their region, and each wait is counted (printed); the last
 * picture of the burst equals the one the same frame draws when it is rendered alone.
 */
class UploadRingTest {
    private static final int W = 480;
    private static final int H = 270;

    private static int[] read() {
        java.nio.ByteBuffer px = org.lwjgl.system.MemoryUtil.memAlloc(4 * W * H);
        try {
            Pixels.read(W, H, px);
            int[] out = new int[W * H];
            px.asIntBuffer().get(out);
            return out;
        } finally {
            org.lwjgl.system.MemoryUtil.memFree((java.nio.Buffer) px);
        }
    }

    @Test
    void framesUploadThroughTheMappedRingWithoutWaiting() {
        SceneDef def = RenderScenes.load("c1.xml");
        World world = RenderScenes.build(def);
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        for (ResolvePath path : ResolvePath.values()) {
            try (GlContext gl = GlContext.headless(DebugOutput.ON);
                 GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), W, H)) {
                if (!path.supported(gl.capabilities())) {
                    continue;
                }
                ViewCamera cam = RenderScenes.camera(def, world, W, H);
                int[] last;
                int[] alone;
                long allocated = -1;
                long waits;
                long burstWaits;
                try (SceneRenderer r = new SceneRenderer(gl, world, RenderScenes.settings(def), path)) {
                    assertTrue(r.uploadRing(), "a 4.5 context has buffer storage: " + gl.describe());
                    fb.bind();
                    Frame f = null;
                    for (int i = 0; i < 30; i++) {
                        f = TestFrames.wind(world, i / 30.0, cam);
                        long a0 = threads.getCurrentThreadAllocatedBytes();
                        r.render(f, cam, W, H);
                        long a1 = threads.getCurrentThreadAllocatedBytes();
                        if (i >= 20) {
                            // the least of the last ten frames: a frame that allocates does so every time,
                            // while code the JIT has not compiled yet may allocate what it later keeps in registers
                            allocated = allocated < 0 ? a1 - a0 : Math.min(allocated, a1 - a0);
                        }
                        gl.finish();
                    }
                    waits = r.uploadWaits();
                    for (int i = 30; i < 50; i++) {
                        f = TestFrames.wind(world, i / 30.0, cam);
                        r.render(f, cam, W, H);
                    }
                    burstWaits = r.uploadWaits() - waits;
                    last = read();
                    // the same frame again, alone and finished: the ring's other regions hold older frames
                    gl.finish();
                    r.render(f, cam, W, H);
                    alone = read();
                }
                GlContexts.debug(gl).check("frames through the upload ring");
                System.out.printf("[ring] %s: 30 paced frames, %d waits for a region, %d bytes allocated by a frame; "
                        + "20 frames back to back, %d waits%n", path, waits, allocated, burstWaits);
                assertEquals(0, waits, path + ": no frame waited for its upload region");
                assertEquals(0, allocated, path + ": a frame allocates nothing");
                int differ = 0;
                for (int i = 0; i < last.length; i++) {
                    differ += last[i] != alone[i] ? 1 : 0;
                }
                assertEquals(0, differ, path + ": the picture drawn at the end of the run is the frame's own");
            }
        }
    }
}
