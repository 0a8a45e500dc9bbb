package org.jecosys.render;

import static org.lwjgl.egl.EGL10.EGL_EXTENSIONS;
import static org.lwjgl.egl.EGL10.EGL_NONE;
import static org.lwjgl.egl.EGL10.EGL_NO_CONTEXT;
import static org.lwjgl.egl.EGL10.EGL_NO_DISPLAY;
import static org.lwjgl.egl.EGL10.EGL_NO_SURFACE;
import static org.lwjgl.egl.EGL12.EGL_RENDERABLE_TYPE;
import static org.lwjgl.egl.EGL10.EGL_SURFACE_TYPE;
import static org.lwjgl.egl.EGL10.EGL_PBUFFER_BIT;
import static org.lwjgl.egl.EGL10.eglChooseConfig;
import static org.lwjgl.egl.EGL10.eglCreateContext;
import static org.lwjgl.egl.EGL10.eglDestroyContext;
import static org.lwjgl.egl.EGL10.eglGetError;
import static org.lwjgl.egl.EGL10.eglInitialize;
import static org.lwjgl.egl.EGL10.eglMakeCurrent;
import static org.lwjgl.egl.EGL10.eglQueryString;
import static org.lwjgl.egl.EGL10.eglTerminate;
import static org.lwjgl.egl.EGL12.eglBindAPI;
import static org.lwjgl.egl.EGL14.EGL_OPENGL_API;
import static org.lwjgl.egl.EGL14.EGL_OPENGL_BIT;
import static org.lwjgl.egl.EGL15.EGL_CONTEXT_MAJOR_VERSION;
import static org.lwjgl.egl.EGL15.EGL_CONTEXT_MINOR_VERSION;
import static org.lwjgl.egl.EGL15.EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT;
import static org.lwjgl.egl.EGL15.EGL_CONTEXT_OPENGL_DEBUG;
import static org.lwjgl.egl.EGL15.EGL_CONTEXT_OPENGL_PROFILE_MASK;

import java.nio.IntBuffer;
import org.lwjgl.PointerBuffer;
import org.lwjgl.egl.EGL;
import org.lwjgl.egl.EGLCapabilities;
import org.lwjgl.system.JNI;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.system.MemoryUtil;

/**
 * An OpenGL core context with no window and no display server, made through EGL directly (not
 * GLFW): on Mesa (llvmpipe) the surfaceless platform, on GPU drivers without it (NVIDIA) the first
 * EGL device that initialises. The renderers draw into framebuffer objects. Works on LWJGL 3.3.3 and
 * 3.4.x alike (GLFW's null platform with EGL does not initialise on 3.3.3). Package-private: reached
 * through {@link GlContext#headless(GlContext.DebugOutput)}. Load time; allocates.
 */
final class EglHeadless {
    /** {@code EGL_PLATFORM_SURFACELESS_MESA} (EGL_MESA_platform_surfaceless). */
    static final int PLATFORM_SURFACELESS_MESA = 0x31DD;
    /** {@code EGL_PLATFORM_DEVICE_EXT} (EGL_EXT_platform_device). */
    static final int PLATFORM_DEVICE_EXT = 0x313F;

    final long display;
    final long context;

    private EglHeadless(long display, long context) {
        this.display = display;
        this.context = context;
    }

    /**
     * Makes a context of OpenGL 4.5, else 4.3, else 3.3 (core) and makes it current on this thread.
     *
     * @param debug whether to ask for a debug context
     * @return the display and context
     * @throws IllegalStateException naming what failed when no context can be made
     */
    static EglHeadless create(boolean debug) {
        EGLCapabilities client;
        try {
            client = EGL.getCapabilities();
        } catch (RuntimeException | UnsatisfiedLinkError e) {
            throw new IllegalStateException("cannot load EGL (libEGL.so.1; on Debian: apt-get install libegl1 "
                    + "libegl-mesa0 libgl1-mesa-dri): " + e.getMessage(), e);
        }
        String extensions = String.valueOf(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS));
        StringBuilder tried = new StringBuilder();
        long display = EGL_NO_DISPLAY;
        if (extensions.contains("EGL_MESA_platform_surfaceless")) {
            display = initialise(platformDisplay(client, PLATFORM_SURFACELESS_MESA, 0), "surfaceless", tried);
        }
        if (display == EGL_NO_DISPLAY && extensions.contains("EGL_EXT_platform_device")
                && client.eglQueryDevicesEXT != 0) {
            display = firstDevice(client, tried);
        }
        if (display == EGL_NO_DISPLAY) {
            throw new IllegalStateException("cannot open an EGL display without a window system (tried: "
                    + (tried.length() == 0 ? "no platform; client extensions " + extensions : tried) + ")");
        }
        try {
            long context = context(display, debug);
            if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
                int err = eglGetError();
                eglDestroyContext(display, context);
                throw new IllegalStateException("eglMakeCurrent without a surface failed: 0x" + Integer.toHexString(err));
            }
            return new EglHeadless(display, context);
        } catch (RuntimeException e) {
            eglTerminate(display);
            throw e;
        }
    }

    /**
     * Releases the context from this thread, destroys it, terminates the display and releases the
     * thread's EGL state (without that, NVIDIA's EGL crashed in its own thread at process exit).
     * Idempotent per object.
     */
    void destroy() {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
        eglTerminate(display);
        org.lwjgl.egl.EGL12.eglReleaseThread();
    }

    /**
     * {@code eglGetPlatformDisplay(platform, nativeDisplay, {EGL_NONE})}, called through its address:
     * LWJGL's wrapper refuses the null native display the surfaceless platform takes.
     */
    private static long platformDisplay(EGLCapabilities client, int platform, long nativeDisplay) {
        long function = client.eglGetPlatformDisplay != 0 ? client.eglGetPlatformDisplay : client.eglGetPlatformDisplayEXT;
        if (function == 0) {
            return EGL_NO_DISPLAY;
        }
        try (MemoryStack s = MemoryStack.stackPush()) {
            PointerBuffer none = s.mallocPointer(1).put(0, EGL_NONE);
            return JNI.callPPP(platform, nativeDisplay, MemoryUtil.memAddress(none), function);
        }
    }

    private static long firstDevice(EGLCapabilities client, StringBuilder tried) {
        try (MemoryStack s = MemoryStack.stackPush()) {
            IntBuffer count = s.mallocInt(1);
            PointerBuffer devices = s.mallocPointer(16);
            if (JNI.callPPI(16, MemoryUtil.memAddress(devices), MemoryUtil.memAddress(count), client.eglQueryDevicesEXT) == 0) {
                tried.append("device enumeration failed; ");
                return EGL_NO_DISPLAY;
            }
            for (int i = 0; i < count.get(0); i++) {
                long d = initialise(platformDisplay(client, PLATFORM_DEVICE_EXT, devices.get(i)), "device " + i, tried);
                if (d != EGL_NO_DISPLAY) {
                    return d;
                }
            }
            return EGL_NO_DISPLAY;
        }
    }

    /** Initialises a display; {@link org.lwjgl.egl.EGL10#EGL_NO_DISPLAY} (noted in {@code tried}) when it cannot be. */
    private static long initialise(long display, String name, StringBuilder tried) {
        if (display == EGL_NO_DISPLAY) {
            tried.append(name).append(": no display; ");
            return EGL_NO_DISPLAY;
        }
        try (MemoryStack s = MemoryStack.stackPush()) {
            if (!eglInitialize(display, s.mallocInt(1), s.mallocInt(1))) {
                tried.append(name).append(": eglInitialize 0x").append(Integer.toHexString(eglGetError())).append("; ");
                return EGL_NO_DISPLAY;
            }
        }
        return display;
    }

    private static long context(long display, boolean debug) {
        if (!eglBindAPI(EGL_OPENGL_API)) {
            throw new IllegalStateException("this EGL has no desktop OpenGL (eglBindAPI: 0x"
                    + Integer.toHexString(eglGetError()) + ")");
        }
        try (MemoryStack s = MemoryStack.stackPush()) {
            IntBuffer attrs = s.ints(EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE);
            PointerBuffer config = s.mallocPointer(1);
            IntBuffer n = s.mallocInt(1);
            if (!eglChooseConfig(display, attrs, config, n) || n.get(0) < 1) {
                throw new IllegalStateException("no EGL config for desktop OpenGL (0x" + Integer.toHexString(eglGetError()) + ")");
            }
            int[][] versions = {{4, 5}, {4, 3}, {3, 3}};
            int err = 0;
            for (int[] v : versions) {
                IntBuffer ca = s.ints(EGL_CONTEXT_MAJOR_VERSION, v[0], EGL_CONTEXT_MINOR_VERSION, v[1],
                        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                        EGL_CONTEXT_OPENGL_DEBUG, debug ? 1 : 0, EGL_NONE);
                long context = eglCreateContext(display, config.get(0), EGL_NO_CONTEXT, ca);
                if (context != EGL_NO_CONTEXT) {
                    return context;
                }
                err = eglGetError();
            }
            throw new IllegalStateException("cannot create an OpenGL 3.3 core context through EGL (0x"
                    + Integer.toHexString(err) + ")");
        }
    }
}
