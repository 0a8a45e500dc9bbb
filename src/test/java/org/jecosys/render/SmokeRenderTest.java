package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.ByteBuffer;
import java.nio.file.Path;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;

class SmokeRenderTest {
    @Test
    void rendersC1() throws Exception {
        SceneDef def = RenderScenes.load("c1.xml");
        World world = RenderScenes.build(def);
        int w = 640;
        int h = 360;
        try (GlContext gl = GlContext.headless(true)) {
            System.out.println(gl.describe());
            ByteBuffer px = MemoryUtil.memAlloc(4 * w * h);
            try (GlFramebuffer fb = new GlFramebuffer(gl.tracker(), w, h);
                 SceneRenderer r = new SceneRenderer(gl, world, new RenderSettings())) {
                ViewCamera cam = RenderScenes.camera(def, world, w, h);
                fb.bind();
                r.render(TestFrames.rest(world), cam, w, h);
                Pixels.read(w, h, px);
                Pixels.writePng(Path.of("target/smoke-rest.png"), px, w, h);
                r.render(TestFrames.wind(world, 1.0), cam, w, h);
                Pixels.read(w, h, px);
                Pixels.writePng(Path.of("target/smoke-wind.png"), px, w, h);
                System.out.println("tri " + r.triangles() + " lines " + r.lines() + " draws " + r.plants().drawCalls());
                gl.debug().check("smoke");
            } finally {
                MemoryUtil.memFree(px);
            }
            assertEquals(0, gl.tracker().live());
        }
    }
}
