package org.jecosys.render;

import static org.lwjgl.opengl.GL11C.GL_BLEND;
import static org.lwjgl.opengl.GL11C.GL_COLOR_CLEAR_VALUE;
import static org.lwjgl.opengl.GL11C.GL_CULL_FACE;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_FUNC;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_WRITEMASK;
import static org.lwjgl.opengl.GL11C.GL_SCISSOR_BOX;
import static org.lwjgl.opengl.GL11C.GL_SCISSOR_TEST;
import static org.lwjgl.opengl.GL11C.GL_VIEWPORT;
import static org.lwjgl.opengl.GL11C.glClearColor;
import static org.lwjgl.opengl.GL11C.glDepthFunc;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glGetFloatv;
import static org.lwjgl.opengl.GL11C.glGetIntegerv;
import static org.lwjgl.opengl.GL11C.glIsEnabled;
import static org.lwjgl.opengl.GL11C.glScissor;
import static org.lwjgl.opengl.GL11C.glViewport;
import static org.lwjgl.opengl.GL13C.GL_ACTIVE_TEXTURE;
import static org.lwjgl.opengl.GL13C.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13C.glActiveTexture;
import static org.lwjgl.opengl.GL14C.GL_BLEND_DST_ALPHA;
import static org.lwjgl.opengl.GL14C.GL_BLEND_DST_RGB;
import static org.lwjgl.opengl.GL14C.GL_BLEND_SRC_ALPHA;
import static org.lwjgl.opengl.GL14C.GL_BLEND_SRC_RGB;
import static org.lwjgl.opengl.GL14C.glBlendFuncSeparate;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER_BINDING;
import static org.lwjgl.opengl.GL15C.glBindBuffer;
import static org.lwjgl.opengl.GL20C.GL_BLEND_EQUATION_ALPHA;
import static org.lwjgl.opengl.GL20C.GL_BLEND_EQUATION_RGB;
import static org.lwjgl.opengl.GL20C.GL_CURRENT_PROGRAM;
import static org.lwjgl.opengl.GL20C.glBlendEquationSeparate;
import static org.lwjgl.opengl.GL20C.glUseProgram;
import static org.lwjgl.opengl.GL30C.GL_VERTEX_ARRAY_BINDING;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BINDING_BUFFER;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BUFFER;
import static org.lwjgl.opengl.GL11C.glBindTexture;

import static org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER;
import static org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER_BINDING;
import static org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER_SIZE;
import static org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER_START;
import static org.lwjgl.opengl.GL30C.glBindBufferBase;
import static org.lwjgl.opengl.GL30C.glBindBufferRange;

import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import org.lwjgl.opengl.GL43C;
import org.lwjgl.system.MemoryUtil;

/**
 * Saves, and puts back, every piece of GL state the scene renderer changes, so that it composes with a
 * host's own drawing: the program, vertex array and array-buffer bindings, the active texture unit,
 * the buffer textures of the units the renderer uses, the 2D texture of unit {@link #UNIT_2D}, the
 * buffers bound to {@code GL_TEXTURE_BUFFER}, {@code GL_TRANSFORM_FEEDBACK_BUFFER} (generic and index
 * 0) and, on OpenGL 4.3, {@code GL_SHADER_STORAGE_BUFFER} (generic and index 0: the compute resolve
 * pass), rasteriser discard, alpha-to-coverage,
 * the depth test, depth function and depth mask, face culling, blending (switch, factors, equations),
 * the scissor test and box, the clear colour and the viewport. The framebuffer binding is not changed
 * by the renderer and so not saved.
 *
 * <p>Render thread only. {@link #save} and {@link #restore} allocate nothing (the storage is made once
 * in native memory, freed by {@link #close}); each costs about 25 {@code glGet}/{@code glSet} calls,
 * which drivers answer from client-side state.
 */
final class GlStateGuard implements AutoCloseable {
    /**
     * The texture units whose buffer-texture binding the renderer changes: 0 to 7 (poses, component
     * records or instances, render states, static data, links, the components' looks, the species
     * slots' looks, the compute resolve pass's list table).
     */
    static final int UNITS = 8;

    /** The texture unit whose 2D texture binding the renderer changes: the terrain's occlusion map. */
    static final int UNIT_2D = 5;

    private static final int[] CAPS = {GL_DEPTH_TEST, GL_CULL_FACE, GL_BLEND, GL_SCISSOR_TEST,
        org.lwjgl.opengl.GL30C.GL_RASTERIZER_DISCARD, org.lwjgl.opengl.GL13C.GL_SAMPLE_ALPHA_TO_COVERAGE};

    private final IntBuffer ints = MemoryUtil.memAllocInt(32);
    private final GlInts query = new GlInts();
    private final FloatBuffer clear = MemoryUtil.memAllocFloat(4);
    private final boolean[] caps = new boolean[CAPS.length];
    private final int[] unitTextures = new int[UNITS];
    private int texture2d;
    private int program;
    private int vertexArray;
    private int arrayBuffer;
    private int textureBuffer;
    private int feedbackBuffer;
    private int feedbackBuffer0;
    private long feedbackStart0;
    private long feedbackSize0;
    /** Whether the context has shader storage buffers (OpenGL 4.3), whose bindings are then kept too. */
    private final boolean storage = org.lwjgl.opengl.GL.getCapabilities().OpenGL43;
    private int storageBuffer;
    private int storageBuffer0;
    private long storageStart0;
    private long storageSize0;
    private int activeTexture;
    private int depthFunc;
    private boolean depthMask;
    private int blendSrcRgb;
    private int blendDstRgb;
    private int blendSrcAlpha;
    private int blendDstAlpha;
    private int blendEqRgb;
    private int blendEqAlpha;
    private boolean closed;

    /** Reads the current state. Render thread; no allocation. */
    void save() {
        program = query.get(GL_CURRENT_PROGRAM);
        vertexArray = query.get(GL_VERTEX_ARRAY_BINDING);
        arrayBuffer = query.get(GL_ARRAY_BUFFER_BINDING);
        textureBuffer = query.get(GL_TEXTURE_BUFFER);
        feedbackBuffer = query.get(GL_TRANSFORM_FEEDBACK_BUFFER_BINDING);
        feedbackBuffer0 = query.get(GL_TRANSFORM_FEEDBACK_BUFFER_BINDING, 0);
        feedbackStart0 = query.get64(GL_TRANSFORM_FEEDBACK_BUFFER_START, 0);
        feedbackSize0 = query.get64(GL_TRANSFORM_FEEDBACK_BUFFER_SIZE, 0);
        if (storage) {
            storageBuffer = query.get(GL43C.GL_SHADER_STORAGE_BUFFER_BINDING);
            storageBuffer0 = query.get(GL43C.GL_SHADER_STORAGE_BUFFER_BINDING, 0);
            storageStart0 = query.get64(GL43C.GL_SHADER_STORAGE_BUFFER_START, 0);
            storageSize0 = query.get64(GL43C.GL_SHADER_STORAGE_BUFFER_SIZE, 0);
        }
        activeTexture = query.get(GL_ACTIVE_TEXTURE);
        for (int u = 0; u < UNITS; u++) {
            glActiveTexture(GL_TEXTURE0 + u);
            unitTextures[u] = query.get(GL_TEXTURE_BINDING_BUFFER);
        }
        glActiveTexture(GL_TEXTURE0 + UNIT_2D);
        texture2d = query.get(org.lwjgl.opengl.GL11C.GL_TEXTURE_BINDING_2D);
        glActiveTexture(activeTexture);
        for (int i = 0; i < CAPS.length; i++) {
            caps[i] = glIsEnabled(CAPS[i]);
        }
        depthFunc = query.get(GL_DEPTH_FUNC);
        depthMask = query.get(GL_DEPTH_WRITEMASK) != 0;
        blendSrcRgb = query.get(GL_BLEND_SRC_RGB);
        blendDstRgb = query.get(GL_BLEND_DST_RGB);
        blendSrcAlpha = query.get(GL_BLEND_SRC_ALPHA);
        blendDstAlpha = query.get(GL_BLEND_DST_ALPHA);
        blendEqRgb = query.get(GL_BLEND_EQUATION_RGB);
        blendEqAlpha = query.get(GL_BLEND_EQUATION_ALPHA);
        ints.clear();
        glGetIntegerv(GL_VIEWPORT, ints.position(0));
        glGetIntegerv(GL_SCISSOR_BOX, ints.position(4));
        ints.position(0);
        glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    }

    /** Viewport x of the last {@link #save}, pixels. */
    int viewportX() {
        return ints.get(0);
    }

    /** Viewport y of the last {@link #save}, pixels (from the bottom). */
    int viewportY() {
        return ints.get(1);
    }

    /** Viewport width of the last {@link #save}, pixels. */
    int viewportWidth() {
        return ints.get(2);
    }

    /** Viewport height of the last {@link #save}, pixels. */
    int viewportHeight() {
        return ints.get(3);
    }

    /** Puts back everything {@link #save} read. Render thread; no allocation. */
    void restore() {
        glUseProgram(program);
        glBindVertexArray(vertexArray);
        glBindBuffer(GL_ARRAY_BUFFER, arrayBuffer);
        glBindBuffer(GL_TEXTURE_BUFFER, textureBuffer);
        if (feedbackSize0 > 0) {
            glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, feedbackBuffer0, feedbackStart0, feedbackSize0);
        } else {
            glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, feedbackBuffer0);
        }
        glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, feedbackBuffer);
        if (storage) {
            if (storageSize0 > 0) {
                glBindBufferRange(GL43C.GL_SHADER_STORAGE_BUFFER, 0, storageBuffer0, storageStart0, storageSize0);
            } else {
                glBindBufferBase(GL43C.GL_SHADER_STORAGE_BUFFER, 0, storageBuffer0);
            }
            glBindBuffer(GL43C.GL_SHADER_STORAGE_BUFFER, storageBuffer);
        }
        for (int u = 0; u < UNITS; u++) {
            glActiveTexture(GL_TEXTURE0 + u);
            glBindTexture(GL_TEXTURE_BUFFER, unitTextures[u]);
        }
        glActiveTexture(GL_TEXTURE0 + UNIT_2D);
        glBindTexture(org.lwjgl.opengl.GL11C.GL_TEXTURE_2D, texture2d);
        glActiveTexture(activeTexture);
        for (int i = 0; i < CAPS.length; i++) {
            if (caps[i]) {
                glEnable(CAPS[i]);
            } else {
                glDisable(CAPS[i]);
            }
        }
        glDepthFunc(depthFunc);
        glDepthMask(depthMask);
        glBlendFuncSeparate(blendSrcRgb, blendDstRgb, blendSrcAlpha, blendDstAlpha);
        glBlendEquationSeparate(blendEqRgb, blendEqAlpha);
        glViewport(ints.get(0), ints.get(1), ints.get(2), ints.get(3));
        glScissor(ints.get(4), ints.get(5), ints.get(6), ints.get(7));
        glClearColor(clear.get(0), clear.get(1), clear.get(2), clear.get(3));
    }

    /** Frees the native storage. Idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            MemoryUtil.memFree((java.nio.Buffer) ints);
            MemoryUtil.memFree((java.nio.Buffer) clear);
            query.close();
        }
    }
}
