package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL11C.GL_RGBA8;
import static org.lwjgl.opengl.GL11C.glGetInteger;
import static org.lwjgl.opengl.GL11C.glViewport;
import static org.lwjgl.opengl.GL30C.GL_COLOR_ATTACHMENT0;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER_COMPLETE;
import static org.lwjgl.opengl.GL30C.GL_RENDERBUFFER;
import static org.lwjgl.opengl.GL30C.glBindFramebuffer;
import static org.lwjgl.opengl.GL30C.glBindRenderbuffer;
import static org.lwjgl.opengl.GL30C.glCheckFramebufferStatus;
import static org.lwjgl.opengl.GL30C.glDeleteFramebuffers;
import static org.lwjgl.opengl.GL30C.glDeleteRenderbuffers;
import static org.lwjgl.opengl.GL30C.glGenFramebuffers;
import static org.lwjgl.opengl.GL30C.glGenRenderbuffers;

/**
 * The single-sampled targets of a multisampled framebuffer: the box average of the samples (a
 * texture, for the filter pass) and the filtered image (a renderbuffer, to read), with the
 * filter's program and an empty vertex array.
 */
final class Resolved extends GlResource {
    final Renderbuffer colour;
    final Box box;
    final GlProgram program;
    final GlVertexArray vao;
    final int uTexel;
    final int uWeights;
    /** What the filter pass changes, put back after it (allocation-free: it runs every frame in the viewer). */
    final PassState state = new PassState(TextureUnits.FILTER_IMAGE, TextureUnits.FILTER_DETAIL);

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
        GlFramebuffer.storage(GL_RGBA8, 1, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        GlFramebuffer.attach(id(), colour, null, null);
        box.resize(width, height);
    }

    /** Draws the box-averaged image through the tent filter into this framebuffer; puts back what it changes. */
    void filter(int width, int height, float tent) {
        state.save();
        PassState.bind(TextureUnits.FILTER_DETAIL, box.detailTexture);
        PassState.bind(TextureUnits.FILTER_IMAGE, box.texture);
        glBindFramebuffer(GL_FRAMEBUFFER, id());
        glViewport(0, 0, width, height);
        program.use();
        org.lwjgl.opengl.GL20C.glUniform2f(uTexel, 1f / width, 1f / height);
        setWeights(uWeights, tent);
        vao.bind();
        org.lwjgl.opengl.GL11C.glDrawArrays(org.lwjgl.opengl.GL11C.GL_TRIANGLES, 0, 3);
        state.restore();
    }

    /**
     * Sets the filter's weights uniform (box, tent, wide; resolve.frag) for a filter width in [0, 2]
     * ({@link GlFramebuffer#setResolveFilter}). The program must be in use.
     */
    private static void setWeights(int uniform, float tent) {
        float plain = Math.max(0, 1 - tent);
        float wide = Math.max(0, tent - 1);
        org.lwjgl.opengl.GL20C.glUniform3f(uniform, plain, 1 - plain - wide, wide);
    }

    @Override
    public void delete(int name) {
        glDeleteFramebuffers(name);
        state.close();
        Closing.closeAll(vao, program, box, colour);
    }

    /** A framebuffer with an RGBA8 texture, linear filtering, clamped: the box-averaged image. */
    static final class Box extends GlResource {
        private final TextureName image;
        private final TextureName detailImage;
        final int texture;
        final int detailTexture;

        Box(GlTracker tracker) {
            super(tracker, glGenFramebuffers());
            TextureName t = null;
            TextureName d;
            try {
                t = new TextureName(tracker);
                d = new TextureName(tracker);
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
}
