package org.jecosys.render;

import static org.lwjgl.opengl.GL11C.GL_RGBA8;
import static org.lwjgl.opengl.GL11C.glViewport;
import static org.lwjgl.opengl.GL30C.GL_COLOR_ATTACHMENT0;
import static org.lwjgl.opengl.GL30C.GL_DEPTH24_STENCIL8;
import static org.lwjgl.opengl.GL30C.GL_DEPTH_STENCIL_ATTACHMENT;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER_COMPLETE;
import static org.lwjgl.opengl.GL30C.GL_RENDERBUFFER;
import static org.lwjgl.opengl.GL30C.glBindFramebuffer;
import static org.lwjgl.opengl.GL30C.glBindRenderbuffer;
import static org.lwjgl.opengl.GL30C.glCheckFramebufferStatus;
import static org.lwjgl.opengl.GL30C.glDeleteFramebuffers;
import static org.lwjgl.opengl.GL30C.glDeleteRenderbuffers;
import static org.lwjgl.opengl.GL30C.glFramebufferRenderbuffer;
import static org.lwjgl.opengl.GL30C.glGenFramebuffers;
import static org.lwjgl.opengl.GL30C.glGenRenderbuffers;
import static org.lwjgl.opengl.GL30C.glRenderbufferStorage;

/**
 * An offscreen framebuffer with an RGBA8 colour and a depth-stencil renderbuffer, resizable: the
 * target of headless rendering (any size, whatever the window). Counts as three GL objects. Render
 * thread only.
 */
public final class GlFramebuffer extends GlResource {
    private final Renderbuffer colour;
    private final Renderbuffer depth;
    private int width;
    private int height;

    /**
     * A framebuffer of {@code width x height} pixels; leaves no framebuffer bound.
     *
     * @param tracker counts the three objects
     * @param width   pixels, in [1, 16384]
     * @param height  pixels, in [1, 16384]
     * @throws IllegalArgumentException when a size is out of range
     * @throws IllegalStateException    when the driver reports the framebuffer incomplete
     */
    public GlFramebuffer(GlTracker tracker, int width, int height) {
        super(tracker, glGenFramebuffers());
        Renderbuffer c = null;
        Renderbuffer d = null;
        try {
            c = new Renderbuffer(tracker);
            d = new Renderbuffer(tracker);
        } catch (RuntimeException e) {
            PlantRenderer.closeAll(c);
            close();
            throw e;
        }
        colour = c;
        depth = d;
        try {
            resize(width, height);
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    /**
     * Reallocates the storage for a new size (contents undefined). Not per frame; leaves no
     * framebuffer bound.
     *
     * @param width  pixels, in [1, 16384]
     * @param height pixels, in [1, 16384]
     * @throws IllegalArgumentException when a size is out of range
     * @throws IllegalStateException    when the driver reports the framebuffer incomplete
     */
    public void resize(int width, int height) {
        if (width < 1 || height < 1 || width > 16384 || height > 16384) {
            throw new IllegalArgumentException("framebuffer size must be in [1, 16384], got " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        glBindRenderbuffer(GL_RENDERBUFFER, colour.id());
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, depth.id());
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, id());
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour.id());
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth.id());
        int status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            throw new IllegalStateException("framebuffer incomplete: status 0x" + Integer.toHexString(status));
        }
    }

    /** {@return the width, pixels} */
    public int width() {
        return width;
    }

    /** {@return the height, pixels} */
    public int height() {
        return height;
    }

    /** Binds it for drawing and reading and sets the viewport to its size. */
    public void bind() {
        glBindFramebuffer(GL_FRAMEBUFFER, id());
        glViewport(0, 0, width, height);
    }

    @Override
    void delete(int name) {
        glDeleteFramebuffers(name);
        PlantRenderer.closeAll(colour, depth);
    }

    private static final class Renderbuffer extends GlResource {
        Renderbuffer(GlTracker tracker) {
            super(tracker, glGenRenderbuffers());
        }

        @Override
        void delete(int name) {
            glDeleteRenderbuffers(name);
        }
    }
}
