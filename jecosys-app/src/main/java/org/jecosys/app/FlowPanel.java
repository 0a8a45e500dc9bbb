package org.jecosys.app;

import imgui.ImGui;
import imgui.flag.ImGuiTreeNodeFlags;
import imgui.type.ImInt;
import java.util.List;
import org.jecosys.render.overlay.GizmoKind;
import org.jecosys.render.overlay.GizmoRenderer;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.jecosys.wind.WindField;
import org.jecosys.wind.WindSource;

/**
 * The panel's "Flows" section (ImGui): the list of flows and agents with their gizmo colour and
 * switch, every parameter of the selected flow editable live (centre, strength, direction, core and
 * influence radii, activation window and ramps, motion, gust size, frequency, strength and
 * turbulence, seed), the kind, strength and radius
 * of the flow F adds, and the colours of the gizmo kinds. Edits go through {@link SceneEditor}
 * (values kept as the decimal the slider shows). Render thread; allocates labels.
 */
final class FlowPanel {
    private static final String[] NEW_NAMES = {"uniform", "source", "sink", "vortex", "gust", "blast"};
    private static final String[] MOTIONS = {"fixed", "advected by the other flows"};

    private final ViewerControls controls;
    private final SceneEditor editor;
    private final Heightfield ground;
    private final double size;
    private final float[] f = new float[1];
    private final float[] rgba = new float[4];
    private final ImInt combo = new ImInt();
    private final ImInt seed = new ImInt();
    private String note = "";
    private FlowDef current;

    FlowPanel(ViewerControls controls, Heightfield ground) {
        this.controls = controls;
        this.editor = controls.editor();
        this.ground = ground;
        this.size = Math.max(ground.sizeX(), ground.sizeZ());
    }

    /** Draws the section's content (the caller opened the header). */
    void draw(WindField wind) {
        list(wind);
        ImGui.separator();
        String sel = controls.selected();
        if (sel != null) {
            if (editor.flow(sel) != null) {
                edit(sel, editor.flow(sel));
            } else {
                WindSource w = controls.source(sel);
                if (w != null) {
                    ImGui.text(ViewerPanel.safe(sel + (controls.isAgent(w) ? " (agent: not saved with the scene)"
                            : " (not saved)")));
                    if (ImGui.button("Remove " + sel)) {
                        controls.removeSelected();
                    }
                }
            }
            ImGui.separator();
        }
        newFlow();
        if (!note.isEmpty()) {
            ImGui.textWrapped(ViewerPanel.safe(note));
        }
        if (ImGui.treeNode("Gizmo colours")) {
            for (GizmoKind k : GizmoKind.values()) {
                ImGui.colorButton("##" + k, k.red(), k.green(), k.blue(), 1f);
                ImGui.sameLine();
                ImGui.text(k.name().toLowerCase(java.util.Locale.ROOT));
            }
            ImGui.textWrapped("Faint and greyer: not active now (activation window); grey: switched off. "
                    + "The ring is the influence radius, the thin ring the core.");
            ImGui.treePop();
        }
    }

    private void swatch(WindSource w, double time) {
        GizmoRenderer.shade(FlowGizmos.kind(w, controls.isAgent(w)), w.isEnabled(), w.weight(time), rgba);
        ImGui.colorButton("##c" + w.id(), rgba[0], rgba[1], rgba[2], 1f);
        ImGui.sameLine();
    }

    private void list(WindField wind) {
        List<String> ids = editor.flowIds();
        for (String id : ids) {
            FlowDef d = editor.flow(id);
            WindSource w = editor.handle(id);
            ImGui.pushID(id);
            if (w != null) {
                swatch(w, wind.time());
            }
            if (ImGui.checkbox("##on", d.enabled())) {
                editor.setEnabled(id, !d.enabled());
            }
            ImGui.sameLine();
            if (ImGui.selectable(id + " (" + d.kind().xmlName() + ")", id.equals(controls.selected()))) {
                controls.select(id.equals(controls.selected()) ? null : id);
            }
            ImGui.popID();
        }
        for (int i = 0; i < wind.size(); i++) {
            WindSource w = wind.get(i);
            if (editor.flow(w.id()) != null) {
                continue;
            }
            ImGui.pushID(w.id());
            swatch(w, wind.time());
            String what = controls.isAgent(w) ? "agent" : w.kind() == null ? "program's flow" : w.kind().xmlName();
            if (ImGui.selectable(w.id() + " (" + what + ")", w.id().equals(controls.selected()))) {
                controls.select(w.id());
            }
            ImGui.popID();
        }
        if (ids.isEmpty() && wind.size() == 0) {
            ImGui.textDisabled("no flows: press F over the terrain to add one");
        }
    }

    /** Every parameter of scene flow {@code id}; each change replaces the flow live. */
    private void edit(String id, FlowDef d) {
        FlowKind k = d.kind();
        boolean directional = k == FlowKind.UNIFORM || k == FlowKind.GUST;
        String unit = directional ? "m/s" : "m2/s";
        ImGui.text(ViewerPanel.safe("Selected: " + id + " (" + k.xmlName() + ")"));
        ImGui.pushID("edit-" + id);
        ImGui.pushItemWidth(150);
        if (ImGui.checkbox("switched on", d.enabled())) {
            editor.setEnabled(id, !d.enabled());
            d = editor.flow(id);
        }
        FlowDef n = d;
        current = d;
        double def = controls.defaults().strength(k, Double.isInfinite(d.influenceRadius())
                ? controls.defaults().radius() : d.influenceRadius());
        float top = (float) Math.max(4 * def, 2 * Math.abs(d.strength()));
        f[0] = (float) d.strength();
        if (ImGui.sliderFloat("strength (" + unit + ")", f, k == FlowKind.VORTEX ? -top : 0, top, "%.2f")) {
            n = build(n.toBuilder().strength(Decimals.ofFloat(k == FlowKind.VORTEX ? f[0] : Math.max(0, f[0]))));
        }
        if (k == FlowKind.VORTEX) {
            ImGui.sameLine();
            ImGui.textDisabled(d.strength() >= 0 ? "(anticlockwise)" : "(clockwise)");
        }
        if (directional) {
            f[0] = (float) Math.toDegrees(d.direction());
            if (ImGui.sliderFloat("direction (deg, 0 = +X)", f, -180, 360, "%.0f")) {
                n = build(n.toBuilder().direction(Math.toRadians(Decimals.ofFloat(f[0]))));
            }
        }
        f[0] = (float) d.x();
        float half = (float) (0.5 * size);
        if (ImGui.dragFloat("centre x (m)", f, (float) (size / 400), (float) ground.minX(), (float) ground.maxX(), "%.2f")) {
            n = build(n.toBuilder().centre(Decimals.ofFloat(f[0]), n.z()));
        }
        f[0] = (float) d.z();
        if (ImGui.dragFloat("centre z (m)", f, (float) (size / 400), (float) ground.minZ(), (float) ground.maxZ(), "%.2f")) {
            n = build(n.toBuilder().centre(n.x(), Decimals.ofFloat(f[0])));
        }
        if (!directional) {
            f[0] = (float) d.coreRadius();
            if (ImGui.sliderFloat("core radius (m)", f, 0.01f, Math.max(0.02f, half / 2), "%.2f")) {
                n = build(n.toBuilder().coreRadius(Decimals.ofFloat(Math.max(0.01f, f[0]))));
            }
        }
        boolean unbounded = Double.isInfinite(d.influenceRadius());
        if (k != FlowKind.RAIN && ImGui.checkbox("unbounded (no influence radius)", unbounded)) {
            n = build(n.toBuilder().influenceRadius(unbounded ? controls.defaults().radius()
                    : Double.POSITIVE_INFINITY));
        }
        if (!unbounded) {
            f[0] = (float) d.influenceRadius();
            if (ImGui.sliderFloat("influence radius (m)", f, 0.05f, (float) size, "%.2f")) {
                n = build(n.toBuilder().influenceRadius(Decimals.ofFloat(Math.max(0.05f, f[0]))));
            }
        }
        if (ImGui.treeNode("activation")) {
            f[0] = (float) d.activation().start();
            if (ImGui.dragFloat("start (s)", f, 0.1f, 0, 1e6f, "%.2f")) {
                n = build(n.toBuilder().start(Decimals.ofFloat(Math.max(0, f[0]))));
            }
            boolean forever = Double.isInfinite(d.activation().duration());
            if (ImGui.checkbox("forever", forever)) {
                n = build(n.toBuilder().duration(forever ? 10 : Double.POSITIVE_INFINITY));
            }
            if (!forever) {
                f[0] = (float) d.activation().duration();
                if (ImGui.dragFloat("duration (s)", f, 0.1f, 0.01f, 1e6f, "%.2f")) {
                    n = build(n.toBuilder().duration(Decimals.ofFloat(Math.max(0.01f, f[0]))));
                }
            }
            f[0] = (float) d.activation().rampIn();
            if (ImGui.dragFloat("ramp in (s)", f, 0.05f, 0, 1e4f, "%.2f")) {
                n = build(n.toBuilder().ramps(Decimals.ofFloat(Math.max(0, f[0])), n.activation().rampOut()));
            }
            f[0] = (float) d.activation().rampOut();
            if (ImGui.dragFloat("ramp out (s)", f, 0.05f, 0, 1e4f, "%.2f")) {
                n = build(n.toBuilder().ramps(n.activation().rampIn(), Decimals.ofFloat(Math.max(0, f[0]))));
            }
            ImGui.treePop();
        }
        MotionDef m = d.motion();
        if (m.kind() == MotionDef.Kind.PATH) {
            ImGui.text("moves along a path of " + m.waypoints().size() + " waypoints" + (m.loop() ? ", looping" : ""));
            f[0] = (float) m.speed();
            if (ImGui.sliderFloat("path speed (m/s)", f, 0.05f, (float) Math.max(10, 2 * m.speed()), "%.2f")) {
                n = build(n.toBuilder().motion(new MotionDef(MotionDef.Kind.PATH, m.waypoints(),
                        Decimals.ofFloat(Math.max(0.05f, f[0])), m.loop())));
            }
        } else if (!directional) {
            combo.set(m.kind() == MotionDef.Kind.ADVECTED ? 1 : 0);
            if (ImGui.combo("motion", combo, MOTIONS)) {
                n = build(n.toBuilder().advected(combo.get() == 1));
            }
        }
        if (k == FlowKind.GUST || k == FlowKind.RAIN) {
            f[0] = (float) d.noiseScale();
            if (ImGui.sliderFloat(k == FlowKind.GUST ? "gust size (m)" : "drop spacing (m)", f, 0.05f,
                    (float) size, "%.2f")) {
                n = build(n.toBuilder().noiseScale(Decimals.ofFloat(Math.max(0.05f, f[0]))));
            }
            f[0] = (float) d.noiseFrequency();
            if (ImGui.sliderFloat(k == FlowKind.GUST ? "gusts per second (Hz)" : "drops per s per m2", f, 0.01f,
                    5, "%.2f")) {
                n = build(n.toBuilder().noiseFrequency(Decimals.ofFloat(Math.max(0.01f, f[0]))));
            }
            if (k == FlowKind.GUST) {
                f[0] = (float) d.gustStrength();
                if (ImGui.sliderFloat("gust strength (x mean)", f, 0, (float) FlowDef.MAX_GUST_STRENGTH, "%.2f")) {
                    n = build(n.toBuilder().gustStrength(Decimals.ofFloat(Math.max(0, f[0]))));
                }
                f[0] = (float) d.turbulence();
                if (ImGui.sliderFloat("turbulence (eddies)", f, 0, (float) FlowDef.MAX_TURBULENCE, "%.2f")) {
                    n = build(n.toBuilder().turbulence(Decimals.ofFloat(Math.max(0, f[0]))));
                }
            }
            seed.set((int) d.seed());
            if (ImGui.inputInt("seed", seed)) {
                n = build(n.toBuilder().seed(seed.get()));
            }
        }
        ImGui.popItemWidth();
        if (!n.equals(d)) {
            editor.setFlow(id, n);
        }
        if (ImGui.button("Remove " + id)) {
            controls.removeSelected();
        }
        ImGui.popID();
    }

    /** The built def, or the flow's current one with a note when the values are out of range. */
    private FlowDef build(FlowDef.Builder b) {
        try {
            FlowDef d = b.build();
            note = "";
            return d;
        } catch (RuntimeException e) {
            note = e.getMessage();
            return current;
        }
    }

    private void newFlow() {
        ImGui.pushItemWidth(150);
        combo.set(controls.newKind());
        if (ImGui.combo("kind F adds (1-6)", combo, NEW_NAMES)) {
            controls.setNewKind(combo.get());
        }
        FlowKind k = ViewerControls.NEW_KINDS[controls.newKind()];
        boolean directional = k == FlowKind.UNIFORM || k == FlowKind.GUST;
        if (!directional) {
            f[0] = (float) controls.newRadius();
            if (ImGui.sliderFloat("its radius (m)", f, 0.05f, (float) size, "%.2f")) {
                controls.setNewRadius(Math.max(0.05f, f[0]));
            }
        }
        f[0] = (float) controls.newStrength();
        float top = (float) (4 * controls.defaults().strength(k, controls.newRadius()));
        if (ImGui.sliderFloat(directional ? "its speed (m/s)" : "its strength (m2/s)", f, 0.01f, top, "%.2f")) {
            controls.setNewStrength(Math.max(0.01f, f[0]));
        }
        ImGui.popItemWidth();
        ImGui.textWrapped(String.format(java.util.Locale.ROOT, "Scaled to this scene: %s m/s%s. Press F with "
                + "the pointer over the terrain to add it there; T places an agent; left-drag on the ground "
                + "pushes plants.", ViewerPanel.number(controls.defaults().targetSpeed()),
                directional ? "" : " at half the radius"));
    }
}
