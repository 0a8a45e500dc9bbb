package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL30C.glDeleteVertexArrays;
import static org.lwjgl.opengl.GL30C.glGenVertexArrays;

/** A vertex array object. Render thread only. */
public final class GlVertexArray extends GlResource {
    /**
     * Creates an empty vertex array, bound once so that it exists for the driver at once (a name from
     * glGenVertexArrays is only reserved until its first bind); leaves no vertex array bound.
     *
     * @param tracker counts the object
     */
    public GlVertexArray(GlTracker tracker) {
        super(tracker, glGenVertexArrays());
        glBindVertexArray(id());
        glBindVertexArray(0);
    }

    /** Binds it. */
    public void bind() {
        glBindVertexArray(id());
    }

    @Override
    public void delete(int name) {
        glDeleteVertexArrays(name);
    }
}
