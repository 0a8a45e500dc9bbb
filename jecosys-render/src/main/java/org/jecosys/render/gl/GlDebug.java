package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL11C.GL_NO_ERROR;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glGetError;
import static org.lwjgl.opengl.GL43C.GL_DEBUG_OUTPUT;
import static org.lwjgl.opengl.GL43C.GL_DEBUG_OUTPUT_SYNCHRONOUS;
import static org.lwjgl.opengl.GL43C.GL_DEBUG_SEVERITY_HIGH;
import static org.lwjgl.opengl.GL43C.GL_DEBUG_TYPE_ERROR;
import static org.lwjgl.opengl.GL43C.GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR;

import org.lwjgl.opengl.GL43C;
import org.lwjgl.opengl.GLCapabilities;
import org.lwjgl.opengl.GLDebugMessageCallback;
import org.lwjgl.opengl.KHRDebug;

/**
 * KHR_debug output (GL 4.3 core, or the extension on 3.3 contexts) recording every error the driver
 * reports, synchronously, so tests can fail on any GL error. Also polls {@code glGetError}. Render
 * thread only. The callback is freed by {@link #close()} (idempotent).
 */
public final class GlDebug implements AutoCloseable {
    private static final int KEEP = 8;

    private final GLDebugMessageCallback callback;
    private final String[] first = new String[KEEP];
    private int errors;
    private boolean closed;

    public GlDebug(GLCapabilities caps) {
        callback = GLDebugMessageCallback.create(this::message);
        if (!install(caps)) {
            callback.free();
            throw new IllegalStateException("GL debug output needs OpenGL 4.3 or KHR_debug; this driver has neither");
        }
    }

    private boolean install(GLCapabilities caps) {
        if (caps.OpenGL43) {
            GL43C.glDebugMessageCallback(callback, 0);
        } else if (caps.GL_KHR_debug) {
            KHRDebug.glDebugMessageCallback(callback, 0);
        } else {
            return false;
        }
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        return true;
    }

    /**
     * Installs the same callback in a new context that replaced the old one (the old context, and
     * its callback registration, are gone); the error record carries on. Render thread, with the new
     * context current; no allocation. A new context without debug output records nothing more.
     *
     * @param caps the new context's capabilities
     */
    public void moveTo(GLCapabilities caps) {
        if (!closed) {
            install(caps);
        }
    }

    /** Frees the callback without a GL call: its context is gone. Idempotent. */
    public void forget() {
        if (!closed) {
            closed = true;
            callback.free();
        }
    }

    private void message(int source, int type, int id, int severity, int length, long message, long user) {
        if (type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR || severity == GL_DEBUG_SEVERITY_HIGH) {
            record("GL debug: type 0x" + Integer.toHexString(type) + " id " + id + ": "
                    + GLDebugMessageCallback.getMessage(length, message));
        }
    }

    private void record(String text) {
        if (errors < KEEP) {
            first[errors] = text;
        }
        errors++;
    }

    /**
     * Drains {@code glGetError} (at most 16 codes) into the error record. Render thread.
     *
     * @return the total error count so far
     */
    public int poll() {
        for (int e = glGetError(), n = 0; e != GL_NO_ERROR && n < 16; e = glGetError(), n++) {
            record("glGetError: 0x" + Integer.toHexString(e));
        }
        return errors;
    }

    /** {@return the number of errors recorded so far} */
    public int errors() {
        return errors;
    }

    /** {@return the first recorded errors (at most 8), one a line; empty when none} Allocates. */
    public String report() {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < Math.min(errors, KEEP); i++) {
            sb.append(first[i]).append('\n');
        }
        return sb.toString();
    }

    /**
     * Fails with the recorded errors if there are any (after {@link #poll()}). Render thread.
     *
     * @param where what ran, for the message, e.g. {@code "SceneRenderer.render"}
     * @throws IllegalStateException listing the first errors when any was recorded
     */
    public void check(String where) {
        if (poll() > 0) {
            throw new IllegalStateException(errors + " GL error(s) by " + where + ":\n" + report());
        }
    }

    @Override
    public void close() {
        if (!closed) {
            closed = true;
            GL43C.glDisable(GL_DEBUG_OUTPUT);
            callback.free();
        }
    }
}
