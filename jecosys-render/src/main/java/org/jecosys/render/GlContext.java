package org.jecosys.render;

import static org.lwjgl.glfw.GLFW.GLFW_CLIENT_API;
import static org.lwjgl.glfw.GLFW.GLFW_CONTEXT_DEBUG;
import static org.lwjgl.glfw.GLFW.GLFW_CONTEXT_VERSION_MAJOR;
import static org.lwjgl.glfw.GLFW.GLFW_CONTEXT_VERSION_MINOR;
import static org.lwjgl.glfw.GLFW.GLFW_FALSE;
import static org.lwjgl.glfw.GLFW.GLFW_OPENGL_API;
import static org.lwjgl.glfw.GLFW.GLFW_OPENGL_CORE_PROFILE;
import static org.lwjgl.glfw.GLFW.GLFW_OPENGL_FORWARD_COMPAT;
import static org.lwjgl.glfw.GLFW.GLFW_OPENGL_PROFILE;
import static org.lwjgl.glfw.GLFW.GLFW_TRUE;
import static org.lwjgl.glfw.GLFW.glfwCreateWindow;
import static org.lwjgl.glfw.GLFW.glfwDefaultWindowHints;
import static org.lwjgl.glfw.GLFW.glfwDestroyWindow;
import static org.lwjgl.glfw.GLFW.glfwInit;
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
import org.jecosys.render.gl.GlDebug;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.GlTracker;

/**
 * The OpenGL 3.3+ core context the renderers draw with, current on the thread that made or wrapped
 * it, which becomes the render thread: every GL call of the renderers made with this object must
 * happen on it ({@link #checkThread()}). Three ways to get one:
 * <ul>
 * <li>{@link #current(DebugOutput)} wraps the context the caller (a game) made current on this thread,
 * with any windowing library: no window is made, no GLFW call is made and no callback is touched;
 * {@link #close()} frees only what the library made (its debug callback, when asked for one) and
 * leaves the context, the window and GLFW to their owner.</li>
 * <li>{@link #headless} makes a context through EGL with no window and no display server, on Mesa's
 * llvmpipe (tests, CI) or a GPU server's driver.</li>
 * <li>{@link #windowed} opens a visible window on the desktop.</li>
 * </ul>
 *
 * <p>{@link #windowed} owns GLFW, which is process-global: one such context at a time; its
 * {@link #close()} (idempotent) destroys the window, frees the error callback and terminates GLFW. A
 * headless context's {@link #close()} destroys its EGL context and display. Close every renderer
 * first (see {@link #tracker()}).
 *
 * <p>A new context: a game may destroy its context and make a new one (jMonkeyEngine's
 * {@code app.restart()} to change the resolution, vsync or samples; a window made again). Every GL
 * object belongs to a context generation ({@link #generation()}); a wrapped context ({@link #current})
 * follows the host's: {@link #follow()}, which {@code SceneRenderer.render} calls first every frame,
 * sees that the LWJGL capabilities current on the render thread are no longer the ones this object
 * was made with (every host makes new ones, {@code GL.createCapabilities()}, for a new context),
 * and then does what {@link #contextReplaced()} does: the objects made so far are abandoned (closing
 * them makes no GL call: their names died with the old context) and the renderers make theirs again
 * in the new context. A host that hands the same capabilities object to a new context calls
 * {@link #contextReplaced()} itself. A context the library made ({@link #headless}, {@link #windowed})
 * is never replaced; once it is {@link #close() closed}, closing a renderer made in it makes no GL call.
 *
 * <p>Each of the three takes a {@link DebugOutput}: whether the library asks for a debug context and
 * turns the GL's KHR_debug messages into exceptions ({@code GlContext.headless(DebugOutput.ON)} in
 * tests, {@code GlContext.current(DebugOutput.OFF)} in a game).
 */
public final class GlContext implements AutoCloseable {
    /**
     * Whether a context's GL debug output is on: a debug context where the library makes one, and a
     * KHR_debug message callback that turns GL errors into exceptions ({@link #debug()}). On costs
     * time on every GL call on some drivers; tests turn it on, games leave it off.
     */
    public enum DebugOutput {
        /** No debug callback; a context the library makes is an ordinary one. */
        OFF,
        /**
         * A debug context (where the library makes it) and a KHR_debug callback that turns GL errors
         * into exceptions; for a wrapped context it replaces the host's callback until {@link #close()}.
         */
        ON;

        /** {@return whether this is {@link #ON}} */
        boolean on() {
            return this == ON;
        }
    }

    private final long window;
    private final Thread thread;
    private final GlTracker tracker = new GlTracker();
    /** The capabilities LWJGL made for the context this object stands for; replaced by {@link #contextReplaced()}. */
    private GLCapabilities caps;
    private final GlDebug debug;
    /** What {@link #close()} releases besides the debug callback; null for a wrapped context. */
    private final Runnable release;
    private final String[] lastGlfwError;
    private boolean closed;

    private GlContext(long window, GLCapabilities caps, GlDebug debug, Runnable release, String[] lastGlfwError) {
        this.window = window;
        this.caps = caps;
        this.debug = debug;
        this.release = release;
        this.lastGlfwError = lastGlfwError;
        this.thread = Thread.currentThread();
    }

    /**
     * Wraps the OpenGL context that is current on the calling thread (made by a game with GLFW, SDL,
     * AWT or anything else), which becomes the render thread of the renderers made with the result.
     * Makes no window and calls no GLFW function; uses the thread's LWJGL capabilities when the host
     * has created them ({@code GL.createCapabilities()}) and creates them otherwise. Allocates.
     *
     * @param debug {@link DebugOutput#ON} to install a KHR_debug message callback that turns GL errors
     *              into exceptions ({@link #debug()}); it replaces the host's debug callback, if any,
     *              until {@link #close()}, so leave it {@link DebugOutput#OFF} unless you want the
     *              library's checks
     * @return a context object that does not own the context: its {@link #close()} leaves the context,
     *         the window and GLFW alone
     * @throws IllegalStateException when no context is current on this thread, or it is older than
     *                               OpenGL 3.3, or LWJGL is older than {@link LwjglVersion#MINIMUM_TEXT}
     * @throws IllegalArgumentException when {@code debug} is null
     */
    public static GlContext current(DebugOutput debug) {
        requireDebug(debug);
        LwjglVersion.require();
        GLCapabilities caps;
        try {
            caps = GL.getCapabilities();
        } catch (IllegalStateException noCaps) {
            try {
                caps = GL.createCapabilities();
            } catch (IllegalStateException | UnsatisfiedLinkError e) {
                throw new IllegalStateException("no OpenGL context is current on thread "
                        + Thread.currentThread().getName() + ": make the game's context current (e.g. "
                        + "glfwMakeContextCurrent) before GlContext.current", e);
            }
        }
        if (!caps.OpenGL33) {
            throw new IllegalStateException("JEcoSys needs OpenGL 3.3 core; the current context is "
                    + glGetString(GL_VERSION));
        }
        GlDebug dbg = debug.on() ? new GlDebug(caps) : null;
        return new GlContext(0, caps, dbg, null, new String[1]);
    }

    private static void requireDebug(DebugOutput debug) {
        if (debug == null) {
            throw new IllegalArgumentException("debug must be DebugOutput.ON or DebugOutput.OFF, got null");
        }
    }

    /**
     * {@return whether a desktop display is available: {@code DISPLAY} or {@code WAYLAND_DISPLAY} is
     * set} Any thread.
     */
    public static boolean hasDisplay() {
        return nonEmpty(System.getenv("DISPLAY")) || nonEmpty(System.getenv("WAYLAND_DISPLAY"));
    }

    private static boolean nonEmpty(String s) {
        return s != null && !s.isEmpty();
    }

    /**
     * A context with no window and no display server, made through EGL (Mesa's surfaceless platform,
     * e.g. llvmpipe; an EGL device on GPU drivers without it): render into a {@link GlFramebuffer} of
     * any size. OpenGL 4.5, else 4.3, else 3.3, core profile. Calls no GLFW function. Fails with a
     * clear message when no context can be made.
     *
     * @param debug whether KHR_debug output is on ({@link #debug()}); tests turn it on
     * @return a context current on this thread, which becomes the render thread; owns the EGL
     *         display and context
     * @throws IllegalStateException when EGL or an OpenGL 3.3 core context cannot be made, or LWJGL is
     *                               older than {@link LwjglVersion#MINIMUM_TEXT}
     * @throws IllegalArgumentException when {@code debug} is null
     */
    public static GlContext headless(DebugOutput debug) {
        requireDebug(debug);
        LwjglVersion.require();
        EglHeadless egl = EglHeadless.create(debug.on());
        GLCapabilities caps;
        try {
            caps = GL.createCapabilities();
            if (!caps.OpenGL33) {
                throw new IllegalStateException("the headless context is older than OpenGL 3.3: " + glGetString(GL_VERSION));
            }
        } catch (RuntimeException e) {
            egl.destroy();
            throw e;
        }
        GlDebug dbg = null;
        if (debug.on()) {
            try {
                dbg = new GlDebug(caps);
            } catch (RuntimeException e) {
                GL.setCapabilities(null);
                egl.destroy();
                throw e;
            }
        }
        return new GlContext(0, caps, dbg, () -> {
            GL.setCapabilities(null);
            egl.destroy();
        }, new String[1]);
    }

    /**
     * A visible desktop window (X11 or Wayland) with an OpenGL 3.3 core context, current on this
     * thread, which becomes the render thread.
     *
     * @param title  window title
     * @param width  client width, pixels
     * @param height client height, pixels
     * @param debug  whether KHR_debug output is on ({@link #debug()})
     * @return the context; owns the window and GLFW
     * @throws IllegalStateException when GLFW or the context cannot be made (e.g. no display)
     * @throws IllegalArgumentException when {@code debug} is null
     */
    public static GlContext windowed(String title, int width, int height, DebugOutput debug) {
        requireDebug(debug);
        LwjglVersion.require();
        return create(title, width, height, debug.on());
    }

    private static GlContext create(String title, int width, int height, boolean debug) {
        String[] last = new String[1];
        GLFWErrorCallback cb = GLFWErrorCallback.create((code, description) ->
                last[0] = "GLFW error 0x" + Integer.toHexString(code) + ": " + GLFWErrorCallback.getDescription(description));
        GLFWErrorCallback previous = glfwSetErrorCallback(cb);
        if (previous != null) {
            previous.free();
        }
        if (!glfwInit()) {
            glfwSetErrorCallback(null);
            cb.free();
            throw new IllegalStateException("cannot initialise GLFW" + (last[0] == null ? "" : ": " + last[0]));
        }
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_CONTEXT_DEBUG, debug ? GLFW_TRUE : GLFW_FALSE);
        long w = glfwCreateWindow(width, height, title, 0, 0);
        if (w == 0) {
            glfwTerminate();
            glfwSetErrorCallback(null);
            cb.free();
            throw new IllegalStateException("cannot create an OpenGL 3.3 core context"
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
        return new GlContext(w, caps, dbg, () -> {
            GL.setCapabilities(null);
            glfwMakeContextCurrent(0);
            glfwDestroyWindow(w);
            glfwTerminate();
            glfwSetErrorCallback(null);
            cb.free();
        }, last);
    }

    /**
     * The GLFW window handle of a {@link #windowed} context, 0 for a headless or wrapped one.
     *
     * @return the window handle, or 0
     */
    public long window() {
        return window;
    }

    static {
        org.jecosys.render.gl.GlContexts.grant(new org.jecosys.render.gl.GlContexts.Access() {
            @Override
            public GlTracker tracker(GlContext gl) {
                return gl.tracker;
            }

            @Override
            public GlDebug debug(GlContext gl) {
                return gl.debug;
            }
        });
    }

    /** The live-object counter shared by every GL wrapper made in this context (internal: {@code GlContexts}). */
    GlTracker tracker() {
        return tracker;
    }

    /** The debug output, or null when made without debug (internal: {@code GlContexts}). */
    GlDebug debug() {
        return debug;
    }

    /**
     * {@return the context generation the renderers' GL objects belong to: 0 at first, one more each
     * time the wrapped context is replaced ({@link #follow()}, {@link #contextReplaced()}) and when a
     * context the library made is closed} Any thread that may call the context's methods; no allocation.
     */
    public int generation() {
        return tracker.generation();
    }

    /**
     * For a wrapped context ({@link #current}): whether the host replaced its context since the last
     * call, told by the LWJGL capabilities current on this thread ({@code GL.getCapabilities()}, a
     * thread-local read) no longer being the ones this object holds; if so, {@link #contextReplaced()}.
     * For a context the library made: nothing. Renderers call it first in every frame and remake their
     * GL objects when the generation changed. Render thread; no allocation unless replaced.
     *
     * @return the current {@link #generation()}
     * @throws IllegalStateException off the render thread, or when no LWJGL capabilities are current
     *                               on it (the host has no context)
     */
    public int follow() {
        checkThread();
        if (release == null && !closed) {
            GLCapabilities now = GL.getCapabilities();
            if (now != caps) {
                replace(now);
            }
        }
        return tracker.generation();
    }

    /**
     * The host destroyed its context and made a new one current on this (the render) thread: takes the
     * new context's LWJGL capabilities, abandons every GL object made so far (closing one makes no GL
     * call) and moves the debug callback, if any, to the new context. The renderers made with this
     * object remake their objects at their next frame (they compare {@link #generation()}). Only for a
     * wrapped context ({@link #current}); {@link #follow()} does this by itself whenever the host made
     * new capabilities, so call this only when the host hands the old capabilities object to the new
     * context. Render thread; allocates nothing itself.
     *
     * @throws IllegalStateException off the render thread, for a context the library made, after
     *                               {@link #close()}, or when no LWJGL capabilities are current
     */
    public void contextReplaced() {
        checkThread();
        if (release != null || closed) {
            throw new IllegalStateException(closed ? "the context is closed"
                    : "a context the library made is never replaced; make a new GlContext instead");
        }
        replace(GL.getCapabilities());
    }

    private void replace(GLCapabilities now) {
        caps = now;
        tracker.abandon();
        if (debug != null) {
            debug.moveTo(now);
        }
    }

    private static GLCapabilities currentCapsOrNull() {
        try {
            return GL.getCapabilities();
        } catch (IllegalStateException none) {
            return null;
        }
    }

    /** {@return the context's LWJGL capabilities} */
    public GLCapabilities capabilities() {
        return caps;
    }

    /**
     * {@return {@code GL_RENDERER + " / " + GL_VERSION}, e.g. "llvmpipe (LLVM 15.0.7, 256 bits) / 4.5
     * (Core Profile) Mesa"} Render thread; allocates.
     */
    public String describe() {
        return glGetString(GL_RENDERER) + " / " + glGetString(GL_VERSION);
    }

    /** Waits until the GL has finished every command issued so far (for frame timing). Render thread. */
    public void finish() {
        checkThread();
        org.lwjgl.opengl.GL11C.glFinish();
    }

    /** {@return the last GLFW error message, or null (always null for a wrapped context)} */
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

    /**
     * Whether this object made the context (and owns the window and GLFW), as opposed to wrapping a
     * host's ({@link #current}).
     *
     * @return true for {@link #headless} and {@link #windowed} contexts
     */
    public boolean ownsContext() {
        return release != null;
    }

    /**
     * Frees what the library made. For a wrapped context ({@link #current}): only the debug callback,
     * if one was asked for; the context, its capabilities, the window and GLFW stay the host's. For a
     * context this class made: also destroys it (a headless one's EGL display; a window and GLFW).
     * Close every renderer first. Render thread; idempotent.
     */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        checkThread();
        closed = true;
        if (debug != null) {
            if (release == null && currentCapsOrNull() != caps) {
                debug.forget(); // the host's context it was installed in is gone
            } else {
                debug.close();
            }
        }
        if (release != null) {
            release.run();
            tracker.abandon(); // the names died with the context: closing a renderer now makes no GL call
        }
    }
}
