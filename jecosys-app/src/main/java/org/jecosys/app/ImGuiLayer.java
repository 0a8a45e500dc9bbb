package org.jecosys.app;

import imgui.ImGui;
import imgui.ImGuiIO;
import imgui.gl3.ImGuiImplGl3;
import imgui.glfw.ImGuiImplGlfw;
import imgui.internal.ImGuiContext;
import org.jecosys.render.GlContext;

/**
 * Dear ImGui (imgui-java) on the render thread: the viewer's HUD and panel. With a window
 * ({@code installGlfw}), input and display size come from GLFW; headless (tests), the caller gives
 * the display size and no input. Panels are built between {@link #begin} and {@link #end} with the
 * plain {@code ImGui.*} calls. The GL3 backend's own GL objects (font texture, program, buffers) are
 * released by {@link #close()} (idempotent); {@link org.jecosys.render.gl.GlTracker} does not see them (the tests count them
 * by asking the driver about every name, and check that closing releases them all).
 */
public final class ImGuiLayer implements AutoCloseable {
    private final ImGuiContext context;
    private final ImGuiImplGl3 gl3 = new ImGuiImplGl3();
    private final ImGuiImplGlfw glfw;
    private boolean closed;

    /**
     * Creates the ImGui context and the GL3 backend (GLSL 330 core).
     *
     * @param window      the GLFW window when input should come from it, or 0 (headless)
     */
    public ImGuiLayer(GlContext gl, long window) {
        gl.checkThread();
        context = ImGui.createContext();
        ImGui.getIO().setIniFilename(null);
        if (window != 0) {
            glfw = new ImGuiImplGlfw();
            glfw.init(window, true);
        } else {
            glfw = null;
        }
        gl3.init("#version 330 core");
    }

    /** Whether ImGui wants the mouse (the pointer is over a panel): the viewer then ignores it. */
    public boolean wantsMouse() {
        return ImGui.getIO().getWantCaptureMouse();
    }

    /** Whether ImGui wants the keyboard (a text field has focus). */
    public boolean wantsKeyboard() {
        return ImGui.getIO().getWantCaptureKeyboard();
    }

    /**
     * Starts a frame. Render thread.
     *
     * @param width  display width, pixels (used headless; with GLFW the window's)
     * @param height display height, pixels
     * @param dt     seconds since the last frame, &gt; 0
     */
    public void begin(int width, int height, float dt) {
        ImGuiIO io = ImGui.getIO();
        if (glfw != null) {
            glfw.newFrame();
        } else {
            io.setDisplaySize(width, height);
            io.setDisplayFramebufferScale(1, 1);
        }
        io.setDeltaTime(Math.max(dt, 1e-4f));
        gl3.newFrame();
        ImGui.newFrame();
    }

    /** Ends the frame and draws it into the bound framebuffer. Render thread. */
    public void end() {
        ImGui.render();
        gl3.renderDrawData(ImGui.getDrawData());
    }

    /** Releases the backends and the context. Render thread; idempotent. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        gl3.shutdown();
        if (glfw != null) {
            try {
                glfw.shutdown();
            } catch (RuntimeException e) {
                // imgui-java's GLFW backend can fail freeing cursors a platform never made (Xvfb, null)
            }
        }
        ImGui.destroyContext(context);
    }
}
