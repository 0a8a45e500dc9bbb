package org.jecosys.render.gl;

/** A framebuffer object name, counted by the tracker. */
final class FramebufferName extends GlResource {
    FramebufferName(GlTracker tracker) {
        super(tracker, org.lwjgl.opengl.GL30C.glGenFramebuffers());
    }

    @Override
    public void delete(int name) {
        org.lwjgl.opengl.GL30C.glDeleteFramebuffers(name);
    }
}
