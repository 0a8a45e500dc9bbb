package org.jecosys.app;

import static org.lwjgl.glfw.GLFW.glfwSetKeyCallback;
import static org.lwjgl.glfw.GLFW.glfwSetMouseButtonCallback;
import static org.lwjgl.glfw.GLFW.glfwSetScrollCallback;

import org.lwjgl.glfw.GLFWKeyCallback;
import org.lwjgl.glfw.GLFWMouseButtonCallback;
import org.lwjgl.glfw.GLFWScrollCallback;

/**
 * GLFW's key, mouse-button and scroll callbacks of the viewer's window, feeding {@link ViewerInput}
 * so that every key event is seen however long the frame (GLFW calls them from
 * {@code glfwPollEvents} on the render thread). Install it before {@link ImGuiLayer}: ImGui's GLFW
 * backend keeps the callbacks it finds and calls them before its own, and puts them back when it
 * closes; {@link #close()} then removes and frees them. Render thread only.
 */
final class GlfwInput implements AutoCloseable {
    private final long window;
    private final GLFWKeyCallback key;
    private final GLFWMouseButtonCallback button;
    private final GLFWScrollCallback scroll;
    private boolean closed;

    GlfwInput(long window, ViewerInput input) {
        this.window = window;
        key = GLFWKeyCallback.create((w, k, scancode, action, mods) -> input.key(k, action, mods));
        button = GLFWMouseButtonCallback.create((w, b, action, mods) -> input.mouseButton(b, action, mods));
        scroll = GLFWScrollCallback.create((w, dx, dy) -> input.scroll(dy));
        glfwSetKeyCallback(window, key);
        glfwSetMouseButtonCallback(window, button);
        glfwSetScrollCallback(window, scroll);
    }

    /** Removes the callbacks from the window and frees them. Idempotent. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        glfwSetKeyCallback(window, null);
        glfwSetMouseButtonCallback(window, null);
        glfwSetScrollCallback(window, null);
        key.free();
        button.free();
        scroll.free();
    }
}
