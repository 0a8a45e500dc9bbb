package org.jecosys.app;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiWindowFlags;
import imgui.type.ImInt;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.plant.LodDef;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.render.PlantBatches;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.SceneRenderer;
import org.jecosys.render.TerrainTint;
import org.jecosys.scene.RenderDef;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.jecosys.wind.WindField;
import org.jecosys.wind.WindSource;

/**
 * The viewer's HUD and ImGui panel: flows (enable, strength, radius, add at the cursor), animation
 * mode, force field, LOD distances, overlays, terrain tint, save. Render thread. The HUD builds a few
 * short strings per frame (imgui-java takes Java strings); edits allocate.
 */
final class ViewerPanel {
    static final String[] KINDS = {"uniform", "source", "sink", "vortex", "gust", "blast"};
    static final FlowKind[] KIND_VALUES = {FlowKind.UNIFORM, FlowKind.SOURCE, FlowKind.SINK, FlowKind.VORTEX,
        FlowKind.GUST, FlowKind.BLAST};
    private static final String[] MODES = {"static", "random", "constraint"};
    private static final String[] TINTS = {"none", "water", "nutrients"};

    private final SceneDef def;
    private final Path file;
    private final Simulation sim;
    private final SceneRenderer renderer;
    private final ImInt kind = new ImInt(1);
    private final ImInt mode = new ImInt();
    private final ImInt tint = new ImInt();
    private final float[] strength = {4f};
    private final float[] radius = {3f};
    private final float[] edit = new float[1];
    private final float[] lod = new float[2];
    private final double[] fps = new double[2];
    private final double[] edges = new double[2];
    private String message = "";
    private int added;

    ViewerPanel(SceneDef def, Path file, Simulation sim, SceneRenderer renderer) {
        this.def = def;
        this.file = file;
        this.sim = sim;
        this.renderer = renderer;
        mode.set(sim.mode().ordinal());
        tint.set(renderer.settings().tint().ordinal());
    }

    void hud(FrameTimes times, boolean playing, Frame frame) {
        times.fps(fps);
        ImGui.setNextWindowPos(8, 8, ImGuiCond.Always);
        ImGui.setNextWindowBgAlpha(0.45f);
        ImGui.begin("hud", ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize
                | ImGuiWindowFlags.NoInputs);
        ImGui.text(String.format("%.1f fps (sd %.1f)", fps[0], fps[1]));
        ImGui.text("triangles " + renderer.triangles() + "  lines " + renderer.lines());
        ImGui.text("components animated " + frame.componentsAnimated());
        ImGui.text(String.format("field %.2f ms  simulation %.2f ms", frame.fieldNanos() / 1e6,
                frame.animationNanos() / 1e6));
        ImGui.text(playing ? "camera path playing (P stops)" : "WASD QE Shift, right-drag look, P path, F12 shot");
        ImGui.end();
    }

    /** The panel; returns the flow kind index to add when the user presses F over the terrain. */
    void panel() {
        ImGui.setNextWindowPos(8, 150, ImGuiCond.FirstUseEver);
        ImGui.setNextWindowSize(330, 520, ImGuiCond.FirstUseEver);
        ImGui.begin("JEcoSys");
        WindField wind = sim.windField();
        if (ImGui.collapsingHeader("Flows")) {
            for (int i = 0; i < wind.size(); i++) {
                WindSource w = wind.get(i);
                ImGui.pushID(i);
                String kindName = w.def() == null ? "user flow" : w.kind().xmlName();
                if (ImGui.checkbox(w.id() + " (" + kindName + ")", w.isEnabled())) {
                    sim.setFlowEnabled(w, !w.isEnabled());
                }
                if (w.def() == null) {
                    ImGui.popID();
                    continue; // a program's own flow: only its switch is editable here
                }
                edit[0] = (float) w.def().strength();
                if (ImGui.sliderFloat("strength", edit, 0, 20)) {
                    replace(w, edit[0], w.def().influenceRadius());
                }
                double r = w.def().influenceRadius();
                edit[0] = Double.isInfinite(r) ? 0 : (float) r;
                if (ImGui.sliderFloat("radius (0 = unbounded)", edit, 0, 30)) {
                    replace(w, w.def().strength(), edit[0] <= 0 ? Double.POSITIVE_INFINITY : edit[0]);
                }
                ImGui.popID();
            }
            ImGui.separator();
            ImGui.combo("new flow", kind, KINDS);
            ImGui.sliderFloat("new strength", strength, 0.1f, 20);
            ImGui.sliderFloat("new radius", radius, 0.5f, 30);
            ImGui.textWrapped("Press F with the pointer over the terrain to add it there; left-drag pushes plants.");
        }
        if (ImGui.collapsingHeader("Animation")) {
            if (ImGui.combo("mode", mode, MODES)) {
                sim.setMode(AnimationMode.values()[mode.get()]);
            }
            if (ImGui.checkbox("force field", sim.fieldEnabled())) {
                sim.setFieldEnabled(!sim.fieldEnabled());
            }
        }
        RenderSettings s = renderer.settings();
        if (ImGui.collapsingHeader("Level of detail")) {
            PlantBatches b = renderer.plants().batches();
            for (int sp = 0; sp < b.speciesCount(); sp++) {
                if (b.levels(sp) != 3) {
                    continue;
                }
                lod[0] = (float) b.edge(sp, 0);
                lod[1] = (float) b.edge(sp, 1);
                if (ImGui.sliderFloat2(def.species().get(sp).id(), lod, 1, 60)) {
                    edges[0] = Math.max(0.5, lod[0]);
                    edges[1] = Math.max(edges[0] + 0.5, lod[1]);
                    b.setLodDistances(sp, edges);
                }
            }
            edit[0] = (float) s.lodTransition();
            if (ImGui.sliderFloat("transition band (m)", edit, 0, 3)) {
                s.lodTransition(edit[0]);
            }
        }
        if (ImGui.collapsingHeader("Overlays")) {
            if (ImGui.checkbox("force-field quadtree (Fig. 2)", s.showField())) {
                s.showField(!s.showField());
            }
            if (ImGui.checkbox("wind vectors (Fig. 3)", s.showWind())) {
                s.showWind(!s.showWind());
            }
            if (ImGui.combo("terrain tint", tint, TINTS)) {
                s.tint(TerrainTint.values()[tint.get()]);
            }
        }
        if (ImGui.button("Save scene")) {
            save();
        }
        if (!message.isEmpty()) {
            ImGui.textWrapped(message);
        }
        ImGui.end();
    }

    /** Replaces a flow by one with a new strength and radius (applied at the next step). */
    private void replace(WindSource w, double strength, double radius) {
        FlowDef d = w.def();
        FlowDef n = new FlowDef(d.id(), d.kind(), w.isEnabled(), w.centreX(), w.centreZ(), strength, d.direction(),
                d.coreRadius(), radius, d.activation(), d.motion(), d.noiseScale(), d.noiseFrequency(), d.seed());
        sim.removeFlow(w);
        sim.addFlow(n);
    }

    /** Adds the selected kind of flow at (x, z) metres; the uniform and gust blow along {@code heading}. */
    void addFlow(double x, double z, double heading) {
        FlowKind k = KIND_VALUES[kind.get()];
        String id = k.xmlName() + "-" + (++added);
        try {
            if (k == FlowKind.BLAST) {
                sim.blast(id, x, z, strength[0] * 4, 1.5);
            } else {
                // heading: yaw 0 looks along -Z; FlowDef direction is radians from +X toward +Z
                double dir = Math.atan2(-Math.cos(heading), Math.sin(heading));
                sim.addFlow(new FlowDef(id, k, true, x, z, strength[0], dir, FlowDef.DEFAULT_CORE_RADIUS, radius[0],
                        ActivationDef.ALWAYS, MotionDef.FIXED, FlowDef.DEFAULT_NOISE_SCALE,
                        FlowDef.DEFAULT_NOISE_FREQUENCY, added));
            }
            message = "added " + id + String.format(" at (%.1f, %.1f)", x, z);
        } catch (RuntimeException e) {
            message = "cannot add " + id + ": " + e.getMessage();
        }
    }

    private void save() {
        WindField wind = sim.windField();
        List<FlowDef> flows = new ArrayList<>();
        for (int i = 0; i < wind.size(); i++) {
            WindSource w = wind.get(i);
            if (w.def() == null || w.kind() == FlowKind.BLAST || w.id().startsWith(Viewer.AGENT_ID)) {
                continue; // a program's own flow, a blast or the drag agent is not part of the scene file
            }
            FlowDef d = w.def();
            flows.add(new FlowDef(d.id(), d.kind(), w.isEnabled(), d.x(), d.z(), d.strength(), d.direction(),
                    d.coreRadius(), d.influenceRadius(), d.activation(), d.motion(), d.noiseScale(),
                    d.noiseFrequency(), d.seed()));
        }
        PlantBatches b = renderer.plants().batches();
        List<SpeciesDef> species = new ArrayList<>();
        for (int sp = 0; sp < def.species().size(); sp++) {
            SpeciesDef sd = def.species().get(sp);
            List<LodDef> lods = new ArrayList<>();
            for (int l = 0; l < sd.lods().size(); l++) {
                double max = l < sd.lods().size() - 1 ? b.edge(sp, l) : Double.POSITIVE_INFINITY;
                lods.add(new LodDef(max, sd.lods().get(l).primitive()));
            }
            species.add(new SpeciesDef(sd.id(), sd.name(), sd.poses(), sd.maxBend(), sd.components(), lods,
                    sd.variation()));
        }
        RenderSettings s = renderer.settings();
        RenderDef r = def.render();
        RenderDef nr = new RenderDef(r.width(), r.height(), s.sky(), s.lodTransition(),
                RenderDef.Tint.values()[s.tint().ordinal()], s.showField(), s.showWind());
        AnimationDef a = def.animation();
        AnimationDef na = new AnimationDef(sim.mode(), a.fixedStep(), a.maxSubSteps(), a.subIntervals(), a.threads(),
                a.seed());
        ForceFieldDef f = def.field();
        ForceFieldDef nf = new ForceFieldDef(sim.fieldEnabled(), f.maxObjectsPerNode(), f.maxDepth(), f.lodDistances());
        SceneDef out = new SceneDef(def.version(), def.name(), def.seed(), def.terrain(), species, def.distributions(),
                def.placements(), flows, nf, def.camera(), na, nr);
        try {
            SceneFiles.save(file, out);
            message = "saved " + file;
        } catch (Exception e) {
            message = "cannot save " + file + ": " + e.getMessage();
        }
    }
}
