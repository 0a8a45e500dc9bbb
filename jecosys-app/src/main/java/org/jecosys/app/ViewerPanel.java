package org.jecosys.app;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiTreeNodeFlags;
import imgui.flag.ImGuiWindowFlags;
import imgui.type.ImInt;
import java.math.BigDecimal;
import java.util.Locale;
import org.jecosys.anim.AnimationMode;
import org.jecosys.render.overlay.Gizmos;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.SceneRenderer;
import org.jecosys.render.ShadowPath;
import org.jecosys.scene.RenderDef;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;

/**
 * The viewer's HUD and ImGui panel: flows ({@link FlowPanel}: every parameter of the selected flow,
 * the flow F adds), animation mode, force field, LOD distances, overlays, terrain tint, Save and
 * Save As ({@link SaveDialogs}); and the legends ({@link Legends}). Edits go through
 * {@link SceneEditor}. Render thread. The HUD builds a few short strings per frame (imgui-java takes
 * Java strings); edits allocate.
 */
final class ViewerPanel {
    /** The shadow paths' radio labels, by ordinal: auto, the ground splat, the map (plants shade plants). */
    private static final String[] SHADOW_LABELS = {"auto", "ground splat", "shadow map"};

    private static final String[] MODES = {"static", "random", "constraint"};
    private static final String[] TINTS = {"none", "water", "nutrients"};

    private final SceneDef def;
    private final ViewerControls controls;
    private final SceneEditor editor;
    private final Simulation sim;
    private final SceneRenderer renderer;
    private final FlowPanel flows;
    private final SaveDialogs saving;
    private final Legends legends;
    /** The rendering path, as the HUD names it. */
    private final String renderPath;
    private final ImInt mode = new ImInt();
    private final ImInt tint = new ImInt();
    private final float[] edit = new float[1];
    private final double[] fps = new double[2];

    ViewerPanel(SceneDef def, ViewerControls controls, Simulation sim, SceneRenderer renderer) {
        this.def = def;
        this.controls = controls;
        this.editor = controls.editor();
        this.sim = sim;
        this.renderer = renderer;
        this.renderPath = "render path: " + renderer.resolvePath().description();
        this.flows = new FlowPanel(controls, sim.world().terrain().heightfield());
        this.saving = new SaveDialogs(controls);
        this.legends = new Legends(sim.world().terrain().heightfield());
    }

    /**
     * Text for ImGui's text calls, which read their string as a printf format: '%' doubled. Any thread.
     *
     * @param text any text (a path, a message)
     * @return the text to pass to {@code ImGui.text} or {@code ImGui.textWrapped}
     */
    static String safe(String text) {
        return text.replace("%", "%%");
    }

    /**
     * A number as short as it reads: {@code 4}, {@code 0.5}, {@code 43.146}. Any thread.
     *
     * @param v a finite value
     * @return its shortest decimal form, without trailing zeros
     */
    static String number(double v) {
        if (!Double.isFinite(v)) {
            return Double.toString(v);
        }
        String s = new BigDecimal(Double.toString(v)).stripTrailingZeros().toPlainString();
        return s.equals("-0") ? "0" : s;
    }

    /**
     * The HUD, top left: frame rate, walking speed, what was drawn, and the times of the force field,
     * the animation and the rendering, each on its own.
     *
     * @param times    the frame times
     * @param fly      the camera
     * @param frame    the frame shown
     * @param renderMs the time spent issuing this frame's draw calls (scene and gizmos), milliseconds
     */
    void hud(FrameTimes times, FlyCamera fly, Frame frame, double renderMs) {
        times.fps(fps);
        ImGui.setNextWindowPos(8, 8, ImGuiCond.Always);
        ImGui.setNextWindowBgAlpha(0.45f);
        ImGui.begin("hud", ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize
                | ImGuiWindowFlags.NoInputs);
        ImGui.text(String.format(Locale.ROOT, "%.1f fps (sd %.1f)   walk %.2f m/s (Shift x4, Ctrl /4, wheel)",
                fps[0], fps[1], fly.speed()));
        ImGui.text("triangles " + renderer.triangles() + "  lines " + renderer.lines() + "  components animated "
                + frame.componentsAnimated());
        // Frame.animationNanos is the chunks' own span: it no longer includes the field update, which the
        // stepping thread runs before helping the workers (side by side with several threads)
        int threads = sim.inspect().workers();
        ImGui.text(String.format(Locale.ROOT, "field %.2f ms  animation %.2f ms (%d thread%s%s)  render %.2f ms",
                frame.fieldNanos() / 1e6, frame.animationNanos() / 1e6, threads, threads == 1 ? "" : "s",
                threads == 1 ? ", one after the other" : ", side by side", renderMs));
        ImGui.text(renderPath);
        ImGui.text(fly.playing() ? "camera path playing (P stops)"
                : "WASD QE, right-drag look, H frame scene, F add flow, T agent, P path (view --help lists all)");
        if (!controls.message().isEmpty()) {
            ImGui.text(safe(controls.message()));
        }
        ImGui.end();
    }

    /**
     * The legends and the confirmations, after the panel.
     *
     * @param width  framebuffer width, pixels
     * @param height framebuffer height, pixels
     * @param gizmos the gizmos drawn this frame, or null
     * @param wind   the wind arrows' scale
     */
    void overlays(int width, int height, Gizmos gizmos, WindLegend wind) {
        RenderSettings s = renderer.settings();
        if (s.overlays().showField() || s.overlays().showWind()) {
            legends.map(width, height, s.overlays(), gizmos);
        }
        if (controls.showWind()) {
            legends.wind(wind.scale(), wind.speed());
        }
        saving.modals();
    }

    /** The panel. */
    void panel() {
        ImGui.setNextWindowPos(8, 110, ImGuiCond.FirstUseEver);
        ImGui.setNextWindowSize(440, Math.max(200, Math.min(640, ImGui.getIO().getDisplaySizeY() - 120)),
                ImGuiCond.FirstUseEver);
        ImGui.begin("JEcoSys");
        if (ImGui.collapsingHeader("Flows", ImGuiTreeNodeFlags.DefaultOpen)) {
            flows.draw(sim.inspect().windField());
        }
        if (ImGui.collapsingHeader("Animation")) {
            mode.set(editor.mode().ordinal());
            if (ImGui.combo("mode", mode, MODES)) {
                editor.setMode(AnimationMode.values()[mode.get()]);
            }
            if (ImGui.checkbox("force field", editor.fieldEnabled())) {
                editor.setFieldEnabled(!editor.fieldEnabled());
            }
        }
        RenderSettings s = renderer.settings();
        if (ImGui.collapsingHeader("Level of detail")) {
            for (int sp = 0; sp < def.species().size(); sp++) {
                for (int l = 0; l < editor.lodEdges(sp); l++) {
                    edit[0] = (float) editor.lodEdge(sp, l);
                    if (ImGui.sliderFloat(def.species().get(sp).id() + ": level " + l + " ends (m)", edit, 0.5f,
                            (float) Math.max(60, 2 * editor.lodEdge(sp, l)), "%.3f")) {
                        editor.setLodEdge(sp, l, edit[0]);
                    }
                }
            }
            edit[0] = (float) editor.lodTransition();
            if (ImGui.sliderFloat("transition band (m)", edit, 0, 3, "%.2f")) {
                editor.setLodTransition(edit[0]);
            }
        }
        if (ImGui.collapsingHeader("Light")) {
            edit[0] = (float) Math.toDegrees(s.lighting().sunAzimuth());
            if (ImGui.sliderFloat("sun azimuth (deg)", edit, -180, 360, "%.0f")) {
                editor.setSun(Math.toRadians(edit[0]), s.lighting().sunElevation());
            }
            edit[0] = (float) Math.toDegrees(s.lighting().sunElevation());
            if (ImGui.sliderFloat("sun elevation (deg)", edit, 0, 90, "%.0f")) {
                editor.setSun(s.lighting().sunAzimuth(), Math.toRadians(edit[0]));
            }
            // a view setting: the scene file keeps its own <light sheen>
            if (ImGui.checkbox("wind sheen on bent grass", s.sheen() > 0)) {
                s.setSheen(s.sheen() > 0 ? 0f : (float) Math.max(0.25, editor.sceneSheen()));
            }
            // likewise: the scene file keeps its own <light shadows>
            if (ImGui.checkbox("sun shadows", s.shadows() > 0)) {
                s.setShadows(s.shadows() > 0 ? 0f : (float) Math.max(0.6, editor.sceneShadows()));
            }
            if (s.shadows() > 0) {
                // how they are drawn: a view setting too (auto: the map on a GPU, the splat on llvmpipe)
                ImGui.text("  drawn as");
                for (ShadowPath p : ShadowPath.values()) {
                    ImGui.sameLine();
                    if (ImGui.radioButton(SHADOW_LABELS[p.ordinal()], s.shadowPath() == p)) {
                        s.setShadowPath(p);
                    }
                }
            }
        }
        if (ImGui.collapsingHeader("Overlays")) {
            if (ImGui.checkbox("wind arrows on the terrain (V)", controls.showWind())) {
                controls.showWind(!controls.showWind());
            }
            if (ImGui.checkbox("flow and agent gizmos (G)", controls.showGizmos())) {
                controls.showGizmos(!controls.showGizmos());
            }
            if (ImGui.checkbox("map: force-field quadtree (Fig. 2)", s.overlays().showField())) {
                editor.setShowField(!s.overlays().showField());
            }
            if (ImGui.checkbox("map: wind vectors (Fig. 3)", s.overlays().showWind())) {
                editor.setShowWind(!s.overlays().showWind());
            }
            tint.set(s.tint().ordinal());
            if (ImGui.combo("terrain tint", tint, TINTS)) {
                editor.setTint(RenderDef.Tint.values()[tint.get()]);
            }
        }
        ImGui.separator();
        saving.section();
        ImGui.end();
    }
}
