package org.jecosys.render;

import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL30C.glDeleteVertexArrays;
import static org.lwjgl.opengl.GL30C.glGenVertexArrays;

/** A vertex array object. Render thread only. */
public final class GlVertexArray extends GlResource {
    /** Creates an empty vertex array. */
    public GlVertexArray(GlTracker tracker) {
        super(tracker, glGenVertexArrays());
    }

    /** Binds it. */
    public void bind() {
        glBindVertexArray(id());
    }

    @Override
    void delete(int name) {
        glDeleteVertexArrays(name);
    }
}
