package org.jecosys.app;

import java.util.function.Consumer;
import java.util.function.Predicate;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.Simulation;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.jecosys.wind.WindField;
import org.jecosys.wind.WindSource;

/**
 * The flow and agent editing of {@link ViewerControls}: picking the ground and the gizmos under the
 * pointer, selecting, dragging a flow or agent, pushing plants with the cursor agent, adding flows
 * and agents and removing them, and the parameters of the flows F adds. Holds the picker, the
 * gizmos, the scene-scaled defaults, the last ground hit (metres), the selection, the hovered flow,
 * the drag under way and the cursor agent. Render thread (the viewer's stepping thread); allocates on
 * edits only.
 */
final class FlowEditing {
    private final Simulation sim;
    private final SceneEditor editor;
    private final FlyCamera fly;
    private final Picker picker;
    private final FlowGizmos gizmos;
    private final FlowDefaults defaults;
    private final Consumer<String> message;
    private final double[] hit = new double[2];
    private final Predicate<WindSource> isAgent = w -> w.id().equals(ViewerControls.DRAG_AGENT)
            || w.id().startsWith(ViewerControls.AGENT_PREFIX);
    private int newKind = 1;
    private double newRadius;
    private double newStrength;
    private String selected;
    private WindSource hovered;
    private String dragging;
    private double dragDX;
    private double dragDZ;
    private double dragX;
    private double dragZ;
    private boolean dragMoved;
    private WindSource pusher;
    private int agents;

    /**
     * Editing for a running scene.
     *
     * @param ground   the terrain picked against
     * @param defaults the scene-scaled defaults of new flows
     * @param sim      the simulation
     * @param editor   the scene's editor
     * @param fly      the camera (new flows blow along its heading)
     * @param message  sets the message shown to the user
     */
    FlowEditing(Heightfield ground, FlowDefaults defaults, Simulation sim, SceneEditor editor, FlyCamera fly,
                Consumer<String> message) {
        this.sim = sim;
        this.editor = editor;
        this.fly = fly;
        this.message = message;
        this.picker = new Picker(ground);
        this.gizmos = new FlowGizmos(ground);
        this.defaults = defaults;
        this.newRadius = defaults.radius();
        this.newStrength = defaults.strength(ViewerControls.NEW_KINDS[newKind], newRadius);
    }

    /**
     * Picks the ground under the pointer; {@link #hitX()} and {@link #hitZ()} hold the point hit.
     *
     * @param camera the viewer
     * @param sx     pointer X, framebuffer pixels from the left
     * @param sy     pointer Y, framebuffer pixels from the top
     * @param width  framebuffer width, pixels
     * @param height framebuffer height, pixels
     * @return whether the pointer is over the terrain
     */
    boolean pickGround(ViewCamera camera, double sx, double sy, int width, int height) {
        return picker.ground(camera, camera.far(), sx, sy, width, height, hit);
    }

    /** {@return X of the last ground hit, metres} */
    double hitX() {
        return hit[0];
    }

    /** {@return Z of the last ground hit, metres} */
    double hitZ() {
        return hit[1];
    }

    /**
     * The pointer for one frame: hover, select on a left press, drag, push, release.
     *
     * @param camera     the viewer
     * @param sx         pointer X, framebuffer pixels from the left
     * @param sy         pointer Y, framebuffer pixels from the top
     * @param width      framebuffer width, pixels
     * @param height     framebuffer height, pixels
     * @param uiMouse    whether the pointer is over the panel
     * @param showGizmos whether the gizmos are shown (and can be picked)
     * @param pressed    whether the left button was pressed this frame
     * @param down       whether the left button is down
     * @param onGround   whether {@link #pickGround} hit the terrain this frame
     */
    void pointer(ViewCamera camera, double sx, double sy, int width, int height, boolean uiMouse,
                 boolean showGizmos, boolean pressed, boolean down, boolean onGround) {
        int over = uiMouse || !showGizmos ? -1 : picker.gizmo(gizmos.gizmos(), camera, sx, sy, width, height);
        hovered = over < 0 ? null : gizmos.source(over);
        if (pressed && !uiMouse) {
            press(over, onGround);
        }
        if (dragging != null && onGround) {
            double nx = hit[0] + dragDX;
            double nz = hit[1] + dragDZ;
            dragMoved |= Math.abs(nx - dragX) > 1e-6 || Math.abs(nz - dragZ) > 1e-6;
            dragX = nx;
            dragZ = nz;
            WindSource w = live(dragging);
            if (w != null && dragMoved) {
                if (editor.flow(dragging) != null) {
                    editor.dragFlow(dragging, dragX, dragZ);
                } else {
                    sim.moveAgent(w, dragX, dragZ);
                }
            }
        }
        if (pusher != null && onGround) {
            sim.moveAgent(pusher, hit[0], hit[1]);
        }
        if (!down) {
            release();
        }
    }

    private void press(int over, boolean onGround) {
        if (over >= 0) {
            WindSource w = gizmos.source(over);
            selected = w.id();
            if (w.def() != null && w.def().motion().kind() == MotionDef.Kind.PATH) {
                message.accept(w.id() + " walks its path; edit its path in the scene file");
                return;
            }
            if (w.kind() == FlowKind.BLAST || (w.def() == null)) {
                return;
            }
            dragging = w.id();
            dragMoved = false;
            dragX = gizmos.gizmos().x(over);
            dragZ = gizmos.gizmos().z(over);
            if (onGround) {
                dragDX = dragX - hit[0];
                dragDZ = dragZ - hit[1];
            } else {
                dragDX = 0;
                dragDZ = 0;
            }
            return;
        }
        selected = null;
        if (onGround && pusher == null) {
            FlowDef d = FlowDef.builder(ViewerControls.DRAG_AGENT, FlowKind.SOURCE).centre(hit[0], hit[1])
                    .strength(defaults.strength(FlowKind.SOURCE, agentRadius())).coreRadius(agentRadius() / 8)
                    .influenceRadius(agentRadius()).build();
            pusher = sim.attachAgent(d);
        }
    }

    private void release() {
        if (dragging != null) {
            if (dragMoved && editor.flow(dragging) != null) {
                editor.commitMove(dragging, dragX, dragZ);
                message.accept("moved " + dragging + String.format(" to (%.2f, %.2f)", dragX, dragZ));
            }
            dragging = null;
        }
        if (pusher != null) {
            sim.removeFlow(pusher);
            pusher = null;
        }
    }

    /** The radius of an agent: half a new flow's. */
    private double agentRadius() {
        return Decimals.round(Math.max(0.1, defaults.radius() / 2), 2);
    }

    /** The running flow with {@code id}: the editor's handle for a scene flow, else the wind field's. */
    WindSource live(String id) {
        WindSource w = editor.handle(id);
        if (w != null) {
            return w;
        }
        WindField wind = sim.inspect().windField();
        int i = wind.indexOf(id);
        return i < 0 ? null : wind.get(i);
    }

    /**
     * Adds the chosen kind of flow at (x, z) metres (rounded to the centimetre) with the panel's
     * strength and radius; a uniform or gust flow blows along the camera's heading (whole degrees).
     */
    void addFlow(double x, double z) {
        FlowKind k = ViewerControls.NEW_KINDS[newKind];
        String id = editor.freeId(k.xmlName());
        double cx = Decimals.round(x, 2);
        double cz = Decimals.round(z, 2);
        try {
            if (k == FlowKind.BLAST) {
                sim.blast(id, cx, cz, newStrength, ViewerControls.BLAST_SECONDS);
                message.accept("blast at " + String.format("(%.2f, %.2f)", cx, cz));
                return;
            }
            ViewCamera c = fly.camera();
            // yaw 0 looks along -Z; a flow's direction is radians from +X toward +Z
            double heading = Math.toDegrees(Math.atan2(-Math.cos(c.yaw()), Math.sin(c.yaw())));
            FlowDef.Builder b = FlowDef.builder(id, k).centre(cx, cz).strength(newStrength)
                    .direction(Math.toRadians(Math.round(heading)));
            if (k != FlowKind.UNIFORM && k != FlowKind.GUST) {
                b.coreRadius(Math.min(defaults.coreRadius(), newRadius / 4)).influenceRadius(newRadius);
            }
            editor.addFlow(b.build());
            selected = id;
            message.accept("added " + id + String.format(" at (%.2f, %.2f)", cx, cz));
        } catch (RuntimeException e) {
            message.accept("cannot add " + id + ": " + e.getMessage());
        }
    }

    /** Places an agent (a source that is not saved with the scene) at (x, z) metres. */
    void addAgent(double x, double z) {
        String id = ViewerControls.AGENT_PREFIX + (++agents);
        double r = agentRadius();
        sim.attachAgent(FlowDef.builder(id, FlowKind.SOURCE).centre(Decimals.round(x, 2), Decimals.round(z, 2))
                .strength(defaults.strength(FlowKind.SOURCE, r)).coreRadius(r / 8).influenceRadius(r)
                .activation(ActivationDef.ALWAYS).build());
        selected = id;
        message.accept("placed " + id + "; drag it to push plants, Delete removes it");
    }

    /** Removes the selected flow or agent. */
    void removeSelected() {
        if (selected == null) {
            return;
        }
        if (editor.flow(selected) != null) {
            editor.removeFlow(selected);
        } else {
            WindSource w = live(selected);
            if (w != null) {
                sim.removeFlow(w);
            }
        }
        message.accept("removed " + selected);
        selected = null;
    }

    /** Chooses the kind F adds (index into {@link ViewerControls#NEW_KINDS}); its strength is reset to the scene's scale. */
    void setNewKind(int index) {
        if (index >= 0 && index < ViewerControls.NEW_KINDS.length && index != newKind) {
            newKind = index;
            newStrength = defaults.strength(ViewerControls.NEW_KINDS[index], newRadius);
        }
        message.accept("F adds a " + ViewerControls.NEW_KINDS[newKind].xmlName());
    }

    /** Sets the new flows' influence radius from a slider (metres); the strength follows. */
    void setNewRadius(float metres) {
        double r = Decimals.ofFloat(metres);
        if (r > 0 && r != newRadius) {
            newRadius = r;
            newStrength = defaults.strength(ViewerControls.NEW_KINDS[newKind], r);
        }
    }

    /** Sets the new flows' strength from a slider. */
    void setNewStrength(float strength) {
        double s = Decimals.ofFloat(strength);
        if (s > 0) {
            newStrength = s;
        }
    }

    /** Refreshes the gizmos from the flows as they are now (after the step). */
    FlowGizmos gizmos() {
        WindSource sel = selected == null ? null : live(selected);
        gizmos.fill(sim.inspect().windField(), isAgent, sel, hovered);
        return gizmos;
    }

    /** {@return the new flows' kind index into {@link ViewerControls#NEW_KINDS}} */
    int newKind() {
        return newKind;
    }

    /** {@return the new flows' influence radius, metres} */
    double newRadius() {
        return newRadius;
    }

    /** {@return the new flows' strength, m/s or m^2/s} */
    double newStrength() {
        return newStrength;
    }

    /** {@return the scene-scaled defaults} */
    FlowDefaults defaults() {
        return defaults;
    }

    /** {@return the selected flow's id, or null} */
    String selected() {
        return selected;
    }

    /** Selects flow {@code id} (from the panel's list), or nothing. */
    void select(String id) {
        selected = id;
    }

    /** {@return whether {@code w} is an agent} */
    boolean isAgent(WindSource w) {
        return isAgent.test(w);
    }

    /** {@return the flow under the pointer, or null} */
    WindSource hovered() {
        return hovered;
    }
}
