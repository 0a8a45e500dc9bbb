package org.jecosys.app;

import org.jecosys.render.gl.GlContexts;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import imgui.ImGui;
import java.nio.ByteBuffer;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.GlCensus;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.render.RenderScenes;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.SceneRenderer;
import org.jecosys.render.TestFrames;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlTracker;

/** The viewer's ImGui layer over a headless render of C1: it draws, and closing it frees its GL objects. */
class ImGuiLayerTest {
    private static final int W = 320;
    private static final int H = 200;

    @Test
    void theImGuiPanelRendersAndClosingReleasesItsGlObjects() {
        World world = RenderScenes.build(RenderScenes.load("c1.xml"));
        ViewCamera cam = new ViewCamera();
        cam.setPosition(0, 1.5, 6);
        cam.setOrientation(0, -0.25);
        cam.setLens(Math.toRadians(50), W / (double) H, 0.05, 200);
        ByteBuffer px = MemoryUtil.memAlloc(4 * W * H);
        ByteBuffer other = MemoryUtil.memAlloc(4 * W * H);
        try (GlContext gl = GlContext.headless(DebugOutput.ON);
             GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), W, H);
             SceneRenderer renderer = new SceneRenderer(gl, world, RenderSettings.standalone())) {
            fb.bind();
            renderer.render(TestFrames.rest(world, cam), cam, W, H);
            Pixels.read(W, H, other);
            GlCensus before = GlCensus.take();
            GlCensus during;
            ImGuiLayer closed;
            try (ImGuiLayer ui = new ImGuiLayer(gl, 0)) {
                closed = ui;
                for (int i = 0; i < 2; i++) {
                    fb.bind();
                    renderer.render(TestFrames.rest(world, cam), cam, W, H);
                    ui.begin(W, H, 1 / 60f);
                    ImGui.setNextWindowPos(10, 10);
                    ImGui.setNextWindowSize(180, 120);
                    ImGui.begin("JEcoSys");
                    ImGui.text("fps 60.0");
                    ImGui.checkbox("force field", true);
                    ImGui.end();
                    ui.end();
                }
                Pixels.read(W, H, px);
                during = GlCensus.take().minus(before);
            }
            // the backend's own GL objects, which GlTracker does not see: counted by asking the driver
            assertTrue(during.textures() >= 1, "ImGui's font atlas: " + during);
            assertTrue(during.programs() >= 1, "ImGui's program: " + during);
            assertTrue(during.buffers() >= 2, "ImGui's vertex and index buffers: " + during);
            assertEquals(before, GlCensus.take(), "closing the ImGui layer releases every GL object it made (it had "
                    + during + ")");
            closed.close(); // idempotent
            assertEquals(before, GlCensus.take());
            // the panel covers the top-left corner
            int changed = 0;
            for (int y = H - 120; y < H - 20; y++) {
                for (int x = 20; x < 180; x++) {
                    changed += px.getInt(4 * (y * W + x)) != other.getInt(4 * (y * W + x)) ? 1 : 0;
                }
            }
            assertTrue(changed > 5000, "panel pixels: " + changed);
            GlContexts.debug(gl).check("the ImGui test");
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) px);
            MemoryUtil.memFree((java.nio.Buffer) other);
        }
    }
}
