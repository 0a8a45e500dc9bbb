package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL11C.GL_BLEND;
import static org.lwjgl.opengl.GL11C.GL_COLOR_CLEAR_VALUE;
import static org.lwjgl.opengl.GL11C.GL_COLOR_LOGIC_OP;
import static org.lwjgl.opengl.GL11C.GL_COLOR_WRITEMASK;
import static org.lwjgl.opengl.GL11C.GL_CULL_FACE;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_FUNC;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_WRITEMASK;
import static org.lwjgl.opengl.GL11C.GL_FILL;
import static org.lwjgl.opengl.GL11C.GL_FRONT_AND_BACK;
import static org.lwjgl.opengl.GL11C.GL_FRONT_FACE;
import static org.lwjgl.opengl.GL11C.GL_CCW;
import static org.lwjgl.opengl.GL11C.GL_POLYGON_MODE;
import static org.lwjgl.opengl.GL11C.GL_POLYGON_OFFSET_FILL;
import static org.lwjgl.opengl.GL11C.GL_SCISSOR_BOX;
import static org.lwjgl.opengl.GL11C.GL_SCISSOR_TEST;
import static org.lwjgl.opengl.GL11C.GL_STENCIL_TEST;
import static org.lwjgl.opengl.GL11C.GL_UNPACK_ALIGNMENT;
import static org.lwjgl.opengl.GL11C.GL_UNPACK_ROW_LENGTH;
import static org.lwjgl.opengl.GL11C.GL_UNPACK_SKIP_PIXELS;
import static org.lwjgl.opengl.GL11C.GL_UNPACK_SKIP_ROWS;
import static org.lwjgl.opengl.GL11C.GL_UNPACK_SWAP_BYTES;
import static org.lwjgl.opengl.GL11C.GL_UNPACK_LSB_FIRST;
import static org.lwjgl.opengl.GL11C.GL_VIEWPORT;
import static org.lwjgl.opengl.GL11C.glBindTexture;
import static org.lwjgl.opengl.GL11C.glClearColor;
import static org.lwjgl.opengl.GL11C.glDepthFunc;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glFrontFace;
import static org.lwjgl.opengl.GL11C.glIsEnabled;
import static org.lwjgl.opengl.GL11C.glPixelStorei;
import static org.lwjgl.opengl.GL11C.glPolygonMode;
import static org.lwjgl.opengl.GL11C.glScissor;
import static org.lwjgl.opengl.GL11C.glViewport;
import static org.lwjgl.opengl.GL12C.GL_UNPACK_IMAGE_HEIGHT;
import static org.lwjgl.opengl.GL12C.GL_UNPACK_SKIP_IMAGES;
import static org.lwjgl.opengl.GL13C.GL_ACTIVE_TEXTURE;
import static org.lwjgl.opengl.GL13C.GL_MULTISAMPLE;
import static org.lwjgl.opengl.GL13C.GL_SAMPLE_ALPHA_TO_COVERAGE;
import static org.lwjgl.opengl.GL13C.GL_SAMPLE_ALPHA_TO_ONE;
import static org.lwjgl.opengl.GL13C.GL_SAMPLE_COVERAGE;
import static org.lwjgl.opengl.GL13C.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13C.glActiveTexture;
import static org.lwjgl.opengl.GL14C.GL_BLEND_DST_ALPHA;
import static org.lwjgl.opengl.GL14C.GL_BLEND_DST_RGB;
import static org.lwjgl.opengl.GL14C.GL_BLEND_SRC_ALPHA;
import static org.lwjgl.opengl.GL14C.GL_BLEND_SRC_RGB;
import static org.lwjgl.opengl.GL14C.GL_FUNC_ADD;
import static org.lwjgl.opengl.GL14C.glBlendFuncSeparate;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER_BINDING;
import static org.lwjgl.opengl.GL15C.glBindBuffer;
import static org.lwjgl.opengl.GL20C.GL_BLEND_EQUATION_ALPHA;
import static org.lwjgl.opengl.GL20C.GL_BLEND_EQUATION_RGB;
import static org.lwjgl.opengl.GL20C.GL_CURRENT_PROGRAM;
import static org.lwjgl.opengl.GL20C.glBlendEquationSeparate;
import static org.lwjgl.opengl.GL20C.glUseProgram;
import static org.lwjgl.opengl.GL21C.GL_PIXEL_UNPACK_BUFFER;
import static org.lwjgl.opengl.GL21C.GL_PIXEL_UNPACK_BUFFER_BINDING;
import static org.lwjgl.opengl.GL30C.GL_CLIP_DISTANCE0;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER_SRGB;
import static org.lwjgl.opengl.GL30C.GL_RASTERIZER_DISCARD;
import static org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER;
import static org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER_BINDING;
import static org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER_SIZE;
import static org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER_START;
import static org.lwjgl.opengl.GL30C.GL_VERTEX_ARRAY_BINDING;
import static org.lwjgl.opengl.GL30C.glBindBufferBase;
import static org.lwjgl.opengl.GL30C.glBindBufferRange;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL30C.glColorMaski;
import static org.lwjgl.opengl.GL31C.GL_PRIMITIVE_RESTART;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BINDING_BUFFER;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BUFFER;
import static org.lwjgl.opengl.GL32C.GL_DEPTH_CLAMP;
import static org.lwjgl.opengl.GL32C.GL_SAMPLE_MASK;
import static org.lwjgl.opengl.GL33C.GL_SAMPLER_BINDING;
import static org.lwjgl.opengl.GL33C.glBindSampler;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.opengl.GL43C;
import org.lwjgl.system.MemoryUtil;

/**
 * Saves, and puts back, every piece of GL state the renderers change or depend on, so that they are
 * good guests in a host's context (a game, libGDX, jMonkeyEngine), whose own state caches assume
 * nothing changed behind their back:
 * <ul>
 * <li>bindings: program, vertex array, array buffer, {@code GL_TEXTURE_BUFFER}, pixel-unpack buffer,
 * transform feedback buffer (generic and index 0), on OpenGL 4.3 the shader storage buffer (generic
 * and index 0), the active texture unit and, on units 0 to {@link TextureUnits#GUARDED} - 1, the buffer texture,
 * the 2D texture and the sampler object (and the 2D array on {@link TextureUnits#PLANT_TEXTURES});</li>
 * <li>capabilities: depth test, face culling, blending, scissor test, rasteriser discard,
 * alpha-to-coverage and alpha-to-one, multisampling, stencil test, polygon offset (fill, line, point: Mesa offsets
 * line primitives too), sRGB framebuffer writes,
 * colour logic op, sample mask and sample coverage, primitive restart, depth clamp and the eight clip
 * distances;</li>
 * <li>values: depth function and mask, blend factors and equations, colour masks (draw buffers 0 to 7),
 * front face, polygon mode, polygon offset factor and units, scissor box, clear colour and depth, viewport,
 * and the pixel-unpack store (alignment, row length, skips, image height, byte order) that texture uploads
 * read.</li>
 * </ul>
 * {@link #setGuestState()} then sets what the renderers depend on, whatever the host left: additive
 * blend equations, all colour channels of draw buffer 0 written and none of a host's other draw buffers, no stencil test, polygon offset, logic op, sample mask
 * or coverage, clip distances or depth clamp, filled counter-clockwise front faces, depth cleared to 1,
 * the last vertex provoking, dithering on, multisampling on (the plants' fringe switches it off for its
 * pass and on again), the upload unit ({@link TextureUnits#UPLOAD}) active, no sampler objects
 * on the renderer's units, and sRGB conversion off. The plants' colours are display (sRGB-encoded)
 * values: written unconverted into an sRGB framebuffer they read back exactly as in a linear one (and
 * a host with gamma correction, such as jMonkeyEngine's default, sees the same picture as without).
 * The framebuffer binding and depth range stay the host's (the sun's shadow map binds
 * its own framebuffer for its pass and binds the host's again right after).
 *
 * <p>Render thread only. {@link #save} and {@link #restore} allocate nothing (the storage is made once
 * in native memory, freed by {@link #close}); together about 180 {@code glGet}/{@code glSet} calls
 * a frame, which drivers answer from client-side state.
 */
public final class GlStateGuard implements AutoCloseable {
    /** Draw buffers whose colour masks are saved: every one OpenGL 3.3 guarantees. */
    public static final int DRAW_BUFFERS = 8;

    /** Capabilities saved and put back; those from {@link #OFF} on are switched off by {@link #setGuestState()}. */
    private static final int[] CAPS = {GL_DEPTH_TEST, GL_CULL_FACE, GL_BLEND, GL_SCISSOR_TEST, GL_RASTERIZER_DISCARD,
        GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_MULTISAMPLE,
        GL_STENCIL_TEST, GL_POLYGON_OFFSET_FILL, GL11C.GL_POLYGON_OFFSET_LINE, GL11C.GL_POLYGON_OFFSET_POINT,
        GL_FRAMEBUFFER_SRGB, GL_COLOR_LOGIC_OP, GL_SAMPLE_MASK,
        GL_SAMPLE_COVERAGE, GL_PRIMITIVE_RESTART, GL_DEPTH_CLAMP, GL_CLIP_DISTANCE0, GL_CLIP_DISTANCE0 + 1,
        GL_CLIP_DISTANCE0 + 2, GL_CLIP_DISTANCE0 + 3, GL_CLIP_DISTANCE0 + 4, GL_CLIP_DISTANCE0 + 5,
        GL_CLIP_DISTANCE0 + 6, GL_CLIP_DISTANCE0 + 7};
    /** Index in {@link #CAPS} of the first capability the renderers need off. */
    private static final int OFF = 8;

    /** Pixel-unpack store parameters and their defaults. */
    private static final int[] UNPACK = {GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_PIXELS,
        GL_UNPACK_SKIP_ROWS, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES, GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST};
    private static final int[] UNPACK_DEFAULTS = {4, 0, 0, 0, 0, 0, 0, 0};

    private final IntBuffer ints = MemoryUtil.memAllocInt(32);
    /** The colour write masks of draw buffers 0 to {@link #DRAW_BUFFERS} - 1, four bytes each. */
    private final ByteBuffer mask = MemoryUtil.memAlloc(4 * DRAW_BUFFERS);
    private final GlInts query = new GlInts();
    private final FloatBuffer clear = MemoryUtil.memAllocFloat(4);
    /** The polygon offset factor and units, read into native memory (LWJGL 3.3's glGetFloat allocates). */
    private final FloatBuffer offset = MemoryUtil.memAllocFloat(2);
    private final boolean[] caps = new boolean[CAPS.length];
    private final int[] unpack = new int[UNPACK.length];
    private final int[] unitBufferTextures = new int[TextureUnits.GUARDED];
    private final int[] unitTextures2d = new int[TextureUnits.GUARDED];
    private final int[] unitSamplers = new int[TextureUnits.GUARDED];
    /** The 2D-array binding of {@link TextureUnits#PLANT_TEXTURES}, the one unit the library binds an array on. */
    private int plantTextureArray;
    private int program;
    private int vertexArray;
    private int arrayBuffer;
    private int textureBuffer;
    private int unpackBuffer;
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
    private int frontFace;
    private int polygonMode;
    private double clearDepth;
    private float polygonOffsetFactor;
    private float polygonOffsetUnits;
    private int provokingVertex;
    private boolean dither;
    private boolean closed;

    /** Reads the current state. Render thread; no allocation. */
    public void save() {
        program = query.get(GL_CURRENT_PROGRAM);
        vertexArray = query.get(GL_VERTEX_ARRAY_BINDING);
        arrayBuffer = query.get(GL_ARRAY_BUFFER_BINDING);
        textureBuffer = query.get(GL_TEXTURE_BUFFER);
        unpackBuffer = query.get(GL_PIXEL_UNPACK_BUFFER_BINDING);
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
        for (int u = 0; u < TextureUnits.GUARDED; u++) {
            glActiveTexture(GL_TEXTURE0 + u);
            unitBufferTextures[u] = query.get(GL_TEXTURE_BINDING_BUFFER);
            unitTextures2d[u] = query.get(GL11C.GL_TEXTURE_BINDING_2D);
            unitSamplers[u] = query.get(GL_SAMPLER_BINDING);
            if (u == TextureUnits.PLANT_TEXTURES) {
                plantTextureArray = query.get(org.lwjgl.opengl.GL30C.GL_TEXTURE_BINDING_2D_ARRAY);
            }
        }
        glActiveTexture(activeTexture);
        for (int i = 0; i < CAPS.length; i++) {
            caps[i] = glIsEnabled(CAPS[i]);
        }
        for (int i = 0; i < UNPACK.length; i++) {
            unpack[i] = query.get(UNPACK[i]);
        }
        depthFunc = query.get(GL_DEPTH_FUNC);
        depthMask = query.get(GL_DEPTH_WRITEMASK) != 0;
        blendSrcRgb = query.get(GL_BLEND_SRC_RGB);
        blendDstRgb = query.get(GL_BLEND_DST_RGB);
        blendSrcAlpha = query.get(GL_BLEND_SRC_ALPHA);
        blendDstAlpha = query.get(GL_BLEND_DST_ALPHA);
        blendEqRgb = query.get(GL_BLEND_EQUATION_RGB);
        blendEqAlpha = query.get(GL_BLEND_EQUATION_ALPHA);
        frontFace = query.get(GL_FRONT_FACE);
        polygonMode = query.get(GL_POLYGON_MODE);
        provokingVertex = query.get(org.lwjgl.opengl.GL32C.GL_PROVOKING_VERTEX);
        dither = glIsEnabled(GL11C.GL_DITHER);
        for (int i = 0; i < DRAW_BUFFERS; i++) {
            org.lwjgl.opengl.GL30C.nglGetBooleani_v(GL_COLOR_WRITEMASK, i, MemoryUtil.memAddress(mask) + 4L * i);
        }
        ints.clear();
        GL11C.nglGetIntegerv(GL_VIEWPORT, MemoryUtil.memAddress(ints));
        GL11C.nglGetIntegerv(GL_SCISSOR_BOX, MemoryUtil.memAddress(ints) + 16);
        GL11C.nglGetFloatv(GL_COLOR_CLEAR_VALUE, MemoryUtil.memAddress(clear));
        GL11C.nglGetFloatv(GL11C.GL_DEPTH_CLEAR_VALUE, MemoryUtil.memAddress(clear) + 12); // the 4th float is read back below
        clearDepth = clear.get(3);
        GL11C.nglGetFloatv(GL11C.GL_POLYGON_OFFSET_FACTOR, MemoryUtil.memAddress(offset));
        GL11C.nglGetFloatv(GL11C.GL_POLYGON_OFFSET_UNITS, MemoryUtil.memAddress(offset) + 4);
        polygonOffsetFactor = offset.get(0);
        polygonOffsetUnits = offset.get(1);
        GL11C.nglGetFloatv(GL_COLOR_CLEAR_VALUE, MemoryUtil.memAddress(clear));
    }

    /**
     * Sets the state the renderers depend on whatever the host left (see the class comment). Call
     * after {@link #save()}; {@link #restore()} puts the host's back. Render thread; no allocation.
     */
    public void setGuestState() {
        for (int i = OFF; i < CAPS.length; i++) {
            glDisable(CAPS[i]);
        }
        glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
        glColorMaski(0, true, true, true, true);
        for (int i = 1; i < DRAW_BUFFERS; i++) {
            glColorMaski(i, false, false, false, false); // a host's other draw buffers (a G-buffer) stay as they are
        }
        glEnable(GL_MULTISAMPLE); // on a multisampled target the plants' cores go to its samples
        glFrontFace(GL_CCW);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        GL11C.glClearDepth(1.0);
        org.lwjgl.opengl.GL32C.glProvokingVertex(org.lwjgl.opengl.GL32C.GL_LAST_VERTEX_CONVENTION);
        glEnable(GL11C.GL_DITHER);
        for (int u = 0; u < TextureUnits.GUARDED; u++) {
            glBindSampler(u, 0);
        }
        glActiveTexture(GL_TEXTURE0 + TextureUnits.UPLOAD); // objects made now are bound on a unit this guard puts back
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        for (int i = 0; i < UNPACK.length; i++) {
            glPixelStorei(UNPACK[i], UNPACK_DEFAULTS[i]);
        }
    }

    /** Viewport x of the last {@link #save}, pixels. */
    public int viewportX() {
        return ints.get(0);
    }

    /** Viewport y of the last {@link #save}, pixels (from the bottom). */
    public int viewportY() {
        return ints.get(1);
    }

    /** Viewport width of the last {@link #save}, pixels. */
    public int viewportWidth() {
        return ints.get(2);
    }

    /** Viewport height of the last {@link #save}, pixels. */
    public int viewportHeight() {
        return ints.get(3);
    }

    /** Puts back everything {@link #save} read. Render thread; no allocation. */
    public void restore() {
        glUseProgram(program);
        glBindVertexArray(vertexArray);
        glBindBuffer(GL_ARRAY_BUFFER, arrayBuffer);
        glBindBuffer(GL_TEXTURE_BUFFER, textureBuffer);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, unpackBuffer);
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
        for (int u = 0; u < TextureUnits.GUARDED; u++) {
            glActiveTexture(GL_TEXTURE0 + u);
            glBindTexture(GL_TEXTURE_BUFFER, unitBufferTextures[u]);
            glBindTexture(GL11C.GL_TEXTURE_2D, unitTextures2d[u]);
            if (u == TextureUnits.PLANT_TEXTURES) {
                glBindTexture(org.lwjgl.opengl.GL30C.GL_TEXTURE_2D_ARRAY, plantTextureArray);
            }
            glBindSampler(u, unitSamplers[u]);
        }
        glActiveTexture(activeTexture);
        for (int i = 0; i < CAPS.length; i++) {
            if (caps[i]) {
                glEnable(CAPS[i]);
            } else {
                glDisable(CAPS[i]);
            }
        }
        for (int i = 0; i < UNPACK.length; i++) {
            glPixelStorei(UNPACK[i], unpack[i]);
        }
        glDepthFunc(depthFunc);
        glDepthMask(depthMask);
        glBlendFuncSeparate(blendSrcRgb, blendDstRgb, blendSrcAlpha, blendDstAlpha);
        glBlendEquationSeparate(blendEqRgb, blendEqAlpha);
        glFrontFace(frontFace);
        glPolygonMode(GL_FRONT_AND_BACK, polygonMode);
        for (int i = 0; i < DRAW_BUFFERS; i++) {
            int o = 4 * i;
            glColorMaski(i, mask.get(o) != 0, mask.get(o + 1) != 0, mask.get(o + 2) != 0, mask.get(o + 3) != 0);
        }
        glViewport(ints.get(0), ints.get(1), ints.get(2), ints.get(3));
        glScissor(ints.get(4), ints.get(5), ints.get(6), ints.get(7));
        glClearColor(clear.get(0), clear.get(1), clear.get(2), clear.get(3));
        GL11C.glClearDepth(clearDepth);
        GL11C.glPolygonOffset(polygonOffsetFactor, polygonOffsetUnits);
        org.lwjgl.opengl.GL32C.glProvokingVertex(provokingVertex);
        if (dither) {
            glEnable(GL11C.GL_DITHER);
        } else {
            glDisable(GL11C.GL_DITHER);
        }
    }

    /** Frees the native storage. Idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            MemoryUtil.memFree((java.nio.Buffer) ints);
            MemoryUtil.memFree((java.nio.Buffer) clear);
            MemoryUtil.memFree((java.nio.Buffer) offset);
            MemoryUtil.memFree((java.nio.Buffer) mask);
            query.close();
        }
    }
}
