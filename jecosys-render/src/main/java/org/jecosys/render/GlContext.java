package org.jecosys.render;

import static org.lwjgl.glfw.GLFW.GLFW_CLIENT_API;
import static org.lwjgl.glfw.GLFW.GLFW_CONTEXT_CREATION_API;
import static org.lwjgl.glfw.GLFW.GLFW_CONTEXT_DEBUG;
import static org.lwjgl.glfw.GLFW.GLFW_CONTEXT_VERSION_MAJOR;
import static org.lwjgl.glfw.GLFW.GLFW_CONTEXT_VERSION_MINOR;
import static org.lwjgl.glfw.GLFW.GLFW_EGL_CONTEXT_API;
import static org.lwjgl.glfw.GLFW.GLFW_FALSE;
import static org.lwjgl.glfw.GLFW.GLFW_OPENGL_API;
import static org.lwjgl.glfw.GLFW.GLFW_OPENGL_CORE_PROFILE;
import static org.lwjgl.glfw.GLFW.GLFW_OPENGL_FORWARD_COMPAT;
import static org.lwjgl.glfw.GLFW.GLFW_OPENGL_PROFILE;
import static org.lwjgl.glfw.GLFW.GLFW_PLATFORM;
import static org.lwjgl.glfw.GLFW.GLFW_PLATFORM_NULL;
import static org.lwjgl.glfw.GLFW.GLFW_TRUE;
import static org.lwjgl.glfw.GLFW.GLFW_VISIBLE;
import static org.lwjgl.glfw.GLFW.glfwCreateWindow;
import static org.lwjgl.glfw.GLFW.glfwDefaultWindowHints;
import static org.lwjgl.glfw.GLFW.glfwDestroyWindow;
import static org.lwjgl.glfw.GLFW.glfwInit;
import static org.lwjgl.glfw.GLFW.glfwInitHint;
import static org.lwjgl.glfw.GLFW.glfwMakeContextCurrent;
import static org.lwjgl.glfw.GLFW.glfwSetErrorCallback;
import static org.lwjgl.glfw.GLFW.glfwTerminate;
import static org.lwjgl.glfw.GLFW.glfwWindowHint;
import static org.lwjgl.opengl.GL11C.GL_RENDERER;
import static org.lwjgl.opengl.GL11C.GL_VERSION;
import static org.lwjgl.opengl.GL11C.glGetString;

import org.lwjgl.glfw.GLFWErrorCallback;
import org.lwjgl.opengl.GL;
import org.lwjgl.opengl.GLCapabilities;

/**
 * A GLFW window with an OpenGL 3.3+ core context, current on the thread that made it, which becomes
 * the render thread: every GL call of the renderers made from this context must happen on it
 * ({@link #checkThread()}). {@link #headless} uses GLFW's null platform with an EGL context, which
 * works on Mesa's llvmpipe with no X server (tests, CI, servers); {@link #windowed} opens a visible
 * window on the desktop.
 *
 * <p>GLFW is process-global: one context at a time. {@link #close()} (idempotent) destroys the
 * window, frees the callbacks and terminates GLFW; close every renderer first (see {@link #tracker()}).
 */
public final class GlContext implements AutoCloseable {
    private final long window;
    private final Thread thread;
    private final GlTracker tracker = new GlTracker();
    private final GLCapabilities caps;
    private final GlDebug debug;
    private final GLFWErrorCallback errorCallback;
    private final String[] lastGlfwError;
    private boolean closed;

    private GlContext(long window, GLCapabilities caps, GlDebug debug, GLFWErrorCallback errorCallback,
                      String[] lastGlfwError) {
        this.window = window;
        this.caps = caps;
        this.debug = debug;
        this.errorCallback = errorCallback;
        this.lastGlfwError = lastGlfwError;
        this.thread = Thread.currentThread();
    }

    /** Whether a desktop display is available: {@code DISPLAY} or {@code WAYLAND_DISPLAY} is set. */
    public static boolean hasDisplay() {
        return nonEmpty(System.getenv("DISPLAY")) || nonEmpty(System.getenv("WAYLAND_DISPLAY"));
    }

    private static boolean nonEmpty(String s) {
        return s != null && !s.isEmpty();
    }

    /**
     * A hidden 16x16 window on GLFW's null platform with an EGL context: render into a
     * {@link GlFramebuffer} of any size. Fails with a clear message when no context can be made.
     *
     * @param debug whether to turn on KHR_debug output ({@link #debug()}); tests do
     */
    public static GlContext headless(boolean debug) {
        return create("jecosys (headless)", 16, 16, true, debug);
    }

    /**
     * A visible desktop window (X11 or Wayland).
     *
     * @param width  client width, pixels
     * @param height client height, pixels
     */
    public static GlContext windowed(String title, int width, int height, boolean debug) {
        return create(title, width, height, false, debug);
    }

    private static GlContext create(String title, int width, int height, boolean headless, boolean debug) {
        String[] last = new String[1];
        GLFWErrorCallback cb = GLFWErrorCallback.create((code, description) ->
                last[0] = "GLFW error 0x" + Integer.toHexString(code) + ": " + GLFWErrorCallback.getDescription(description));
        GLFWErrorCallback previous = glfwSetErrorCallback(cb);
        if (previous != null) {
            previous.free();
        }
        if (headless) {
            glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_NULL);
        }
        if (!glfwInit()) {
            glfwSetErrorCallback(null);
            cb.free();
            throw new IllegalStateException("cannot initialise GLFW" + (headless ? " (null platform)" : "")
                    + (last[0] == null ? "" : ": " + last[0]));
        }
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_CONTEXT_DEBUG, debug ? GLFW_TRUE : GLFW_FALSE);
        if (headless) {
            glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
            glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
        }
        long w = glfwCreateWindow(width, height, title, 0, 0);
        if (w == 0) {
            glfwTerminate();
            glfwSetErrorCallback(null);
            cb.free();
            throw new IllegalStateException("cannot create an OpenGL 3.3 core context"
                    + (headless ? " headless (GLFW null platform + EGL; needs Mesa's EGL, e.g. llvmpipe)" : "")
                    + (last[0] == null ? "" : ": " + last[0]));
        }
        glfwMakeContextCurrent(w);
        GLCapabilities caps = GL.createCapabilities();
        GlDebug dbg = null;
        if (debug) {
            try {
                dbg = new GlDebug(caps);
            } catch (RuntimeException e) {
                GL.setCapabilities(null);
                glfwDestroyWindow(w);
                glfwTerminate();
                glfwSetErrorCallback(null);
                cb.free();
                throw e;
            }
        }
        return new GlContext(w, caps, dbg, cb, last);
    }

    /** The GLFW window handle. */
    public long window() {
        return window;
    }

    /** The live-object counter shared by every GL wrapper made in this context. */
    public GlTracker tracker() {
        return tracker;
    }

    /** The debug output, or null when made without debug. */
    public GlDebug debug() {
        return debug;
    }

    /** The context's capabilities. */
    public GLCapabilities capabilities() {
        return caps;
    }

    /** {@code GL_RENDERER + GL_VERSION}, e.g. "llvmpipe (LLVM 15.0.7, 256 bits) / 4.5 (Core Profile) Mesa". */
    public String describe() {
        return glGetString(GL_RENDERER) + " / " + glGetString(GL_VERSION);
    }

    /** Waits until the GL has finished every command issued so far (for frame timing). Render thread. */
    public void finish() {
        checkThread();
        org.lwjgl.opengl.GL11C.glFinish();
    }

    /** The last GLFW error message, or null. */
    public String lastGlfwError() {
        return lastGlfwError[0];
    }

    /** Fails unless called on the render thread (the thread that made the context). No allocation. */
    public void checkThread() {
        if (Thread.currentThread() != thread) {
            throw new IllegalStateException("GL call off the render thread (" + Thread.currentThread().getName()
                    + "; the context belongs to " + thread.getName() + ")");
        }
    }

    /** Destroys the window and terminates GLFW. Render thread; idempotent. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        checkThread();
        closed = true;
        if (debug != null) {
            debug.close();
        }
        GL.setCapabilities(null);
        glfwMakeContextCurrent(0);
        glfwDestroyWindow(window);
        glfwTerminate();
        glfwSetErrorCallback(null);
        errorCallback.free();
    }
}
