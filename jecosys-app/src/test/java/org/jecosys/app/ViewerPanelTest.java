package org.jecosys.app;

import org.jecosys.render.gl.GlContexts;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.overlay.GizmoRenderer;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.SceneRenderer;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.Simulation;
import org.jecosys.wind.FlowKind;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.lwjgl.system.MemoryUtil;

/**
 * The viewer's whole frame headless, as {@link Viewer} draws it but without a window: the scene, the
 * gizmos and wind arrows, the HUD, the panel with a selected flow of each kind open, the legends and
 * the save and quit confirmations. Every ImGui window and popup is balanced (an unbalanced one fails
 * in ImGui's end of frame) and the panel covers the left of the picture.
 */
class ViewerPanelTest {
    private static final int W = 800;
    private static final int H = 500;

    @TempDir
    Path dir;

    @Test
    void theWholeViewerFrameDrawsWithEveryPanelAndDialogOpen() throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        Path file = Files.copy(Path.of("scenes/c1.xml"), scenes.resolve("c1.xml"));
        SceneDef def = SceneFiles.parse(file);
        ByteBuffer px = MemoryUtil.memAlloc(4 * W * H);
        try (Simulation sim = Simulation.create(def.simulationDef(), scenes, 1, Progress.NONE);
             GlContext gl = GlContext.headless(DebugOutput.ON);
             GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), W, H)) {
            ViewCamera camera = ViewCamera.of(def.camera(), sim.world().terrain().heightfield()
                    .height(def.camera().x(), def.camera().z()), W / (double) H);
            FlyCamera fly = new FlyCamera(camera, def.camera(), sim.world().terrain().heightfield());
            RenderSettings settings = HeadlessRender.settings(def.render());
            settings.overlays().setShowField(true);
            settings.overlays().setShowWind(true);
            SceneEditor editor = new SceneEditor(def, sim, settings);
            ViewerControls controls = new ViewerControls(def, sim, editor, new SceneSaver(file, scenes), fly,
                    new ViewerInput());
            try (SceneRenderer renderer = new SceneRenderer(gl, sim.world(), settings);
                 GizmoRenderer gizmos = new GizmoRenderer(gl, sim.world().terrain().heightfield());
                 ImGuiLayer ui = new ImGuiLayer(gl, 0)) {
                renderer.setField(sim.inspect().forceField().debugView());
                ViewerPanel panel = new ViewerPanel(def, controls, sim, renderer);
                FrameTimes times = new FrameTimes();
                WindLegend legend = new WindLegend();
                for (int frame = 0; frame < 12; frame++) {
                    if (frame < 6) {
                        controls.setNewKind(frame);
                        controls.addFlow(-6 + 2.5 * frame, -2); // selects it: its editor opens in the panel
                    } else if (frame == 8) {
                        controls.save(); // a shipped scene (under "scenes/"): the confirmation opens
                        assertNotNull(controls.pendingSave());
                    } else if (frame == 10) {
                        controls.cancelSave();
                        controls.requestQuit(); // unsaved changes: the question opens
                        assertTrue(controls.quitAsked());
                    }
                    controls.frame(1 / 30.0, W / 2.0, H / 2.0, W, H, false, false);
                    sim.step(1 / 30.0, camera);
                    FlowGizmos flows = controls.gizmos();
                    legend.update(legend.typical(sim.inspect().forceField().debugView()), 1 / 30.0);
                    fb.bind();
                    renderer.render(sim.latestFrame(), camera, W, H);
                    org.lwjgl.opengl.GL11C.glViewport(0, 0, W, H);
                    gizmos.render(flows.gizmos(), sim.inspect().forceField().debugView(), legend.scale(), camera);
                    times.add(1 / 30.0);
                    ui.begin(W, H, 1 / 30f);
                    panel.hud(times, fly, sim.latestFrame(), 1.5);
                    panel.panel();
                    panel.overlays(W, H, flows.gizmos(), legend);
                    ui.end();
                }
                Pixels.read(W, H, px);
                if (System.getProperty("jecosys.panel.png") != null) {
                    Pixels.writePng(Path.of(System.getProperty("jecosys.panel.png")), px, W, H);
                }
                assertEquals(def.flows().size() + 5, editor.flowIds().size(), "five flows added (and a blast)");
                // the panel's dark background covers the left, below the HUD
                int dark = 0;
                for (int y = 20; y < H - 200; y++) {
                    for (int x = 20; x < 300; x++) {
                        dark += Pixels.red(px, W, x, y) < 60 && Pixels.green(px, W, x, y) < 60 ? 1 : 0;
                    }
                }
                assertTrue(dark > 20_000, "panel pixels: " + dark);
                GlContexts.debug(gl).check("the viewer frame");
            }
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) px);
        }
        assertEquals(FlowKind.BLAST, ViewerControls.NEW_KINDS[5]);
    }
}
