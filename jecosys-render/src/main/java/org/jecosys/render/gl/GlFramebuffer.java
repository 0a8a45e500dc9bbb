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
 * ({@link #setResolveFilter}), and with temporal accumulation ({@link #setAccumulation}). Counts as three GL
 * objects, nine when multisampled, eight more with accumulation on.
 * Render thread only.
 */
public final class GlFramebuffer extends GlResource {
    /**
     * How far a multisampled framebuffer's {@link #resolve()} widens its filter by default
     * ({@link #setResolveFilter}) where the plants drew: half way between the tent of one pixel's radius
     * (the 3x3 binomial) and the 5x5 binomial. Thin blades moving by a fraction of a pixel then change
     * the image smoothly instead of in coverage steps of a quarter pixel (4 samples). The plants blend
     * their thin parts by the share of a pixel they cover, with a soft edge (PlantRenderer's default),
     * which already moves them smoothly, so the full 5x5 binomial would mostly soften the picture.
     */
    public static final float DEFAULT_TENT = 1.5f;
    /** The largest sample count asked for; the driver's maximum caps it further. */
    public static final int MAX_SAMPLES = 16;

    private final Renderbuffer colour;
    private final Renderbuffer depth;
    private final Resolved resolved;
    /** Temporal accumulation's state; null while it is off ({@link #setAccumulation}). */
    private Temporal temporal;
    /** Counts the GL objects of this framebuffer and its temporal state. */
    private final GlTracker tracker;
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
        this.tracker = tracker;
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
        if (temporal != null) {
            temporal.resize(width, height);
        }
    }

    static void storage(int format, int samples, int width, int height) {
        if (samples > 1) {
            glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
        } else {
            glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
        }
    }

    static void attach(int framebuffer, Renderbuffer colour, Renderbuffer depth, Renderbuffer detail) {
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
     * With accumulation on ({@link #setAccumulation}) the frame is blended into the running mean instead,
     * and the mean is what is bound: draw overlays after {@link #resolveTo} into its target, since what is
     * drawn into the mean stays in the next frames. Render thread; no allocation.
     */
    public void resolve() {
        if (resolved == null) {
            glBindFramebuffer(GL_FRAMEBUFFER, id());
            return;
        }
        boolean box = tent > 0 || temporal != null;
        // the running mean is shown this frame: the one-frame filter, and the detail mask it reads, are not
        boolean mean = temporal != null && temporal.keeps();
        glBindFramebuffer(GL_READ_FRAMEBUFFER, id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, box ? resolved.box.id() : resolved.id());
        glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        if (box) {
            if (!mean) {
                // the detail mask too, into the box's second texture
                org.lwjgl.opengl.GL11C.glReadBuffer(org.lwjgl.opengl.GL30C.GL_COLOR_ATTACHMENT1);
                org.lwjgl.opengl.GL11C.glDrawBuffer(org.lwjgl.opengl.GL30C.GL_COLOR_ATTACHMENT1);
                glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
                org.lwjgl.opengl.GL11C.glDrawBuffer(GL_COLOR_ATTACHMENT0);
                org.lwjgl.opengl.GL11C.glReadBuffer(GL_COLOR_ATTACHMENT0);
            }
            if (temporal != null && temporal.resolve(id(), resolved.box.texture, width, height)) {
                // the running mean is the picture
                glBindFramebuffer(GL_FRAMEBUFFER, temporal.framebuffer());
                return;
            }
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
     * Turns temporal accumulation on or off (off when made). On, each frame is drawn with its
     * projection moved by a sub-pixel jitter (draw with the camera {@link #jittered} returns), and
     * {@link #resolve()} blends the frame, filtered narrowly, into a running mean of up to {@code frames}
     * frames: a view held still gathers samples from the whole area of each pixel over frames, so thin
     * blades keep their detail without the aliasing a narrow one-frame filter shows. The running mean is
     * reprojected through the frame's depth when the camera moves and clamped to the range of each
     * pixel's neighbourhood in the new frame, so what comes out from behind something leaves no lasting
     * trail; while the scene animates by itself the mean is kept to 4 frames (see
     * {@link #jittered(org.jecosys.math.Camera, boolean)}). Where the mean is forgotten (the first frame, a
     * resize, {@link #resetHistory()}, a frame whose camera was not jittered) the framebuffer shows the
     * one-frame resolve ({@link #setResolveFilter}) for that frame. Costs a depth blit and one
     * full-screen pass per frame and two RGBA16F images plus a depth texture of the framebuffer's size.
     * Render thread (the context current); allocates GL objects when turned on, none per frame.
     *
     * @param frames 0 to turn it off; else the most frames in the running mean, in [2, 64] (16 gathers
     *               the whole jitter pattern)
     * @throws IllegalArgumentException when {@code frames} is out of range
     * @throws IllegalStateException    when the framebuffer is not multisampled (accumulation rides on
     *                                  the multisampled resolve)
     */
    public void setAccumulation(int frames) {
        if (frames != 0 && (frames < 2 || frames > 64)) {
            throw new IllegalArgumentException("accumulation must be 0 (off) or in [2, 64] frames, got " + frames);
        }
        if (frames == 0) {
            if (temporal != null) {
                temporal.close();
                temporal = null;
            }
            return;
        }
        if (resolved == null) {
            throw new IllegalStateException("temporal accumulation needs a multisampled framebuffer (this one has 1 "
                    + "sample per pixel)");
        }
        if (temporal == null) {
            Temporal t = new Temporal(tracker, frames);
            try {
                t.resize(width, height);
            } catch (RuntimeException e) {
                t.close();
                throw e;
            }
            temporal = t;
        }
        temporal.setFrames(frames);
    }

    /** {@return the most frames temporal accumulation blends, 0 when it is off (see {@link #setAccumulation})} */
    public int accumulation() {
        return temporal == null ? 0 : temporal.frames();
    }

    /**
     * {@link #jittered(org.jecosys.math.Camera, boolean)} for a frame of a scene that animates by itself
     * (a running simulation). Render thread; no allocation.
     *
     * @param camera this frame's camera
     * @return the camera to draw with
     */
    public org.jecosys.math.Camera jittered(org.jecosys.math.Camera camera) {
        return jittered(camera, false);
    }

    /**
     * The camera to draw this frame with: with accumulation on ({@link #setAccumulation}), {@code camera}
     * with its projection moved by this frame's sub-pixel jitter (points 1-16 of the Halton (2, 3)
     * sequence, within half a pixel of the centre; nothing else changes), and its unjittered
     * view-projection remembered for the next {@link #resolve()}'s reprojection; with accumulation off,
     * {@code camera} itself. Call once per frame before drawing. The returned camera belongs to this
     * framebuffer and changes at the next call. Render thread; no allocation.
     *
     * @param camera this frame's camera
     * @param still  true when nothing drawn this frame moved by itself since the last one (a paused
     *               simulation, a photograph held for several frames): the running mean then holds its
     *               full length. False while the scene animates (plants, cover sheen and clouds in the
     *               wind): they carry no motion vectors, so the mean holds at most 4 frames, a short trail
     *               rather than a smear
     * @return the camera to draw with
     */
    public org.jecosys.math.Camera jittered(org.jecosys.math.Camera camera, boolean still) {
        if (camera == null) {
            throw new IllegalArgumentException("camera must not be null");
        }
        return temporal == null ? camera : temporal.jittered(camera, still, width, height);
    }

    /**
     * Forgets the running mean of temporal accumulation, so that the next frame shows the one-frame
     * resolve: call it at a cut (a new scene, a jump of the camera that should not blend). Resizing
     * forgets too. No effect with accumulation off. Render thread; no allocation.
     */
    public void resetHistory() {
        if (temporal != null) {
            temporal.reset();
        }
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
        Closing.closeAll(temporal, colour, depth, detail, resolved);
    }
}
