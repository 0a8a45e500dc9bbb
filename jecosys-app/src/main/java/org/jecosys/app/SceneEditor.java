package org.jecosys.app;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.plant.LodDef;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.render.RenderSettings;
import org.jecosys.scene.RenderDef;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Simulation;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.WindField;
import org.jecosys.wind.WindSource;

/**
 * The scene as the user edits it in the viewer, and the {@link SceneDef} to save ({@link #snapshot}):
 * the flows (each flow's current def, in the scene's order, new ones appended), the LOD distances,
 * the render settings, the animation mode and the force-field switch. Every edit is applied live
 * (through the {@link Simulation}'s command queue, at its next step: flows, LOD distances and band,
 * mode, field switch; or to the viewer's {@link RenderSettings}) and marks the scene
 * changed ({@link #dirty()}). Values the user sets through a slider are kept as the decimal the
 * slider showed ({@link Decimals#ofFloat}), so a saved LOD distance of 43.146 m reads
 * {@code "43.146"}. Blasts and agents are not part of the scene file. No GL here, so tests drive it
 * headless. Render thread (the viewer's stepping thread); allocates.
 */
final class SceneEditor {
    private final SceneDef def;
    private final Simulation sim;
    private final RenderSettings settings;
    private final double[][] lod;
    private final java.util.Set<String> issued = new java.util.HashSet<>();
    private double lodTransition;
    private final List<String> order = new ArrayList<>();
    private final Map<String, FlowDef> defs = new HashMap<>();
    private final Map<String, WindSource> handles = new HashMap<>();
    private AnimationMode mode;
    private boolean fieldEnabled;
    private boolean dirty;

    /**
     * An editor of a scene running in {@code sim}.
     *
     * @param def      the scene as loaded
     * @param sim      its simulation (its flows are the scene's, before any edit)
     * @param settings the render settings the viewer draws with
     */
    SceneEditor(SceneDef def, Simulation sim, RenderSettings settings) {
        this.def = def;
        this.sim = sim;
        this.settings = settings;
        this.lodTransition = def.render().lodTransition();
        this.mode = sim.inspect().mode();
        this.fieldEnabled = sim.inspect().fieldEnabled();
        lod = new double[def.species().size()][];
        for (int s = 0; s < lod.length; s++) {
            List<LodDef> lods = def.species().get(s).lods();
            lod[s] = new double[Math.max(0, lods.size() - 1)];
            for (int l = 0; l < lod[s].length; l++) {
                lod[s][l] = lods.get(l).maxDistance();
            }
        }
        WindField wind = sim.inspect().windField();
        for (FlowDef f : def.flows()) {
            order.add(f.id());
            defs.put(f.id(), f);
            int i = wind.indexOf(f.id());
            if (i >= 0) {
                handles.put(f.id(), wind.get(i));
            }
        }
    }

    /** {@return whether anything changed since the scene was opened or last saved} */
    boolean dirty() {
        return dirty;
    }

    /** Records that the current state was saved. */
    void saved() {
        dirty = false;
    }

    // ---- flows

    /** {@return the ids of the scene's flows, in file order (a copy)} */
    List<String> flowIds() {
        return new ArrayList<>(order);
    }

    /** {@return the current def of flow {@code id}, or null when the scene has no such flow} */
    FlowDef flow(String id) {
        return defs.get(id);
    }

    /** {@return the live handle of flow {@code id}, or null} */
    WindSource handle(String id) {
        return handles.get(id);
    }

    /** {@return the id of the scene flow whose live handle is {@code w}, or null (a blast, an agent, a program's flow)} */
    String idOf(WindSource w) {
        return w != null && handles.get(w.id()) == w ? w.id() : null;
    }

    /**
     * A flow id not used by the scene or the running simulation: {@code base-1}, {@code base-2}, ...
     *
     * @param base the prefix, e.g. the kind's name
     * @return a free id
     */
    String freeId(String base) {
        WindField wind = sim.inspect().windField();
        for (int n = 1; ; n++) {
            String id = base + "-" + n;
            if (!defs.containsKey(id) && wind.indexOf(id) < 0 && issued.add(id)) {
                return id;
            }
        }
    }

    /**
     * Adds a flow to the scene (live from the next step).
     *
     * @param f the flow; its id must be free ({@link #freeId})
     * @return its id
     */
    String addFlow(FlowDef f) {
        if (defs.containsKey(f.id())) {
            throw new IllegalArgumentException("flow id '" + f.id() + "' is already used");
        }
        handles.put(f.id(), sim.addFlow(f));
        defs.put(f.id(), f);
        order.add(f.id());
        dirty = true;
        return f.id();
    }

    /**
     * Replaces flow {@code id} by {@code f} (same id; any parameter may change), live from the next
     * step. Nothing happens when {@code f} equals the current def.
     *
     * @param id the flow
     * @param f  its new def
     */
    void setFlow(String id, FlowDef f) {
        FlowDef old = defs.get(id);
        if (old == null) {
            throw new IllegalArgumentException("no flow '" + id + "' in the scene");
        }
        if (!f.id().equals(id)) {
            throw new IllegalArgumentException("a flow keeps its id: '" + id + "', got '" + f.id() + "'");
        }
        if (f.equals(old)) {
            return;
        }
        WindSource h = handles.get(id);
        if (h != null) {
            sim.removeFlow(h);
        }
        handles.put(id, sim.addFlow(f));
        defs.put(id, f);
        dirty = true;
    }

    /** Switches flow {@code id} on or off (saved as its {@code enabled} attribute). */
    void setEnabled(String id, boolean enabled) {
        FlowDef old = defs.get(id);
        if (old == null || old.enabled() == enabled) {
            return;
        }
        defs.put(id, old.toBuilder().enabled(enabled).build());
        WindSource h = handles.get(id);
        if (h != null) {
            sim.setFlowEnabled(h, enabled);
        }
        dirty = true;
    }

    /** Moves flow {@code id}'s live centre while it is dragged (not saved until {@link #commitMove}). */
    void dragFlow(String id, double x, double z) {
        WindSource h = handles.get(id);
        if (h != null) {
            sim.moveAgent(h, x, z);
        }
    }

    /** Makes (x, z), rounded to the centimetre, flow {@code id}'s saved centre. */
    void commitMove(String id, double x, double z) {
        FlowDef old = defs.get(id);
        if (old != null) {
            setFlow(id, old.toBuilder().centre(Decimals.round(x, 2), Decimals.round(z, 2)).build());
        }
    }

    /** Removes flow {@code id} from the scene. */
    void removeFlow(String id) {
        if (defs.remove(id) == null) {
            return;
        }
        order.remove(id);
        WindSource h = handles.remove(id);
        if (h != null) {
            sim.removeFlow(h);
        }
        dirty = true;
    }

    // ---- level of detail

    /** {@return the number of LOD distances of species s (its levels less one)} */
    int lodEdges(int s) {
        return lod[s].length;
    }

    /** {@return LOD distance l of species s, metres: where level l ends} */
    double lodEdge(int s, int l) {
        return lod[s][l];
    }

    /**
     * Sets LOD distance l of species s from a slider's float, kept as its shortest decimal; the
     * distances after it are pushed out to stay at least 0.5 m apart.
     *
     * @param s      species index
     * @param l      distance index, in [0, lodEdges(s))
     * @param metres the slider's value
     */
    void setLodEdge(int s, int l, float metres) {
        double[] e = lod[s].clone();
        e[l] = Math.max(l == 0 ? 0.5 : e[l - 1] + 0.5, Decimals.ofFloat(metres));
        for (int k = l + 1; k < e.length; k++) {
            if (e[k] < e[k - 1] + 0.5) {
                e[k] = Decimals.round(e[k - 1] + 0.5, 3);
            }
        }
        if (java.util.Arrays.equals(e, lod[s])) {
            return;
        }
        sim.setLodDistances(s, e);
        lod[s] = e;
        dirty = true;
    }

    /** {@return the LOD transition band, metres} */
    double lodTransition() {
        return lodTransition;
    }

    /** Sets the LOD transition band from a slider's float, metres, in [0, 10]. */
    void setLodTransition(float metres) {
        double v = Math.max(0, Math.min(10, Decimals.ofFloat(metres)));
        if (v != lodTransition) {
            sim.setLodTransition(v);
            lodTransition = v;
            dirty = true;
        }
    }

    // ---- animation, field, overlays

    /** {@return the animation mode the scene will be saved with} */
    AnimationMode mode() {
        return mode;
    }

    /** Sets the animation mode (live from the next step). */
    void setMode(AnimationMode m) {
        if (m != mode) {
            mode = m;
            sim.setMode(m);
            dirty = true;
        }
    }

    /** {@return whether the force field is on} */
    boolean fieldEnabled() {
        return fieldEnabled;
    }

    /** Switches the force field (live from the next step). */
    void setFieldEnabled(boolean on) {
        if (on != fieldEnabled) {
            fieldEnabled = on;
            sim.setFieldEnabled(on);
            dirty = true;
        }
    }

    /** Shows or hides the quadtree map (saved in the scene's render settings). */
    void setShowField(boolean on) {
        if (on != settings.overlays().showField()) {
            settings.overlays().setShowField(on);
            dirty = true;
        }
    }

    /** Shows or hides the wind on the map (saved in the scene's render settings). */
    void setShowWind(boolean on) {
        if (on != settings.overlays().showWind()) {
            settings.overlays().setShowWind(on);
            dirty = true;
        }
    }

    /**
     * Sets the sun's direction (saved in the scene's render light).
     *
     * @param azimuth   radians, in [-2 pi, 2 pi]
     * @param elevation radians, in [0, pi / 2]
     */
    void setSun(double azimuth, double elevation) {
        if (azimuth != settings.lighting().sunAzimuth() || elevation != settings.lighting().sunElevation()) {
            settings.lighting().setSun(azimuth, elevation);
            dirty = true;
        }
    }

    /** Sets the terrain tint (saved in the scene's render settings). */
    void setTint(RenderDef.Tint tint) {
        if (tint != settings.tint()) {
            settings.setTint(tint);
            dirty = true;
        }
    }

    /**
     * The scene as edited: the loaded scene with the current flows, LOD distances, render settings,
     * animation mode and force-field switch.
     *
     * @return a complete scene, as {@link org.jecosys.scene.SceneFiles#save} writes it
     */
    /** {@return the wind sheen the scene file asks for ({@code <light sheen>})} */
    double sceneSheen() {
        return def.render().light().sheen();
    }

    /** {@return the sun shadows' strength the scene file asks for ({@code <light shadows>})} */
    double sceneShadows() {
        return def.render().light().shadows();
    }

    SceneDef snapshot() {
        List<FlowDef> flows = new ArrayList<>();
        for (String id : order) {
            flows.add(defs.get(id));
        }
        List<SpeciesDef> species = new ArrayList<>();
        for (int s = 0; s < def.species().size(); s++) {
            SpeciesDef sd = def.species().get(s);
            List<LodDef> lods = new ArrayList<>();
            for (int l = 0; l < sd.lods().size(); l++) {
                LodDef ld = sd.lods().get(l);
                lods.add(l < lod[s].length ? new LodDef(lod[s][l], ld.primitive()) : ld);
            }
            species.add(new SpeciesDef(sd.id(), sd.name(), sd.poses(), sd.maxBend(), sd.components(), lods,
                    sd.variation(), sd.trail()));
        }
        RenderDef r = def.render();
        RenderDef.Light l = r.light();
        // the panel edits the sun (radians, as the scene's light holds it: an untouched sun saves exactly)
        double az = settings.lighting().sunAzimuth();
        double el = settings.lighting().sunElevation();
        RenderDef.Light nl = new RenderDef.Light(az, el, l.sunColour(), l.sunIntensity(), l.skyZenith(), l.ambient(),
                l.contactShadow(), l.fogStart(), l.fogEnd(), l.sheen(), l.shadows());
        RenderDef nr = new RenderDef(r.width(), r.height(), settings.lighting().sky(), lodTransition,
                settings.tint(), settings.overlays().showField(), settings.overlays().showWind(), nl,
                r.patches(), r.antialiasing(), r.groundCover());
        AnimationDef a = def.animation();
        AnimationDef na = a.withMode(mode);
        ForceFieldDef f = def.field();
        ForceFieldDef nf = f.withEnabled(fieldEnabled); // thinning and the LOD lens kept
        return new SceneDef(def.version(), def.name(), def.seed(), def.terrain(), species, def.distributions(),
                def.placements(), flows, nf, def.camera(), na, nr, def.world());
    }
}
