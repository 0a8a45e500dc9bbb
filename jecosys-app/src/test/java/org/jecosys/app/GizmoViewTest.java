package org.jecosys.app;

import org.jecosys.render.gl.GlContexts;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.Set;
import org.jecosys.field.FieldDebugView;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.overlay.GizmoKind;
import org.jecosys.render.overlay.GizmoRenderer;
import org.jecosys.render.overlay.Gizmos;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.render.RenderScenes;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.SceneRenderer;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Simulation;
import org.jecosys.wind.AbstractWindSource;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;

/**
 * The viewer's gizmos through its own code path (flows in a running simulation, {@link FlowGizmos},
 * {@link GizmoRenderer} over the scene): every kind of gizmo (each built-in flow kind, an agent and a
 * program's own flow) is drawn in its colour where its flow's centre projects, and the wind arrows
 * are drawn on the terrain. Headless (Mesa llvmpipe or the GPU's EGL driver).
 */
class GizmoViewTest {
    private static final int W = 400;
    private static final int H = 260;

    /** A program's own flow (no def, no kind): the gizmo of kind USER. */
    private static final class Fan extends AbstractWindSource {
        Fan(double x, double z) {
            super("fan", x, z, 1.5, ActivationDef.ALWAYS);
        }

        @Override
        protected void flow(double x, double z, double time, Vector2d dest) {
            dest.set(1, 0);
        }
    }

    @Test
    void eachGizmoKindIsDrawnInItsColourAtItsFlowsCentre() throws Exception {
        SceneDef def = RenderScenes.load("c1.xml");
        ViewCamera cam = new ViewCamera();
        cam.setPosition(0, 24, 6);
        cam.setOrientation(0, -1.2);
        cam.setLens(Math.toRadians(55), W / (double) H, 0.05, 300);
        ByteBuffer px = MemoryUtil.memAlloc(4 * W * H);
        try (Simulation sim = Simulation.create(def.simulationDef(), Path.of("scenes"), 1, Progress.NONE)) {
            // the scene's own flows off the picture, then one flow of each kind on a 3 x 3 grid
            for (int i = 0; i < sim.inspect().windField().size(); i++) {
                sim.removeFlow(sim.inspect().windField().get(i));
            }
            FlowKind[] kinds = {FlowKind.UNIFORM, FlowKind.GUST, FlowKind.SOURCE, FlowKind.SINK, FlowKind.VORTEX,
                FlowKind.RAIN};
            for (int k = 0; k < kinds.length; k++) {
                sim.addFlow(FlowDef.builder(kinds[k].xmlName(), kinds[k]).centre(-6 + 6 * (k % 3), -8 + 5.5 * (k / 3))
                        .strength(3).direction(0.4).coreRadius(0.3).influenceRadius(1.5).build());
            }
            sim.blast("blast", -6, 3, 5, 10);
            sim.attachAgent(FlowDef.builder(ViewerControls.AGENT_PREFIX + "1", FlowKind.SOURCE).centre(0, 3)
                    .strength(2).coreRadius(0.2).influenceRadius(1.2).build());
            sim.addFlow(new Fan(6, 3));
            sim.step(1 / 60.0, cam);
            FlowGizmos flows = new FlowGizmos(sim.world().terrain().heightfield());
            flows.fill(sim.inspect().windField(), w -> w.id().startsWith(ViewerControls.AGENT_PREFIX), null, null);
            Gizmos g = flows.gizmos();
            assertEquals(sim.inspect().windField().size(), g.size(), "a gizmo per flow");
            Set<GizmoKind> seen = EnumSet.noneOf(GizmoKind.class);
            for (int i = 0; i < g.size(); i++) {
                seen.add(g.kind(i));
            }
            assertEquals(EnumSet.allOf(GizmoKind.class), seen, "every kind of gizmo is in the picture");
            try (GlContext gl = GlContext.headless(DebugOutput.ON);
                 GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), W, H);
                 SceneRenderer scene = new SceneRenderer(gl, sim.world(), RenderSettings.standalone());
                 GizmoRenderer gizmos = new GizmoRenderer(gl, sim.world().terrain().heightfield())) {
                scene.setField(sim.inspect().forceField().debugView());
                fb.bind();
                scene.render(sim.latestFrame(), cam, W, H);
                Pixels.read(W, H, px);
                long background = checksum(px);
                org.lwjgl.opengl.GL11C.glViewport(0, 0, W, H);
                gizmos.render(g, null, 5, cam);
                Pixels.read(W, H, px);
                if (System.getProperty("jecosys.gizmo.png") != null) {
                    Pixels.writePng(Path.of(System.getProperty("jecosys.gizmo.png")), px, W, H);
                }
                Picker picker = new Picker(sim.world().terrain().heightfield());
                double[] at = new double[3];
                float[] rgba = new float[4];
                for (int i = 0; i < g.size(); i++) {
                    // the flow's own centre (not the gizmo's): the gizmo must stand where the flow is
                    double cx = flows.source(i).centreX();
                    double cz = flows.source(i).centreZ();
                    picker.project(cam, cx, sim.world().terrain().heightfield().height(cx, cz), cz, W, H, at);
                    int x = (int) at[0];
                    int y = H - 1 - (int) at[1];
                    GizmoRenderer.shade(g.kind(i), g.enabled(i), g.weight(i), rgba);
                    String where = g.kind(i) + " (" + flows.source(i).id() + ") at pixel " + x + "," + y;
                    assertTrue(x > 2 && y > 2 && x < W - 3 && y < H - 3, where + " in view");
                    assertEquals(Math.round(rgba[0] * 255), Pixels.red(px, W, x, y), 12, where + " red");
                    assertEquals(Math.round(rgba[1] * 255), Pixels.green(px, W, x, y), 12, where + " green");
                    assertEquals(Math.round(rgba[2] * 255), Pixels.blue(px, W, x, y), 12, where + " blue");
                    assertTrue(picker.gizmo(g, cam, at[0], at[1], W, H) == i, where + ": picking there finds it");
                }
                // the wind arrows: the scene's breeze and gusts, one arrow per visible node of the field
                FieldDebugView view = sim.inspect().forceField().debugView();
                scene.render(sim.latestFrame(), cam, W, H);
                org.lwjgl.opengl.GL11C.glViewport(0, 0, W, H);
                gizmos.render(null, null, 5, cam);
                Pixels.read(W, H, px);
                assertEquals(background, checksum(px), "nothing drawn without gizmos or wind");
                gizmos.render(null, view, 5, cam);
                Pixels.read(W, H, px);
                assertTrue(gizmos.triangles() > 3 * 10, "arrows: " + gizmos.triangles() + " triangles");
                assertTrue(checksum(px) != background, "the wind arrows change the picture");
                GlContexts.debug(gl).check("the gizmo view test");
            }
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) px);
        }
    }

    private static long checksum(ByteBuffer px) {
        long h = 1125899906842597L;
        for (int i = 0; i < 4 * W * H; i++) {
            h = 31 * h + px.get(i);
        }
        return h;
    }
}
