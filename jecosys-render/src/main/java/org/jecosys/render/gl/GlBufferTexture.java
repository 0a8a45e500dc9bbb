package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL11C.glBindTexture;
import static org.lwjgl.opengl.GL11C.glDeleteTextures;
import static org.lwjgl.opengl.GL11C.glGenTextures;
import static org.lwjgl.opengl.GL13C.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13C.glActiveTexture;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BUFFER;
import static org.lwjgl.opengl.GL31C.glTexBuffer;

/**
 * A buffer texture (texture buffer object, GL 3.1 core) viewing a {@link GlBuffer} as an array of
 * texels the shaders read with {@code texelFetch}: how pose tables and per-component bend data reach
 * the vertex shader. Does not own the buffer. Render thread only.
 */
public final class GlBufferTexture extends GlResource {
    /**
     * A buffer texture over {@code buffer}; leaves no buffer texture bound.
     *
     * @param tracker        counts the object
     * @param buffer         storage (its target should be {@code GL_TEXTURE_BUFFER})
     * @param internalFormat texel format, e.g. {@code GL_RGBA32F}, {@code GL_RG32F}, {@code GL_RGBA32I}
     */
    public GlBufferTexture(GlTracker tracker, GlBuffer buffer, int internalFormat) {
        super(tracker, glGenTextures());
        glBindTexture(GL_TEXTURE_BUFFER, id());
        glTexBuffer(GL_TEXTURE_BUFFER, internalFormat, buffer.id());
        glBindTexture(GL_TEXTURE_BUFFER, 0);
    }

    /**
     * Binds to a texture unit (and makes that unit active).
     *
     * @param unit texture unit index, 0 for {@code GL_TEXTURE0}: one of {@link TextureUnits}
     */
    public void bind(int unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_BUFFER, id());
    }

    @Override
    public void delete(int name) {
        glDeleteTextures(name);
    }
}
