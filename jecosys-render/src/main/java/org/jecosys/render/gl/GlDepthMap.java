package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_COMPONENT;
import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_LINEAR;
import static org.lwjgl.opengl.GL11C.GL_NONE;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_2D;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_BINDING_2D;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_MAG_FILTER;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_MIN_FILTER;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_WRAP_S;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_WRAP_T;
import static org.lwjgl.opengl.GL11C.glBindTexture;
import static org.lwjgl.opengl.GL11C.glClear;
import static org.lwjgl.opengl.GL11C.glDeleteTextures;
import static org.lwjgl.opengl.GL11C.glDrawBuffer;
import static org.lwjgl.opengl.GL11C.glGenTextures;
import static org.lwjgl.opengl.GL11C.glGetInteger;
import static org.lwjgl.opengl.GL11C.glReadBuffer;
import static org.lwjgl.opengl.GL11C.glTexImage2D;
import static org.lwjgl.opengl.GL11C.glTexParameteri;
import static org.lwjgl.opengl.GL11C.glViewport;
import static org.lwjgl.opengl.GL12C.GL_CLAMP_TO_EDGE;
import static org.lwjgl.opengl.GL13C.GL_ACTIVE_TEXTURE;
import static org.lwjgl.opengl.GL13C.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13C.glActiveTexture;
import static org.lwjgl.opengl.GL14C.GL_DEPTH_COMPONENT24;
import static org.lwjgl.opengl.GL14C.GL_TEXTURE_COMPARE_FUNC;
import static org.lwjgl.opengl.GL14C.GL_TEXTURE_COMPARE_MODE;
import static org.lwjgl.opengl.GL11C.GL_LEQUAL;
import static org.lwjgl.opengl.GL30C.GL_COMPARE_REF_TO_TEXTURE;
import static org.lwjgl.opengl.GL30C.GL_DEPTH_ATTACHMENT;
import static org.lwjgl.opengl.GL30C.GL_DRAW_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_DRAW_FRAMEBUFFER_BINDING;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER_COMPLETE;
import static org.lwjgl.opengl.GL30C.GL_READ_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_READ_FRAMEBUFFER_BINDING;
import static org.lwjgl.opengl.GL30C.glBindFramebuffer;
import static org.lwjgl.opengl.GL30C.glCheckFramebufferStatus;
import static org.lwjgl.opengl.GL30C.glDeleteFramebuffers;
import static org.lwjgl.opengl.GL30C.glFramebufferTexture2D;
import static org.lwjgl.opengl.GL30C.glGenFramebuffers;

/**
 * A square depth texture with a framebuffer that draws into it: a shadow map. Drawn into between
 * {@link #begin()} and {@link #end()}, which put back the framebuffer bindings (draw and read) the
 * host had; read in shaders as a {@code sampler2DShadow} (depth compare {@code LEQUAL}, linear filter:
 * each lookup is a 2x2 percentage-closer filter on hardware that has it), clamped at its edges.
 * Render thread only; allocates at construction, not in {@link #begin()} / {@link #end()}.
 */
public final class GlDepthMap extends GlResource {
    private final int size;
    private Fbo fbo;
    /** Allocation-free queries of the host's bindings (LWJGL's glGetInteger may allocate). */
    private GlInts query = new GlInts();
    private int hostDraw;
    private int hostRead;

    /**
     * Makes the texture ({@code GL_DEPTH_COMPONENT24}) and its framebuffer (no colour buffer). Puts
     * back the active unit, its 2D binding and the framebuffer bindings.
     *
     * @param tracker counts the object
     * @param size    texels along each side, in [16, 8192]
     * @throws IllegalStateException when the framebuffer is incomplete on this GL
     */
    public GlDepthMap(GlTracker tracker, int size) {
        super(tracker, glGenTextures());
        if (size < 16 || size > 8192) {
            close();
            throw new IllegalArgumentException("shadow map size must be in [16, 8192], got " + size);
        }
        this.size = size;
        int unit = glGetInteger(GL_ACTIVE_TEXTURE);
        glActiveTexture(GL_TEXTURE0 + TextureUnits.UPLOAD);
        int bound = glGetInteger(GL_TEXTURE_BINDING_2D);
        int draw = glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING);
        int read = glGetInteger(GL_READ_FRAMEBUFFER_BINDING);
        int status;
        try {
            glBindTexture(GL_TEXTURE_2D, id());
            glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    (java.nio.FloatBuffer) null);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
            fbo = new Fbo(tracker);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, id(), 0);
            glDrawBuffer(GL_NONE);
            glReadBuffer(GL_NONE);
            status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        } catch (RuntimeException | Error e) {
            close(); // the texture (and the framebuffer, if made) go again
            throw e;
        } finally {
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, draw);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, read);
            glBindTexture(GL_TEXTURE_2D, bound);
            glActiveTexture(unit);
        }
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            close();
            throw new IllegalStateException("shadow map framebuffer incomplete: status 0x" + Integer.toHexString(status));
        }
    }

    /** {@return texels along each side} */
    public int size() {
        return size;
    }

    /**
     * Remembers the host's framebuffer bindings, binds this map's framebuffer, sets the viewport to the
     * map and clears its depth to 1. The caller puts back the viewport (and enables the depth test and
     * depth writes). No allocation.
     */
    public void begin() {
        hostDraw = query.get(GL_DRAW_FRAMEBUFFER_BINDING);
        hostRead = query.get(GL_READ_FRAMEBUFFER_BINDING);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, size, size);
        glClear(GL_DEPTH_BUFFER_BIT);
    }

    /** Binds the host's framebuffers of the last {@link #begin()} again. No allocation. */
    public void end() {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, hostDraw);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, hostRead);
    }

    /**
     * Binds the depth texture to a texture unit's 2D target (and makes that unit active).
     *
     * @param unit texture unit index, 0 for {@code GL_TEXTURE0}: one of {@link TextureUnits}
     */
    public void bind(int unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, id());
    }

    @Override
    public void delete(int name) {
        if (fbo != null) {
            fbo.close();
            fbo = null;
        }
        if (query != null) {
            query.close();
            query = null;
        }
        glDeleteTextures(name);
    }

    /** The framebuffer that draws into the texture, a tracked object of its own. */
    private static final class Fbo extends GlResource {
        Fbo(GlTracker tracker) {
            super(tracker, glGenFramebuffers());
        }

        @Override
        public void delete(int name) {
            glDeleteFramebuffers(name);
        }
    }
}
