package org.jecosys.gdx;

import org.jecosys.render.gl.GlContexts;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.badlogic.gdx.backends.lwjgl3.Lwjgl3Files;
import com.badlogic.gdx.graphics.PerspectiveCamera;
import com.badlogic.gdx.utils.GdxNativesLoader;
import java.lang.management.ManagementFactory;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.terrain.Heightfield;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The plant layer's per-frame calls, in a headless OpenGL context standing in for libGDX's (the
 * layer needs only a current context and a libGDX camera): after warm-up, update and render allocate
 * nothing on the render thread; a disposed layer refuses both. Drawing inside a real libGDX
 * application is the example's test.
 */
class PlantLayerTest {
    @BeforeAll
    static void gdxNatives() {
        GdxNativesLoader.load();
    }

    @Test
    void updateAndRenderAllocateNothingAfterWarmUpAndADisposedLayerRefusesThem() throws Exception {
        try (GlContext owner = GlContext.headless(DebugOutput.ON)) {
            GlFramebuffer target = new GlFramebuffer(GlContexts.tracker(owner), 320, 180);
            PlantLayer layer = PlantLayer.load(new Lwjgl3Files().classpath("org/jecosys/gdx/tiny/tiny.xml"));
            try {
                Heightfield t = layer.simulation().world().terrain().heightfield();
                PerspectiveCamera cam = new PerspectiveCamera(55, 320, 180);
                cam.near = 0.05f;
                cam.far = 100f;
                cam.position.set(0, (float) t.height(0, 3) + 1.5f, 3);
                cam.lookAt(0, (float) t.height(0, 0), 0);
                cam.update();
                target.bind();
                com.sun.management.ThreadMXBean mx =
                        (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
                long self = Thread.currentThread().getId();
                for (int i = 0; i < 300; i++) { // warm up
                    layer.update(1 / 60f, cam);
                    layer.render(cam);
                }
                assertTrue(layer.renderer().triangles() > 0, "plants drawn");
                long least = Long.MAX_VALUE;
                for (int run = 0; run < 5; run++) {
                    long before = mx.getThreadAllocatedBytes(self);
                    for (int i = 0; i < 30; i++) {
                        layer.update(1 / 60f, cam);
                        layer.render(cam);
                    }
                    least = Math.min(least, mx.getThreadAllocatedBytes(self) - before);
                }
                assertEquals(0, least, "bytes allocated on the render thread by 30 frames of update and render");
            } finally {
                layer.dispose();
                target.close();
            }
            layer.dispose(); // idempotent
            PerspectiveCamera cam = new PerspectiveCamera();
            assertThrows(IllegalStateException.class, () -> layer.update(0.01f, cam));
            assertThrows(IllegalStateException.class, () -> layer.render(cam));
            GlContexts.debug(owner).check("the plant layer test");
        }
    }
}
