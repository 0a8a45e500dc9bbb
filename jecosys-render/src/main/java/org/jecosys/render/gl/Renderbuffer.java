package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL30C.glDeleteRenderbuffers;
import static org.lwjgl.opengl.GL30C.glGenRenderbuffers;

/** A renderbuffer name, counted by the tracker. */
final class Renderbuffer extends GlResource {
    Renderbuffer(GlTracker tracker) {
        super(tracker, glGenRenderbuffers());
    }

    @Override
    public void delete(int name) {
        glDeleteRenderbuffers(name);
    }
}
