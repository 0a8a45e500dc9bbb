package org.jecosys.app;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_B;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_F12;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_H;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_HOME;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_P;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_T;

import org.jecosys.math.ViewCamera;
import org.jecosys.sim.OpenWorld;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;

/**
 * What the viewer does with its input over an open world ({@code <world>}), once per frame, without
 * GLFW, GL or ImGui, so that tests drive it headless. The camera walks as in a scene of one square
 * ({@link WalkControls}: W/A/S/D, Q/E, Shift, Ctrl, the wheel, right-drag), without an edge; the tiles
 * follow it. Keys ({@link #CONTROLS}): P plays the scene's camera path, H or Home returns to the start,
 * T lets a walker go with the camera (an agent {@link #WALKER_AHEAD} metres ahead of the eye that
 * flattens the grass it passes, in every tile it reaches), B sets off a blast ahead, F12 takes a
 * screenshot, Escape quits. An open world is not edited or saved in the viewer: its flows are the
 * scene's and those added here live until the viewer closes.
 *
 * <p>Render thread (the viewer's stepping thread); the walker's move allocates nothing once it has
 * moved in each tile; a blast allocates.
 */
final class OpenWorldControls {
    /** The walker's flow id. */
    static final String WALKER = "walker";
    /** How far ahead of the eye the walker goes, metres along the heading. */
    static final double WALKER_AHEAD = 2.5;
    /** The walker's strength, m^2/s (a source), and its reach, metres. */
    static final double WALKER_STRENGTH = 1.2;
    static final double WALKER_RADIUS = 1.2;
    /** How far ahead a blast goes off, metres; its peak strength, m^2/s; and how long it lasts, seconds. */
    static final double BLAST_AHEAD = 8;
    static final double BLAST_STRENGTH = 40;
    static final double BLAST_SECONDS = 1;
    /** The controls, one per line: {@code view --help} prints them after the scene's and docs/viewer.md lists them. */
    static final String[] CONTROLS = {
        "W A S D, Q E  walk without an edge (4 m/s), down, up",
        "Shift, Ctrl   walk 4x faster, 4x slower; mouse wheel: walking speed",
        "right-drag    look around",
        "H or Home     back to the start",
        "P             play or stop the scene's camera path",
        "T             a walker goes with you, flattening grass; T again stops it",
        "B             a blast 8 m ahead",
        "F12           screenshot to jecosys-screenshot-NNN.png",
        "Escape        quit"};

    private final OpenWorld world;
    private final FlyCamera fly;
    private final ViewerInput input;
    private final WalkControls walk;
    private boolean walker;
    private boolean quit;
    private boolean screenshot;
    private int blasts;
    private String message = "";

    /**
     * Controls over an open world.
     *
     * @param world the open world (flows are added to it)
     * @param fly   the camera, over the world's hills ({@link FlyCamera#unbounded})
     * @param input the input queue GLFW's callbacks fill
     */
    OpenWorldControls(OpenWorld world, FlyCamera fly, ViewerInput input) {
        this.world = world;
        this.fly = fly;
        this.input = input;
        this.walk = new WalkControls(fly, input);
    }

    /**
     * Handles the input queued since the last frame, then moves the walker with the camera. Call once
     * per frame, after polling GLFW's events and before stepping the world.
     *
     * @param dt      seconds since the last frame
     * @param sx      pointer X, framebuffer pixels from the left
     * @param sy      pointer Y, framebuffer pixels from the top
     * @param uiKeys  whether the HUD has the keyboard: keys are ignored
     * @param uiMouse whether the pointer is over the HUD: the wheel and look drags are ignored
     */
    void frame(double dt, double sx, double sy, boolean uiKeys, boolean uiMouse) {
        input.beginFrame();
        for (int i = 0; i < input.presses(); i++) {
            int k = input.pressKey(i);
            if (!uiKeys || k == GLFW_KEY_F12 || k == GLFW_KEY_ESCAPE) {
                key(k);
            }
        }
        walk.frame(dt, sx, sy, uiKeys, uiMouse);
        if (walker) {
            world.moveAgent(WALKER, aheadX(WALKER_AHEAD), aheadZ(WALKER_AHEAD));
        }
    }

    private void key(int key) {
        switch (key) {
            case GLFW_KEY_ESCAPE -> quit = true;
            case GLFW_KEY_P -> fly.togglePath();
            case GLFW_KEY_H, GLFW_KEY_HOME -> fly.frameScene();
            case GLFW_KEY_T -> toggleWalker();
            case GLFW_KEY_B -> blast();
            case GLFW_KEY_F12 -> screenshot = true;
            default -> {
                // not a command key
            }
        }
    }

    private void toggleWalker() {
        if (walker) {
            world.removeFlow(WALKER);
            walker = false;
            message = "the walker stopped";
            return;
        }
        world.addFlow(FlowDef.builder(WALKER, FlowKind.SOURCE).centre(aheadX(WALKER_AHEAD), aheadZ(WALKER_AHEAD))
                .strength(WALKER_STRENGTH).coreRadius(WALKER_RADIUS / 8).influenceRadius(WALKER_RADIUS).build());
        walker = true;
        message = "a walker goes " + WALKER_AHEAD + " m ahead of you and flattens the grass (T stops it)";
    }

    private void blast() {
        double x = aheadX(BLAST_AHEAD);
        double z = aheadZ(BLAST_AHEAD);
        world.blast("blast-" + (++blasts), x, z, BLAST_STRENGTH, BLAST_SECONDS);
        message = String.format(java.util.Locale.ROOT, "blast at (%.1f, %.1f)", x, z);
    }

    /** {@return X of the point {@code d} metres ahead of the eye along its heading} (yaw 0 looks along -Z) */
    private double aheadX(double d) {
        ViewCamera c = fly.camera();
        return c.x() + d * Math.sin(c.yaw());
    }

    private double aheadZ(double d) {
        ViewCamera c = fly.camera();
        return c.z() - d * Math.cos(c.yaw());
    }

    /** {@return whether Escape was pressed} */
    boolean quit() {
        return quit;
    }

    /** Asks to quit (the window's close button). */
    void requestQuit() {
        quit = true;
    }

    /** {@return whether the walker goes with the camera} */
    boolean walker() {
        return walker;
    }

    /** {@return whether a screenshot was asked for since the last call} (clears the request) */
    boolean takeScreenshot() {
        boolean s = screenshot;
        screenshot = false;
        return s;
    }

    /** {@return the last command's message, or ""} */
    String message() {
        return message;
    }

    /** Shows {@code m} in the HUD until the next command. */
    void setMessage(String m) {
        message = m;
    }

    FlyCamera fly() {
        return fly;
    }
}
