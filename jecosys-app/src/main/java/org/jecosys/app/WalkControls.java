package org.jecosys.app;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_A;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_D;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_E;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_CONTROL;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_Q;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_RIGHT_CONTROL;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_RIGHT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_S;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_W;
import static org.lwjgl.glfw.GLFW.GLFW_MOUSE_BUTTON_RIGHT;

/**
 * The camera part of {@link ViewerControls}: right-drag looks, the wheel scales the walking speed,
 * the held keys W/A/S/D/Q/E walk the {@link FlyCamera} (Shift faster, Ctrl slower). Holds whether a
 * look drag is under way and the pointer's last position (framebuffer pixels). Render thread (the
 * viewer's stepping thread); allocates nothing.
 */
final class WalkControls {
    private final FlyCamera fly;
    private final ViewerInput input;
    private boolean looking;
    private double lastX = Double.NaN;
    private double lastY = Double.NaN;

    /**
     * Walking for a camera.
     *
     * @param fly   the camera
     * @param input the input queue GLFW's callbacks fill
     */
    WalkControls(FlyCamera fly, ViewerInput input) {
        this.fly = fly;
        this.input = input;
    }

    /**
     * Looks, scales the speed and walks for one frame.
     *
     * @param dt      seconds since the last frame
     * @param sx      pointer X, framebuffer pixels from the left
     * @param sy      pointer Y, framebuffer pixels from the top
     * @param uiKeys  whether the panel has the keyboard: the camera does not walk
     * @param uiMouse whether the pointer is over the panel: no look drag starts, the wheel is ignored
     */
    void frame(double dt, double sx, double sy, boolean uiKeys, boolean uiMouse) {
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
    }
}
