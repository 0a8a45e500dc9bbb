package org.jecosys.app;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_1;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_6;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_BACKSPACE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_DELETE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_F;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_F12;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_G;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_H;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_HOME;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_P;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_S;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_T;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_V;
import static org.lwjgl.glfw.GLFW.GLFW_MOUSE_BUTTON_LEFT;

import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Simulation;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;

/**
 * What the viewer does with its input, once per frame, without GLFW, GL or ImGui, so that tests
 * drive it headless: the key presses queued by GLFW's callbacks in {@link ViewerInput} are handled
 * in order (a tap shorter than a frame is never missed), the held keys walk the camera, and the mouse
 * picks, selects and drags flows and agents or pushes plants. It also holds the save dialogue's
 * state: a save that needs confirmation ({@link SceneSaver.Plan#confirm()}) waits in
 * {@link #pendingSave()} until {@link #confirmSave()} or {@link #cancelSave()}.
 *
 * <p>Keys ({@link #CONTROLS} lists them for {@code view --help} and docs/viewer.md): W/A/S/D walk, Q/E
 * down/up, Shift faster, Ctrl slower, mouse wheel scales the walking speed, right-drag looks, H or
 * Home frames the scene, P plays the scene's camera path, F adds the chosen flow at the pointer, 1-6
 * choose its kind, T places an agent, left-drag on a gizmo moves its flow or agent, left-drag on the
 * ground pushes plants, Delete removes the selected flow, V shows the wind on the terrain, G the
 * gizmos, Ctrl+S saves, F12 takes a screenshot, Escape deselects, then quits (asking first when
 * there are unsaved changes). Render thread (the viewer's stepping thread); allocates on edits.
 *
 * <p>The work is split: {@link WalkControls} moves the camera, {@link FlowEditing} picks, selects,
 * drags and edits flows and agents, {@link SaveQuitState} holds the save and quit dialogues; this
 * class dispatches the keys and holds the view toggles and the message.
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
    /** The controls, one per line: {@code view --help} prints them and docs/viewer.md lists them. */
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

    private final SceneEditor editor;
    private final SceneSaver saver;
    private final FlyCamera fly;
    private final ViewerInput input;
    private final WalkControls walk;
    private final FlowEditing flows;
    private final SaveQuitState dialogs;
    private boolean showGizmos = true;
    private boolean showWind = true;
    private boolean screenshot;
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
        this.editor = editor;
        this.saver = saver;
        this.fly = fly;
        this.input = input;
        Heightfield ground = sim.world().terrain().heightfield();
        this.walk = new WalkControls(fly, input);
        this.flows = new FlowEditing(ground, FlowDefaults.of(ground, def.flows()), sim, editor, fly,
                m -> message = m);
        this.dialogs = new SaveQuitState(editor, saver, m -> message = m);
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
        boolean onGround = flows.pickGround(camera, sx, sy, width, height);
        for (int i = 0; i < input.presses(); i++) {
            int k = input.pressKey(i);
            if (!uiKeys) {
                key(k, input.pressMods(i), onGround);
            } else if (k == GLFW_KEY_F12) {
                screenshot = true; // even while typing or in a dialog
            } else if (k == GLFW_KEY_ESCAPE && (dialogs.pendingSave() != null || dialogs.quitAsked())) {
                escape(); // a dialog has the keyboard: Escape cancels it
            }
        }
        walk.frame(dt, sx, sy, uiKeys, uiMouse);
        flows.pointer(camera, sx, sy, width, height, uiMouse, showGizmos,
                input.buttonPressed(GLFW_MOUSE_BUTTON_LEFT), input.buttonDown(GLFW_MOUSE_BUTTON_LEFT), onGround);
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
                    addFlow(flows.hitX(), flows.hitZ());
                } else {
                    message = "point at the terrain to add a flow there";
                }
            }
            case GLFW_KEY_T -> {
                if (onGround) {
                    addAgent(flows.hitX(), flows.hitZ());
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
        if (dialogs.pendingSave() != null) {
            cancelSave();
        } else if (dialogs.quitAsked()) {
            dialogs.cancelQuit();
        } else if (flows.selected() != null) {
            flows.select(null);
        } else {
            requestQuit();
        }
    }

    // ---- commands (keys and panel)

    /**
     * Adds the chosen kind of flow at (x, z) metres (rounded to the centimetre) with the panel's
     * strength and radius; a uniform or gust flow blows along the camera's heading (whole degrees).
     */
    void addFlow(double x, double z) {
        flows.addFlow(x, z);
    }

    /** Places an agent (a source that is not saved with the scene) at (x, z) metres. */
    void addAgent(double x, double z) {
        flows.addAgent(x, z);
    }

    /** Removes the selected flow or agent. */
    void removeSelected() {
        flows.removeSelected();
    }

    /** Chooses the kind F adds (index into {@link #NEW_KINDS}); its strength is reset to the scene's scale. */
    void setNewKind(int index) {
        flows.setNewKind(index);
    }

    /** Sets the new flows' influence radius from a slider (metres); the strength follows. */
    void setNewRadius(float metres) {
        flows.setNewRadius(metres);
    }

    /** Sets the new flows' strength from a slider. */
    void setNewStrength(float strength) {
        flows.setNewStrength(strength);
    }

    /** Saves to the open file (Save); asks first when {@link SceneSaver#plan()} says so. */
    void save() {
        dialogs.save();
    }

    /**
     * Saves to another file (Save As); asks first when it exists or is a shipped scene.
     *
     * @param path the file, as typed
     */
    void saveAs(String path) {
        dialogs.saveAs(path);
    }

    /** Writes the save that was waiting for confirmation. */
    void confirmSave() {
        dialogs.confirmSave();
    }

    /** Drops the save that was waiting for confirmation. */
    void cancelSave() {
        dialogs.cancelSave();
    }

    /** Asks to quit: at once when nothing is unsaved, else {@link #quitAsked()} until answered. */
    void requestQuit() {
        dialogs.requestQuit();
    }

    /**
     * Answers the unsaved-changes question.
     *
     * @param save true: save (asking again if the file is shipped), then quit; false: quit without saving
     */
    void answerQuit(boolean save) {
        dialogs.answerQuit(save);
    }

    /** Keeps the viewer open: the unsaved-changes question was cancelled. */
    void cancelQuit() {
        dialogs.cancelQuit();
    }

    // ---- state for the renderer and the panel

    /** Refreshes the gizmos from the flows as they are now (after the step). */
    FlowGizmos gizmos() {
        return flows.gizmos();
    }

    /** {@return the new flows' kind index into {@link #NEW_KINDS}} */
    int newKind() {
        return flows.newKind();
    }

    /** {@return the new flows' influence radius, metres} */
    double newRadius() {
        return flows.newRadius();
    }

    /** {@return the new flows' strength, m/s or m^2/s} */
    double newStrength() {
        return flows.newStrength();
    }

    /** {@return the scene-scaled defaults} */
    FlowDefaults defaults() {
        return flows.defaults();
    }

    /** {@return the selected flow's id, or null} */
    String selected() {
        return flows.selected();
    }

    /** Selects flow {@code id} (from the panel's list), or nothing. */
    void select(String id) {
        flows.select(id);
    }

    /** {@return the running flow or agent with this id, or null} */
    WindSource source(String id) {
        return id == null ? null : flows.live(id);
    }

    /** {@return whether {@code w} is an agent} */
    boolean isAgent(WindSource w) {
        return flows.isAgent(w);
    }

    /** {@return the flow under the pointer, or null} */
    WindSource hovered() {
        return flows.hovered();
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
        return dialogs.pendingSave();
    }

    /** {@return whether the unsaved-changes question is open} */
    boolean quitAsked() {
        return dialogs.quitAsked();
    }

    /** {@return whether the viewer should close now} */
    boolean quit() {
        return dialogs.quit();
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
