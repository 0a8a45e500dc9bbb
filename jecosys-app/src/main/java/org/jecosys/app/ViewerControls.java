package org.jecosys.app;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_1;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_6;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_A;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_BACKSPACE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_D;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_DELETE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_E;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_F;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_F12;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_G;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_H;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_HOME;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_CONTROL;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_P;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_Q;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_RIGHT_CONTROL;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_RIGHT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_S;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_T;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_V;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_W;
import static org.lwjgl.glfw.GLFW.GLFW_MOUSE_BUTTON_LEFT;
import static org.lwjgl.glfw.GLFW.GLFW_MOUSE_BUTTON_RIGHT;

import java.io.IOException;
import java.nio.file.Path;
import java.util.function.Predicate;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Simulation;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.jecosys.wind.WindField;
import org.jecosys.wind.WindSource;

/**
 * What the viewer does with its input, once per frame, without GLFW, GL or ImGui, so that tests
 * drive it headless: the key presses queued by GLFW's callbacks in {@link ViewerInput} are handled
 * in order (a tap shorter than a frame is never missed), the held keys walk the camera, and the mouse
 * picks, selects and drags flows and agents or pushes plants. It also holds the save dialogue's
 * state: a save that needs confirmation ({@link SceneSaver.Plan#confirm()}) waits in
 * {@link #pendingSave()} until {@link #confirmSave()} or {@link #cancelSave()}.
 *
 * <p>Keys ({@link #CONTROLS} lists them for {@code view --help} and the README): W/A/S/D walk, Q/E
 * down/up, Shift faster, Ctrl slower, mouse wheel scales the walking speed, right-drag looks, H or
 * Home frames the scene, P plays the scene's camera path, F adds the chosen flow at the pointer, 1-6
 * choose its kind, T places an agent, left-drag on a gizmo moves its flow or agent, left-drag on the
 * ground pushes plants, Delete removes the selected flow, V shows the wind on the terrain, G the
 * gizmos, Ctrl+S saves, F12 takes a screenshot, Escape deselects, then quits (asking first when
 * there are unsaved changes). Render thread (the viewer's stepping thread); allocates on edits.
 */
final class ViewerControls {
    /** The id of the agent that follows a left-drag on the ground. */
    static final String DRAG_AGENT = "cursor-agent";
    /** The id prefix of agents placed with T. */
    static final String AGENT_PREFIX = "agent-";
    /** Flow kinds F adds, in the order of keys 1-6 and of the panel's list. */
    static final FlowKind[] NEW_KINDS = {FlowKind.UNIFORM, FlowKind.SOURCE, FlowKind.SINK, FlowKind.VORTEX,
        FlowKind.GUST, FlowKind.BLAST};
    /** Seconds a blast added with F lasts. */
    static final double BLAST_SECONDS = 1;
    /** The controls, one per line: {@code view --help} prints them and the README lists them. */
    static final String[] CONTROLS = {
        "W A S D       walk (speed scaled to the terrain, shown in the HUD)",
        "Q E           down, up",
        "Shift, Ctrl   walk 4x faster, 4x slower; mouse wheel: walking speed",
        "right-drag    look around",
        "H or Home     frame the whole scene",
        "P             play or stop the scene's camera path",
        "F             add a flow at the pointer (scaled to the scene)",
        "1 to 6        the flow F adds: uniform source sink vortex gust blast",
        "T             place an agent (a walker pushing plants) at the pointer",
        "left-click    select a flow or agent (its parameters open in the panel)",
        "left-drag     on a gizmo: move its flow or agent; else: push plants",
        "Delete        remove the selected flow or agent",
        "V, G          show or hide the wind arrows, the flow gizmos",
        "Ctrl+S        save (asks before replacing a shipped scene)",
        "F12           screenshot to jecosys-screenshot-NNN.png",
        "Escape        deselect; then quit (asks to save unsaved changes)"};

    private final Simulation sim;
    private final SceneEditor editor;
    private final SceneSaver saver;
    private final FlyCamera fly;
    private final ViewerInput input;
    private final Heightfield ground;
    private final Picker picker;
    private final FlowGizmos gizmos;
    private final FlowDefaults defaults;
    private final double[] hit = new double[2];
    private final Predicate<WindSource> isAgent = w -> w.id().equals(DRAG_AGENT) || w.id().startsWith(AGENT_PREFIX);
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
    private boolean looking;
    private double lastX = Double.NaN;
    private double lastY = Double.NaN;
    private boolean showGizmos = true;
    private boolean showWind = true;
    private boolean screenshot;
    private boolean quitAsked;
    private boolean quit;
    private boolean saveThenQuit;
    private int agents;
    private SceneSaver.Plan pending;
    private String message = "";

    /**
     * Controls for a running scene.
     *
     * @param def    the scene as loaded (its flows set the new flows' scale)
     * @param sim    its simulation
     * @param editor the scene's editor
     * @param saver  where it saves
     * @param fly    the camera
     * @param input  the input queue GLFW's callbacks fill
     */
    ViewerControls(SceneDef def, Simulation sim, SceneEditor editor, SceneSaver saver, FlyCamera fly,
                   ViewerInput input) {
        this.sim = sim;
        this.editor = editor;
        this.saver = saver;
        this.fly = fly;
        this.input = input;
        this.ground = sim.world().terrain().heightfield();
        this.picker = new Picker(ground);
        this.gizmos = new FlowGizmos(ground);
        this.defaults = FlowDefaults.of(ground, def.flows());
        this.newRadius = defaults.radius();
        this.newStrength = defaults.strength(NEW_KINDS[newKind], newRadius);
    }

    /**
     * Handles the input queued since the last frame. Call once per frame, after polling GLFW's
     * events and before stepping the simulation.
     *
     * @param dt       seconds since the last frame
     * @param sx       pointer X, framebuffer pixels from the left
     * @param sy       pointer Y, framebuffer pixels from the top
     * @param width    framebuffer width, pixels
     * @param height   framebuffer height, pixels
     * @param uiKeys   whether the panel has the keyboard (a text field has focus): keys are ignored
     * @param uiMouse  whether the pointer is over the panel: clicks and the wheel are ignored
     */
    void frame(double dt, double sx, double sy, int width, int height, boolean uiKeys, boolean uiMouse) {
        input.beginFrame();
        ViewCamera camera = fly.camera();
        boolean onGround = picker.ground(camera, camera.far(), sx, sy, width, height, hit);
        for (int i = 0; i < input.presses(); i++) {
            int k = input.pressKey(i);
            if (!uiKeys) {
                key(k, input.pressMods(i), onGround);
            } else if (k == GLFW_KEY_F12) {
                screenshot = true; // even while typing or in a dialog
            } else if (k == GLFW_KEY_ESCAPE && (pending != null || quitAsked)) {
                escape(); // a dialog has the keyboard: Escape cancels it
            }
        }
        double dx = Double.isNaN(lastX) ? 0 : sx - lastX;
        double dy = Double.isNaN(lastY) ? 0 : sy - lastY;
        lastX = sx;
        lastY = sy;
        if (input.buttonPressed(GLFW_MOUSE_BUTTON_RIGHT) && !uiMouse) {
            looking = true;
        }
        if (looking && (input.buttonDown(GLFW_MOUSE_BUTTON_RIGHT) || input.buttonPressed(GLFW_MOUSE_BUTTON_RIGHT))) {
            fly.look(dx, dy);
        }
        if (!input.buttonDown(GLFW_MOUSE_BUTTON_RIGHT)) {
            looking = false;
        }
        if (!uiMouse && input.scrolled() != 0) {
            fly.scaleSpeed(input.scrolled());
        }
        boolean ctrl = input.down(GLFW_KEY_LEFT_CONTROL) || input.down(GLFW_KEY_RIGHT_CONTROL);
        boolean shift = input.down(GLFW_KEY_LEFT_SHIFT) || input.down(GLFW_KEY_RIGHT_SHIFT);
        double factor = ctrl && !shift ? FlyCamera.SLOW : shift && !ctrl ? FlyCamera.FAST : 1;
        if (uiKeys) {
            fly.move(dt, 0, 0, 0, factor);
        } else {
            fly.move(dt, input.axis(GLFW_KEY_W, GLFW_KEY_S), input.axis(GLFW_KEY_D, GLFW_KEY_A),
                    input.axis(GLFW_KEY_E, GLFW_KEY_Q), factor);
        }
        // the pointer: hover, select, drag
        int over = uiMouse || !showGizmos ? -1 : picker.gizmo(gizmos.gizmos(), camera, sx, sy, width, height);
        hovered = over < 0 ? null : gizmos.source(over);
        if (input.buttonPressed(GLFW_MOUSE_BUTTON_LEFT) && !uiMouse) {
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
        if (!input.buttonDown(GLFW_MOUSE_BUTTON_LEFT)) {
            release();
        }
    }

    private void key(int key, int mods, boolean onGround) {
        boolean ctrl = (mods & ViewerInput.MOD_CONTROL) != 0;
        if (key == GLFW_KEY_S && ctrl) {
            input.consume(GLFW_KEY_S);
            save();
            return;
        }
        if (key >= GLFW_KEY_1 && key <= GLFW_KEY_6) {
            setNewKind(key - GLFW_KEY_1);
            return;
        }
        switch (key) {
            case GLFW_KEY_ESCAPE -> escape();
            case GLFW_KEY_P -> fly.togglePath();
            case GLFW_KEY_H, GLFW_KEY_HOME -> fly.frameScene();
            case GLFW_KEY_F -> {
                if (onGround) {
                    addFlow(hit[0], hit[1]);
                } else {
                    message = "point at the terrain to add a flow there";
                }
            }
            case GLFW_KEY_T -> {
                if (onGround) {
                    addAgent(hit[0], hit[1]);
                } else {
                    message = "point at the terrain to place an agent there";
                }
            }
            case GLFW_KEY_DELETE, GLFW_KEY_BACKSPACE -> removeSelected();
            case GLFW_KEY_V -> showWind = !showWind;
            case GLFW_KEY_G -> showGizmos = !showGizmos;
            case GLFW_KEY_F12 -> screenshot = true;
            default -> {
                // not a command key
            }
        }
    }

    private void escape() {
        if (pending != null) {
            cancelSave();
        } else if (quitAsked) {
            quitAsked = false;
        } else if (selected != null) {
            selected = null;
        } else {
            requestQuit();
        }
    }

    private void press(int over, boolean onGround) {
        if (over >= 0) {
            WindSource w = gizmos.source(over);
            selected = w.id();
            if (w.def() != null && w.def().motion().kind() == MotionDef.Kind.PATH) {
                message = w.id() + " walks its path; edit its path in the scene file";
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
            FlowDef d = FlowDef.builder(DRAG_AGENT, FlowKind.SOURCE).centre(hit[0], hit[1])
                    .strength(defaults.strength(FlowKind.SOURCE, agentRadius())).coreRadius(agentRadius() / 8)
                    .influenceRadius(agentRadius()).build();
            pusher = sim.attachAgent(d);
        }
    }

    private void release() {
        if (dragging != null) {
            if (dragMoved && editor.flow(dragging) != null) {
                editor.commitMove(dragging, dragX, dragZ);
                message = "moved " + dragging + String.format(" to (%.2f, %.2f)", dragX, dragZ);
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
    private WindSource live(String id) {
        WindSource w = editor.handle(id);
        if (w != null) {
            return w;
        }
        WindField wind = sim.windField();
        int i = wind.indexOf(id);
        return i < 0 ? null : wind.get(i);
    }

    // ---- commands (keys and panel)

    /**
     * Adds the chosen kind of flow at (x, z) metres (rounded to the centimetre) with the panel's
     * strength and radius; a uniform or gust flow blows along the camera's heading (whole degrees).
     */
    void addFlow(double x, double z) {
        FlowKind k = NEW_KINDS[newKind];
        String id = editor.freeId(k.xmlName());
        double cx = Decimals.round(x, 2);
        double cz = Decimals.round(z, 2);
        try {
            if (k == FlowKind.BLAST) {
                sim.blast(id, cx, cz, newStrength, BLAST_SECONDS);
                message = "blast at " + String.format("(%.2f, %.2f)", cx, cz);
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
            message = "added " + id + String.format(" at (%.2f, %.2f)", cx, cz);
        } catch (RuntimeException e) {
            message = "cannot add " + id + ": " + e.getMessage();
        }
    }

    /** Places an agent (a source that is not saved with the scene) at (x, z) metres. */
    void addAgent(double x, double z) {
        String id = AGENT_PREFIX + (++agents);
        double r = agentRadius();
        sim.attachAgent(FlowDef.builder(id, FlowKind.SOURCE).centre(Decimals.round(x, 2), Decimals.round(z, 2))
                .strength(defaults.strength(FlowKind.SOURCE, r)).coreRadius(r / 8).influenceRadius(r)
                .activation(ActivationDef.ALWAYS).build());
        selected = id;
        message = "placed " + id + "; drag it to push plants, Delete removes it";
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
        message = "removed " + selected;
        selected = null;
    }

    /** Chooses the kind F adds (index into {@link #NEW_KINDS}); its strength is reset to the scene's scale. */
    void setNewKind(int index) {
        if (index >= 0 && index < NEW_KINDS.length && index != newKind) {
            newKind = index;
            newStrength = defaults.strength(NEW_KINDS[index], newRadius);
        }
        message = "F adds a " + NEW_KINDS[newKind].xmlName();
    }

    /** Sets the new flows' influence radius from a slider (metres); the strength follows. */
    void setNewRadius(float metres) {
        double r = Decimals.ofFloat(metres);
        if (r > 0 && r != newRadius) {
            newRadius = r;
            newStrength = defaults.strength(NEW_KINDS[newKind], r);
        }
    }

    /** Sets the new flows' strength from a slider. */
    void setNewStrength(float strength) {
        double s = Decimals.ofFloat(strength);
        if (s > 0) {
            newStrength = s;
        }
    }

    /** Saves to the open file (Save); asks first when {@link SceneSaver#plan()} says so. */
    void save() {
        plan(saver.plan());
    }

    /**
     * Saves to another file (Save As); asks first when it exists or is a shipped scene.
     *
     * @param path the file, as typed
     */
    void saveAs(String path) {
        String p = path == null ? "" : path.trim();
        if (p.isEmpty()) {
            message = "type the file to save to";
            return;
        }
        try {
            plan(saver.plan(Path.of(p)));
        } catch (IllegalArgumentException e) { // InvalidPathException included
            message = "cannot save: " + e.getMessage();
        }
    }

    private void plan(SceneSaver.Plan plan) {
        if (plan.confirm()) {
            pending = plan;
            message = "";
        } else {
            write(plan);
        }
    }

    /** Writes the save that was waiting for confirmation. */
    void confirmSave() {
        SceneSaver.Plan p = pending;
        pending = null;
        if (p != null) {
            write(p);
        }
    }

    /** Drops the save that was waiting for confirmation. */
    void cancelSave() {
        pending = null;
        saveThenQuit = false;
        message = "not saved";
    }

    private void write(SceneSaver.Plan plan) {
        try {
            saver.write(plan, editor.snapshot());
            editor.saved();
            message = "saved " + plan.target();
            if (saveThenQuit) {
                quit = true;
            }
        } catch (IOException | RuntimeException e) {
            message = e.getMessage();
            saveThenQuit = false;
        }
    }

    /** Asks to quit: at once when nothing is unsaved, else {@link #quitAsked()} until answered. */
    void requestQuit() {
        if (editor.dirty()) {
            quitAsked = true;
        } else {
            quit = true;
        }
    }

    /**
     * Answers the unsaved-changes question.
     *
     * @param save true: save (asking again if the file is shipped), then quit; false: quit without saving
     */
    void answerQuit(boolean save) {
        quitAsked = false;
        if (save) {
            saveThenQuit = true;
            save();
        } else {
            quit = true;
        }
    }

    /** Keeps the viewer open: the unsaved-changes question was cancelled. */
    void cancelQuit() {
        quitAsked = false;
    }

    // ---- state for the renderer and the panel

    /** Refreshes the gizmos from the flows as they are now (after the step). */
    FlowGizmos gizmos() {
        WindSource sel = selected == null ? null : live(selected);
        gizmos.fill(sim.windField(), isAgent, sel, hovered);
        return gizmos;
    }

    /** {@return the new flows' kind index into {@link #NEW_KINDS}} */
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

    /** {@return the running flow or agent with this id, or null} */
    WindSource source(String id) {
        return id == null ? null : live(id);
    }

    /** {@return whether {@code w} is an agent} */
    boolean isAgent(WindSource w) {
        return isAgent.test(w);
    }

    /** {@return the flow under the pointer, or null} */
    WindSource hovered() {
        return hovered;
    }

    /** {@return whether the gizmos are shown} */
    boolean showGizmos() {
        return showGizmos;
    }

    /** Shows or hides the gizmos. */
    void showGizmos(boolean on) {
        showGizmos = on;
    }

    /** {@return whether the wind arrows are shown on the terrain} */
    boolean showWind() {
        return showWind;
    }

    /** Shows or hides the wind arrows on the terrain. */
    void showWind(boolean on) {
        showWind = on;
    }

    /** {@return whether F12 asked for a screenshot since the last call; clears the request} */
    boolean takeScreenshot() {
        boolean s = screenshot;
        screenshot = false;
        return s;
    }

    /** {@return the save waiting for confirmation, or null} */
    SceneSaver.Plan pendingSave() {
        return pending;
    }

    /** {@return whether the unsaved-changes question is open} */
    boolean quitAsked() {
        return quitAsked;
    }

    /** {@return whether the viewer should close now} */
    boolean quit() {
        return quit;
    }

    /** {@return the last message for the user ("" when none)} */
    String message() {
        return message;
    }

    /** {@return the editor} */
    SceneEditor editor() {
        return editor;
    }

    /** {@return the saver} */
    SceneSaver saver() {
        return saver;
    }
}
