package org.jecosys.render.gl;

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
 * that), through a filter from the plain average of each pixel's samples to a 5x5 binomial
 * ({@link #setResolveFilter}). Counts as three GL objects, nine when multisampled.
 * Render thread only.
 */
public final class GlFramebuffer extends GlResource {
    /**
     * How far a multisampled framebuffer's {@link #resolve()} widens its filter by default
     * ({@link #setResolveFilter}) where the plants drew: half way between the tent of one pixel's radius
     * (the 3x3 binomial) and the 5x5 binomial. Thin blades moving by a fraction of a pixel then change
     * the image smoothly instead of in coverage steps of a quarter pixel (4 samples). The plants blend
     * their thin parts on the samples (PlantRenderer's default), which already moves them smoothly, so
     * the full 5x5 binomial would mostly soften the picture.
     */
    public static final float DEFAULT_TENT = 1.5f;
    /** The largest sample count asked for; the driver's maximum caps it further. */
    public static final int MAX_SAMPLES = 16;

    private final Renderbuffer colour;
    private final Renderbuffer depth;
    private final Resolved resolved;
    /**
     * Multisampled only: the detail mask (draw buffer 1): 1 where thin geometry (plants) was drawn, 0
     * elsewhere, which {@link #resolve()} widens its filter by.
     */
    private final Renderbuffer detail;
    private final int samples;
    private float tent = DEFAULT_TENT;
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
        Renderbuffer m = null;
        Resolved r = null;
        try {
            c = new Renderbuffer(tracker);
            d = new Renderbuffer(tracker);
            m = this.samples > 1 ? new Renderbuffer(tracker) : null;
            r = this.samples > 1 ? new Resolved(tracker) : null;
        } catch (RuntimeException e) {
            Closing.closeAll(c, d, m);
            close();
            throw e;
        }
        colour = c;
        depth = d;
        detail = m;
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
        if (detail != null) {
            glBindRenderbuffer(GL_RENDERBUFFER, detail.id());
            storage(org.lwjgl.opengl.GL30C.GL_R8, samples, width, height);
        }
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        attach(id(), colour, depth, detail);
        if (resolved != null) {
            resolved.resize(width, height);
        }
    }

    private static void storage(int format, int samples, int width, int height) {
        if (samples > 1) {
            glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
        } else {
            glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
        }
    }

    private static void attach(int framebuffer, Renderbuffer colour, Renderbuffer depth, Renderbuffer detail) {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour.id());
        if (depth != null) {
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth.id());
        }
        if (detail != null) {
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, org.lwjgl.opengl.GL30C.GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER,
                    detail.id());
            org.lwjgl.opengl.GL20C.glDrawBuffers(new int[] {GL_COLOR_ATTACHMENT0,
                org.lwjgl.opengl.GL30C.GL_COLOR_ATTACHMENT1});
            // nothing drawn yet: no detail anywhere (a guest's drawing never writes it)
            org.lwjgl.opengl.GL30C.glClearBufferfv(org.lwjgl.opengl.GL11C.GL_COLOR, 1, new float[] {0, 0, 0, 0});
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
     * Makes the image readable: multisampled, averages the samples of every pixel (a blit) and, when
     * {@link #resolveFilter()} is above 0, widens that toward a tent filter in one full-screen pass
     * (which puts back the program, vertex array, texture unit 0 and the switches it changes), then
     * binds the single-sampled result for reading and drawing (call {@link #bind()} again before
     * drawing more); single-sampled, binds the framebuffer. Then {@link Pixels#read} reads the image.
     * Render thread; no allocation.
     */
    public void resolve() {
        if (resolved == null) {
            glBindFramebuffer(GL_FRAMEBUFFER, id());
            return;
        }
        glBindFramebuffer(GL_READ_FRAMEBUFFER, id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, tent > 0 ? resolved.box.id() : resolved.id());
        glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        if (tent > 0) {
            // the detail mask too, into the box's second texture
            org.lwjgl.opengl.GL11C.glReadBuffer(org.lwjgl.opengl.GL30C.GL_COLOR_ATTACHMENT1);
            org.lwjgl.opengl.GL11C.glDrawBuffer(org.lwjgl.opengl.GL30C.GL_COLOR_ATTACHMENT1);
            glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
            org.lwjgl.opengl.GL11C.glDrawBuffer(GL_COLOR_ATTACHMENT0);
            org.lwjgl.opengl.GL11C.glReadBuffer(GL_COLOR_ATTACHMENT0);
            resolved.filter(width, height, tent);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, resolved.id());
    }

    /**
     * {@link #resolve()}, then copies the result into {@code target} (0: the window's framebuffer) at
     * the same size, and binds {@code target} for drawing more (a HUD over the scene). A viewer renders
     * its scene here and shows it in any window, multisampled or not. Render thread; no allocation.
     *
     * @param target the framebuffer object to copy into, 0 for the default framebuffer
     */
    public void resolveTo(int target) {
        resolve();
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
        glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, target);
    }

    /**
     * How far {@link #resolve()} widens the average of each pixel's samples, for multisampled
     * framebuffers: 0 keeps the plain average (a box one pixel wide); 1 is a tent of one pixel's
     * radius (the 3x3 binomial); 2 a 5x5 binomial (a Gaussian of about one pixel); values between
     * mix the neighbouring filters. See {@link #DEFAULT_TENT}. Render thread; no allocation.
     *
     * @param tent in [0, 2]
     * @throws IllegalArgumentException when out of range
     */
    public void setResolveFilter(float tent) {
        if (!(tent >= 0 && tent <= 2)) {
            throw new IllegalArgumentException("resolve filter must be in [0, 2], got " + tent);
        }
        this.tent = tent;
    }

    /** {@return how far {@link #resolve()} widens its filter, in [0, 2] (see {@link #setResolveFilter})} */
    public float resolveFilter() {
        return tent;
    }

    @Override
    public void delete(int name) {
        glDeleteFramebuffers(name);
        Closing.closeAll(colour, depth, detail, resolved);
    }

    private static final class Renderbuffer extends GlResource {
        Renderbuffer(GlTracker tracker) {
            super(tracker, glGenRenderbuffers());
        }

        @Override
        public void delete(int name) {
            glDeleteRenderbuffers(name);
        }
    }

    /**
     * The single-sampled targets of a multisampled framebuffer: the box average of the samples (a
     * texture, for the filter pass) and the filtered image (a renderbuffer, to read), with the
     * filter's program and an empty vertex array.
     */
    private static final class Resolved extends GlResource {
        final Renderbuffer colour;
        final Box box;
        final GlProgram program;
        final GlVertexArray vao;
        final int uTexel;
        final int uWeights;
        /** Allocation-free state queries: the filter runs every frame in the viewer. */
        final GlInts query = new GlInts();

        Resolved(GlTracker tracker) {
            super(tracker, glGenFramebuffers());
            Renderbuffer c = null;
            Box b = null;
            GlProgram p = null;
            GlVertexArray v;
            try {
                c = new Renderbuffer(tracker);
                b = new Box(tracker);
                p = new GlProgram(tracker, "resolve.vert", "resolve.frag");
                v = new GlVertexArray(tracker);
            } catch (RuntimeException e) {
                Closing.closeAll(p, b, c);
                close();
                throw e;
            }
            colour = c;
            box = b;
            program = p;
            vao = v;
            int current = glGetInteger(org.lwjgl.opengl.GL20C.GL_CURRENT_PROGRAM);
            program.use();
            org.lwjgl.opengl.GL20C.glUniform1i(program.uniform("uImage"), TextureUnits.FILTER_IMAGE);
            org.lwjgl.opengl.GL20C.glUniform1i(program.uniform("uDetail"), TextureUnits.FILTER_DETAIL);
            uTexel = program.uniform("uTexel");
            uWeights = program.uniform("uWeights");
            org.lwjgl.opengl.GL20C.glUseProgram(current);
        }

        void resize(int width, int height) {
            glBindRenderbuffer(GL_RENDERBUFFER, colour.id());
            storage(GL_RGBA8, 1, width, height);
            glBindRenderbuffer(GL_RENDERBUFFER, 0);
            attach(id(), colour, null, null);
            box.resize(width, height);
        }

        /** Draws the box-averaged image through the tent filter into this framebuffer; puts back what it changes. */
        void filter(int width, int height, float tent) {
            int program0 = query.get(org.lwjgl.opengl.GL20C.GL_CURRENT_PROGRAM);
            int vao0 = query.get(org.lwjgl.opengl.GL30C.GL_VERTEX_ARRAY_BINDING);
            int unit0 = query.get(org.lwjgl.opengl.GL13C.GL_ACTIVE_TEXTURE);
            org.lwjgl.opengl.GL13C.glActiveTexture(org.lwjgl.opengl.GL13C.GL_TEXTURE0 + TextureUnits.FILTER_DETAIL);
            int detail0 = query.get(org.lwjgl.opengl.GL11C.GL_TEXTURE_BINDING_2D);
            org.lwjgl.opengl.GL11C.glBindTexture(org.lwjgl.opengl.GL11C.GL_TEXTURE_2D, box.detailTexture);
            org.lwjgl.opengl.GL13C.glActiveTexture(org.lwjgl.opengl.GL13C.GL_TEXTURE0 + TextureUnits.FILTER_IMAGE);
            int image0 = query.get(org.lwjgl.opengl.GL11C.GL_TEXTURE_BINDING_2D);
            boolean depth = org.lwjgl.opengl.GL11C.glIsEnabled(org.lwjgl.opengl.GL11C.GL_DEPTH_TEST);
            boolean blend = org.lwjgl.opengl.GL11C.glIsEnabled(org.lwjgl.opengl.GL11C.GL_BLEND);
            boolean scissor = org.lwjgl.opengl.GL11C.glIsEnabled(org.lwjgl.opengl.GL11C.GL_SCISSOR_TEST);
            boolean cull = org.lwjgl.opengl.GL11C.glIsEnabled(org.lwjgl.opengl.GL11C.GL_CULL_FACE);
            org.lwjgl.opengl.GL11C.glDisable(org.lwjgl.opengl.GL11C.GL_DEPTH_TEST);
            org.lwjgl.opengl.GL11C.glDisable(org.lwjgl.opengl.GL11C.GL_BLEND);
            org.lwjgl.opengl.GL11C.glDisable(org.lwjgl.opengl.GL11C.GL_SCISSOR_TEST);
            org.lwjgl.opengl.GL11C.glDisable(org.lwjgl.opengl.GL11C.GL_CULL_FACE);
            glBindFramebuffer(GL_FRAMEBUFFER, id());
            glViewport(0, 0, width, height);
            program.use();
            org.lwjgl.opengl.GL20C.glUniform2f(uTexel, 1f / width, 1f / height);
            float plain = Math.max(0, 1 - tent);
            float wide = Math.max(0, tent - 1);
            org.lwjgl.opengl.GL20C.glUniform3f(uWeights, plain, 1 - plain - wide, wide);
            org.lwjgl.opengl.GL11C.glBindTexture(org.lwjgl.opengl.GL11C.GL_TEXTURE_2D, box.texture);
            vao.bind();
            org.lwjgl.opengl.GL11C.glDrawArrays(org.lwjgl.opengl.GL11C.GL_TRIANGLES, 0, 3);
            org.lwjgl.opengl.GL30C.glBindVertexArray(vao0);
            org.lwjgl.opengl.GL20C.glUseProgram(program0);
            org.lwjgl.opengl.GL11C.glBindTexture(org.lwjgl.opengl.GL11C.GL_TEXTURE_2D, image0);
            org.lwjgl.opengl.GL13C.glActiveTexture(org.lwjgl.opengl.GL13C.GL_TEXTURE0 + TextureUnits.FILTER_DETAIL);
            org.lwjgl.opengl.GL11C.glBindTexture(org.lwjgl.opengl.GL11C.GL_TEXTURE_2D, detail0);
            org.lwjgl.opengl.GL13C.glActiveTexture(unit0);
            enable(org.lwjgl.opengl.GL11C.GL_DEPTH_TEST, depth);
            enable(org.lwjgl.opengl.GL11C.GL_BLEND, blend);
            enable(org.lwjgl.opengl.GL11C.GL_SCISSOR_TEST, scissor);
            enable(org.lwjgl.opengl.GL11C.GL_CULL_FACE, cull);
        }

        private static void enable(int cap, boolean on) {
            if (on) {
                org.lwjgl.opengl.GL11C.glEnable(cap);
            } else {
                org.lwjgl.opengl.GL11C.glDisable(cap);
            }
        }

        @Override
        public void delete(int name) {
            glDeleteFramebuffers(name);
            query.close();
            Closing.closeAll(vao, program, box, colour);
        }
    }

    /** A framebuffer with an RGBA8 texture, linear filtering, clamped: the box-averaged image. */
    private static final class Box extends GlResource {
        private final Texture image;
        private final Texture detailImage;
        final int texture;
        final int detailTexture;

        Box(GlTracker tracker) {
            super(tracker, glGenFramebuffers());
            Texture t = null;
            Texture d;
            try {
                t = new Texture(tracker);
                d = new Texture(tracker);
            } catch (RuntimeException e) {
                Closing.closeAll(t);
                close();
                throw e;
            }
            image = t;
            detailImage = d;
            texture = t.id();
            detailTexture = d.id();
        }

        void resize(int width, int height) {
            int unit0 = glGetInteger(org.lwjgl.opengl.GL13C.GL_ACTIVE_TEXTURE);
            org.lwjgl.opengl.GL13C.glActiveTexture(org.lwjgl.opengl.GL13C.GL_TEXTURE0 + TextureUnits.UPLOAD);
            int bound = glGetInteger(org.lwjgl.opengl.GL11C.GL_TEXTURE_BINDING_2D);
            int t2 = org.lwjgl.opengl.GL11C.GL_TEXTURE_2D;
            for (int k = 0; k < 2; k++) {
            org.lwjgl.opengl.GL11C.glBindTexture(t2, k == 0 ? texture : detailTexture);
            org.lwjgl.opengl.GL11C.glTexImage2D(t2, 0, k == 0 ? GL_RGBA8 : org.lwjgl.opengl.GL30C.GL_R8, width, height,
                    0, org.lwjgl.opengl.GL11C.GL_RGBA, org.lwjgl.opengl.GL11C.GL_UNSIGNED_BYTE, (java.nio.ByteBuffer) null);
            org.lwjgl.opengl.GL11C.glTexParameteri(t2, org.lwjgl.opengl.GL11C.GL_TEXTURE_MIN_FILTER,
                    org.lwjgl.opengl.GL11C.GL_LINEAR);
            org.lwjgl.opengl.GL11C.glTexParameteri(t2, org.lwjgl.opengl.GL11C.GL_TEXTURE_MAG_FILTER,
                    org.lwjgl.opengl.GL11C.GL_LINEAR);
            org.lwjgl.opengl.GL11C.glTexParameteri(t2, org.lwjgl.opengl.GL11C.GL_TEXTURE_WRAP_S,
                    org.lwjgl.opengl.GL12C.GL_CLAMP_TO_EDGE);
            org.lwjgl.opengl.GL11C.glTexParameteri(t2, org.lwjgl.opengl.GL11C.GL_TEXTURE_WRAP_T,
                    org.lwjgl.opengl.GL12C.GL_CLAMP_TO_EDGE);
            }
            org.lwjgl.opengl.GL11C.glBindTexture(t2, bound);
            org.lwjgl.opengl.GL13C.glActiveTexture(unit0);
            glBindFramebuffer(GL_FRAMEBUFFER, id());
            org.lwjgl.opengl.GL30C.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t2, texture, 0);
            org.lwjgl.opengl.GL30C.glFramebufferTexture2D(GL_FRAMEBUFFER, org.lwjgl.opengl.GL30C.GL_COLOR_ATTACHMENT1, t2,
                    detailTexture, 0);
            int status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            if (status != GL_FRAMEBUFFER_COMPLETE) {
                throw new IllegalStateException("framebuffer incomplete: status 0x" + Integer.toHexString(status));
            }
        }

        @Override
        public void delete(int name) {
            glDeleteFramebuffers(name);
            Closing.closeAll(image, detailImage);
        }
    }

    /** A texture name, counted by the tracker. */
    private static final class Texture extends GlResource {
        Texture(GlTracker tracker) {
            super(tracker, org.lwjgl.opengl.GL11C.glGenTextures());
        }

        @Override
        public void delete(int name) {
            org.lwjgl.opengl.GL11C.glDeleteTextures(name);
        }
    }
}
