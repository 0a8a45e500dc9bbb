package org.jecosys.render.gl;

/** A texture name, counted by the tracker. */
final class TextureName extends GlResource {
    TextureName(GlTracker tracker) {
        super(tracker, org.lwjgl.opengl.GL11C.glGenTextures());
    }

    @Override
    public void delete(int name) {
        org.lwjgl.opengl.GL11C.glDeleteTextures(name);
    }
}
