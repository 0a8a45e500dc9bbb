package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL11C.GL_LINEAR;
import static org.lwjgl.opengl.GL11C.GL_NEAREST;
import static org.lwjgl.opengl.GL11C.GL_NONE;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_2D;
import static org.lwjgl.opengl.GL11C.glBindTexture;
import static org.lwjgl.opengl.GL11C.glTexImage2D;
import static org.lwjgl.opengl.GL11C.glTexParameteri;
import static org.lwjgl.opengl.GL11C.glViewport;
import static org.lwjgl.opengl.GL30C.GL_COLOR_ATTACHMENT0;
import static org.lwjgl.opengl.GL30C.GL_DEPTH24_STENCIL8;
import static org.lwjgl.opengl.GL30C.GL_DEPTH_BUFFER_BIT;
import static org.lwjgl.opengl.GL30C.GL_DEPTH_STENCIL;
import static org.lwjgl.opengl.GL30C.GL_DEPTH_STENCIL_ATTACHMENT;
import static org.lwjgl.opengl.GL30C.GL_DRAW_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER_COMPLETE;
import static org.lwjgl.opengl.GL30C.GL_READ_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_RGBA16F;
import static org.lwjgl.opengl.GL30C.GL_UNSIGNED_INT_24_8;
import static org.lwjgl.opengl.GL30C.glBindFramebuffer;
import static org.lwjgl.opengl.GL30C.glBlitFramebuffer;
import static org.lwjgl.opengl.GL30C.glCheckFramebufferStatus;
import static org.lwjgl.opengl.GL30C.glDeleteFramebuffers;
import static org.lwjgl.opengl.GL30C.glFramebufferTexture2D;
import static org.lwjgl.opengl.GL30C.glGenFramebuffers;

import org.jecosys.math.Camera;
import org.jecosys.math.MatrixCamera;
import org.joml.Matrix4f;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.opengl.GL12C;
import org.lwjgl.opengl.GL20C;

/**
 * The temporal half of a multisampled {@link GlFramebuffer}'s resolve ({@link GlFramebuffer#setAccumulation}):
 * the sub-pixel jitter of each frame's projection, the running mean of earlier frames (two RGBA16F
 * textures, read and written in turn, each the colour of a framebuffer; alpha counts the frames each
 * pixel holds), the frame's depth (resolved from the samples, to reproject the history for the camera's
 * motion) and the pass ({@code temporal.frag}) that blends the frame in. The framebuffer shows the newest
 * mean; one pass, one target (on Mesa's llvmpipe a second target doubled the pass's time). Eight GL
 * objects. Render thread only; no allocation after construction.
 */
final class Temporal extends GlResource {
    /** Jitter offsets repeat after this many frames: the Halton (2, 3) points 1 to 16. */
    static final int JITTER_PERIOD = 16;
    /**
     * The narrow filter each accumulated frame is resolved with: the box average of each pixel's samples
     * mixed this far toward the 1 2 1 tent (the one-frame filter's 1 is the whole tent). With the box
     * alone (0) the meadow held still kept 0.91 of the supersampled detail but moved half a pixel changed
     * by 2.10/255 (issue 13 allows 2); at 0.5, 0.63 and 1.39.
     */
    static final float NARROW = 0.1f;
    /** The neighbourhood's colour range the history is clamped to: its mean within this many standard deviations. */
    static final float CLIP = 1.5f;
    /** The most frames the running mean holds while the scene animates by itself ({@code still} false). */
    static final int LIVE_FRAMES = 4;

    private final TextureName[] history = new TextureName[2];
    private final int[] passes = new int[2];
    private final FramebufferName secondPass;
    private final FramebufferName depthTarget;
    private final TextureName depth;
    private final int depthFb;
    private final GlProgram program;
    private final GlVertexArray vao;
    private final PassState state = new PassState(TextureUnits.FILTER_IMAGE, TextureUnits.TEMPORAL_DEPTH,
            TextureUnits.TEMPORAL_HISTORY);
    private final int uTexel;
    private final int uTent;
    private final int uReproject;
    private final int uKeep;
    private final int uFrames;
    private final int uMovingFrames;
    private final int uClip;
    private final int uLiveFrames;
    private final int uStill;
    private final float[] jitter = new float[2 * JITTER_PERIOD];
    private final float[] matrix = new float[16];
    private final MatrixCamera jittered = new MatrixCamera();
    private final Matrix4f view = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();
    private final Matrix4f current = new Matrix4f();
    private final Matrix4f previous = new Matrix4f();
    private final Matrix4f reproject = new Matrix4f();
    private int frames;
    private long frame;
    private int read;
    /** A jittered camera was handed out since the last resolve. */
    private boolean cameraSet;
    /** What was drawn since the last resolve did not move by itself. */
    private boolean still;
    /** The history holds a frame whose camera is {@link #previous}. */
    private boolean valid;

    Temporal(GlTracker tracker, int frames) {
        super(tracker, glGenFramebuffers());
        GlProgram p = null;
        GlVertexArray v = null;
        TextureName d = null;
        FramebufferName f1 = null;
        FramebufferName fd = null;
        try {
            history[0] = new TextureName(tracker);
            history[1] = new TextureName(tracker);
            d = new TextureName(tracker);
            p = new GlProgram(tracker, "resolve.vert", "temporal.frag");
            v = new GlVertexArray(tracker);
            f1 = new FramebufferName(tracker);
            fd = new FramebufferName(tracker);
        } catch (RuntimeException e) {
            Closing.closeAll(f1, v, p, d, history[1], history[0]);
            close();
            throw e;
        }
        depth = d;
        program = p;
        vao = v;
        secondPass = f1;
        depthTarget = fd;
        passes[0] = id();
        passes[1] = f1.id();
        depthFb = fd.id();
        int program0 = GL11C.glGetInteger(GL20C.GL_CURRENT_PROGRAM);
        program.use();
        GL20C.glUniform1i(program.uniform("uImage"), TextureUnits.FILTER_IMAGE);
        GL20C.glUniform1i(program.uniform("uDepth"), TextureUnits.TEMPORAL_DEPTH);
        GL20C.glUniform1i(program.uniform("uHistory"), TextureUnits.TEMPORAL_HISTORY);
        uTexel = program.uniform("uTexel");
        uTent = program.uniform("uTent");
        uReproject = program.uniform("uReproject");
        uKeep = program.uniform("uKeep");
        uFrames = program.uniform("uFrames");
        uMovingFrames = program.uniform("uMovingFrames");
        uClip = program.uniform("uClip");
        uLiveFrames = program.uniform("uLiveFrames");
        uStill = program.uniform("uStill");
        GL20C.glUseProgram(program0);
        for (int k = 0; k < JITTER_PERIOD; k++) {
            jitter[2 * k] = (float) (halton(k + 1, 2) - 0.5);
            jitter[2 * k + 1] = (float) (halton(k + 1, 3) - 0.5);
        }
        setFrames(frames);
    }

    /** The radical inverse of {@code i} in base {@code b}: the Halton sequence, in [0, 1). */
    static double halton(int i, int b) {
        double f = 1;
        double r = 0;
        for (int n = i; n > 0; n /= b) {
            f /= b;
            r += f * (n % b);
        }
        return r;
    }

    void setFrames(int n) {
        frames = n;
    }

    int frames() {
        return frames;
    }

    /** Forgets the history: the next resolve shows the one-frame resolve. */
    void reset() {
        valid = false;
    }

    /** This frame's jitter, pixels in [-0.5, 0.5): {@code axis} 0 is x, 1 is y. */
    float jitter(int axis) {
        return jitter[2 * (int) (frame % JITTER_PERIOD) + axis];
    }

    /**
     * The camera moved by this frame's jitter (its projection shifted by a fraction of a pixel, nothing
     * else changed); remembers its unjittered view-projection and whether the frame's content is held still
     * for the next resolve. The returned camera
     * is this object's and changes at the next call.
     */
    Camera jittered(Camera camera, boolean heldStill, int width, int height) {
        still = heldStill;
        camera.view(view);
        camera.projection(projection);
        camera.viewProjection(current);
        projection.translateLocal(2f * jitter(0) / width, 2f * jitter(1) / height, 0);
        jittered.set(view, projection);
        cameraSet = true;
        return jittered;
    }

    /** Allocates the history and depth at a new size (contents forgotten). */
    void resize(int width, int height) {
        int unit0 = GL11C.glGetInteger(org.lwjgl.opengl.GL13C.GL_ACTIVE_TEXTURE);
        org.lwjgl.opengl.GL13C.glActiveTexture(org.lwjgl.opengl.GL13C.GL_TEXTURE0 + TextureUnits.UPLOAD);
        int bound = GL11C.glGetInteger(GL11C.GL_TEXTURE_BINDING_2D);
        for (int k = 0; k < 3; k++) {
            glBindTexture(GL_TEXTURE_2D, k < 2 ? history[k].id() : depth.id());
            if (k < 2) {
                glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, width, height, 0, GL11C.GL_RGBA, GL11C.GL_FLOAT,
                        (java.nio.ByteBuffer) null);
            } else {
                glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, width, height, 0, GL_DEPTH_STENCIL,
                        GL_UNSIGNED_INT_24_8, (java.nio.ByteBuffer) null);
            }
            int filter = k < 2 ? GL_LINEAR : GL_NEAREST;
            glTexParameteri(GL_TEXTURE_2D, GL11C.GL_TEXTURE_MIN_FILTER, filter);
            glTexParameteri(GL_TEXTURE_2D, GL11C.GL_TEXTURE_MAG_FILTER, filter);
            glTexParameteri(GL_TEXTURE_2D, GL11C.GL_TEXTURE_WRAP_S, GL12C.GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL11C.GL_TEXTURE_WRAP_T, GL12C.GL_CLAMP_TO_EDGE);
        }
        glBindTexture(GL_TEXTURE_2D, bound);
        org.lwjgl.opengl.GL13C.glActiveTexture(unit0);
        for (int k = 0; k < 2; k++) {
            glBindFramebuffer(GL_FRAMEBUFFER, passes[k]);
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, history[k].id(), 0);
            complete();
        }
        glBindFramebuffer(GL_FRAMEBUFFER, depthFb);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depth.id(), 0);
        GL11C.glDrawBuffer(GL_NONE);
        GL11C.glReadBuffer(GL_NONE);
        complete();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        valid = false;
    }

    private static void complete() {
        int status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            throw new IllegalStateException("temporal resolve framebuffer incomplete: status 0x"
                    + Integer.toHexString(status));
        }
    }

    /**
     * Blends this frame into the history. The samples' average is in {@code box} (a texture);
     * {@code samples} is the multisampled framebuffer, whose depth this resolves. Puts back the GL state it
     * changes apart from the framebuffer bindings.
     *
     * @return true when the history held earlier frames of this camera, so that the framebuffer shows the
     *         running mean ({@link #framebuffer()}); false when it was forgotten (the first frame, a reset,
     *         a resize, a frame drawn without {@link #jittered}): then it shows its one-frame resolve
     */
    boolean resolve(int samples, int box, int width, int height) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, samples);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, depthFb);
        glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        boolean keep = keeps();
        if (!keep || previous.equals(current)) {
            reproject.identity();
        } else {
            current.invert(reproject);
            previous.mul(reproject, reproject);
        }
        state.save();
        PassState.bind(TextureUnits.TEMPORAL_DEPTH, depth.id());
        PassState.bind(TextureUnits.TEMPORAL_HISTORY, history[read].id());
        PassState.bind(TextureUnits.FILTER_IMAGE, box);
        glBindFramebuffer(GL_FRAMEBUFFER, passes[1 - read]);
        glViewport(0, 0, width, height);
        program.use();
        GL20C.glUniform2f(uTexel, 1f / width, 1f / height);
        GL20C.glUniform1f(uTent, NARROW);
        GL20C.glUniformMatrix4fv(uReproject, false, reproject.get(matrix));
        GL20C.glUniform1f(uKeep, keep ? 1 : 0);
        GL20C.glUniform1f(uFrames, frames);
        GL20C.glUniform1f(uMovingFrames, Math.max(2, frames / 2));
        GL20C.glUniform1f(uLiveFrames, LIVE_FRAMES);
        GL20C.glUniform1f(uStill, still ? 1 : 0);
        GL20C.glUniform1f(uClip, CLIP);
        vao.bind();
        GL11C.glDrawArrays(GL11C.GL_TRIANGLES, 0, 3);
        state.restore();
        read = 1 - read;
        previous.set(current);
        valid = cameraSet;
        cameraSet = false;
        frame++;
        return keep;
    }

    /** {@return whether the next {@link #resolve} keeps the history, so that the running mean is shown} */
    boolean keeps() {
        return valid && cameraSet;
    }

    /** {@return the framebuffer whose colour is the running mean the last {@link #resolve} wrote} */
    int framebuffer() {
        return passes[read];
    }

    @Override
    public void delete(int name) {
        glDeleteFramebuffers(name);
        state.close();
        Closing.closeAll(depthTarget, secondPass, vao, program, depth, history[1], history[0]);
    }
}
