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
import static org.lwjgl.opengl.GL30C.glRenderbufferStorageMultisample;
import static org.lwjgl.opengl.GL30C.glBlitFramebuffer;
import static org.lwjgl.opengl.GL30C.GL_READ_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_DRAW_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_MAX_SAMPLES;
import static org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_NEAREST;
import static org.lwjgl.opengl.GL11C.glGetInteger;

/**
 * An offscreen framebuffer with an RGBA8 colour and a depth-stencil renderbuffer, resizable, single-
 * or multisampled: the target of headless rendering (any size, whatever the window). Multisampled,
 * it also owns a single-sampled colour target that {@link #resolve()} fills (read the image after
 * that). Counts as three GL objects, five when multisampled. Render thread only.
 */
public final class GlFramebuffer extends GlResource {
    /** The largest sample count asked for; the driver's maximum caps it further. */
    public static final int MAX_SAMPLES = 16;

    private final Renderbuffer colour;
    private final Renderbuffer depth;
    private final Resolved resolved;
    private final int samples;
    private int width;
    private int height;

    /**
     * A single-sampled framebuffer of {@code width x height} pixels; leaves no framebuffer bound.
     *
     * @param tracker counts the three objects
     * @param width   pixels, in [1, 16384]
     * @param height  pixels, in [1, 16384]
     * @throws IllegalArgumentException when a size is out of range
     * @throws IllegalStateException    when the driver reports the framebuffer incomplete
     */
    public GlFramebuffer(GlTracker tracker, int width, int height) {
        this(tracker, width, height, 1);
    }

    /**
     * A framebuffer of {@code width x height} pixels with {@code samples} samples per pixel (1: not
     * multisampled; more than the driver offers: the driver's maximum); leaves no framebuffer bound.
     *
     * @param tracker counts the objects
     * @param width   pixels, in [1, 16384]
     * @param height  pixels, in [1, 16384]
     * @param samples samples per pixel, in [1, {@value #MAX_SAMPLES}]
     * @throws IllegalArgumentException when a size or the sample count is out of range
     * @throws IllegalStateException    when the driver reports the framebuffer incomplete
     */
    public GlFramebuffer(GlTracker tracker, int width, int height, int samples) {
        super(tracker, glGenFramebuffers());
        if (samples < 1 || samples > MAX_SAMPLES) {
            close();
            throw new IllegalArgumentException("samples must be in [1, " + MAX_SAMPLES + "], got " + samples);
        }
        this.samples = samples == 1 ? 1 : Math.max(1, Math.min(samples, glGetInteger(GL_MAX_SAMPLES)));
        Renderbuffer c = null;
        Renderbuffer d = null;
        Resolved r = null;
        try {
            c = new Renderbuffer(tracker);
            d = new Renderbuffer(tracker);
            r = this.samples > 1 ? new Resolved(tracker) : null;
        } catch (RuntimeException e) {
            PlantRenderer.closeAll(c, d);
            close();
            throw e;
        }
        colour = c;
        depth = d;
        resolved = r;
        try {
            resize(width, height);
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    /**
     * Resizes the renderbuffers (contents undefined afterwards); leaves no framebuffer bound.
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
        storage(GL_RGBA8, samples, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, depth.id());
        storage(GL_DEPTH24_STENCIL8, samples, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        attach(id(), colour, depth);
        if (resolved != null) {
            glBindRenderbuffer(GL_RENDERBUFFER, resolved.colour.id());
            storage(GL_RGBA8, 1, width, height);
            glBindRenderbuffer(GL_RENDERBUFFER, 0);
            attach(resolved.id(), resolved.colour, null);
        }
    }

    private static void storage(int format, int samples, int width, int height) {
        if (samples > 1) {
            glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
        } else {
            glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
        }
    }

    private static void attach(int framebuffer, Renderbuffer colour, Renderbuffer depth) {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour.id());
        if (depth != null) {
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth.id());
        }
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

    /** {@return samples per pixel: 1, or the multisample count the driver gave} */
    public int samples() {
        return samples;
    }

    /** Binds it for drawing and reading and sets the viewport to its size. */
    public void bind() {
        glBindFramebuffer(GL_FRAMEBUFFER, id());
        glViewport(0, 0, width, height);
    }

    /**
     * Makes the image readable: multisampled, averages the samples of every pixel into the
     * single-sampled target and binds that for reading and drawing (call {@link #bind()} again
     * before drawing more); single-sampled, binds the framebuffer. Then {@link Pixels#read} reads
     * the image. Render thread; no allocation.
     */
    public void resolve() {
        if (resolved == null) {
            glBindFramebuffer(GL_FRAMEBUFFER, id());
            return;
        }
        glBindFramebuffer(GL_READ_FRAMEBUFFER, id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved.id());
        glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, resolved.id());
    }

    @Override
    void delete(int name) {
        glDeleteFramebuffers(name);
        PlantRenderer.closeAll(colour, depth, resolved);
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

    /** The single-sampled target of a multisampled framebuffer: a framebuffer and its colour. */
    private static final class Resolved extends GlResource {
        final Renderbuffer colour;

        Resolved(GlTracker tracker) {
            super(tracker, glGenFramebuffers());
            Renderbuffer c;
            try {
                c = new Renderbuffer(tracker);
            } catch (RuntimeException e) {
                close();
                throw e;
            }
            colour = c;
        }

        @Override
        void delete(int name) {
            glDeleteFramebuffers(name);
            PlantRenderer.closeAll(colour);
        }
    }
}
