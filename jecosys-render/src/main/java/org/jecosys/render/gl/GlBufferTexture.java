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
        this(tracker, buffer.id(), internalFormat);
    }

    /**
     * A buffer texture over the buffer named {@code buffer} (e.g. a {@link GlUploadRing}'s, set to a
     * range each frame with {@link #range}); leaves no buffer texture bound.
     *
     * @param tracker        counts the object
     * @param buffer         the buffer's GL name
     * @param internalFormat texel format
     */
    public GlBufferTexture(GlTracker tracker, int buffer, int internalFormat) {
        super(tracker, glGenTextures());
        this.internalFormat = internalFormat;
        glBindTexture(GL_TEXTURE_BUFFER, id());
        glTexBuffer(GL_TEXTURE_BUFFER, internalFormat, buffer);
        glBindTexture(GL_TEXTURE_BUFFER, 0);
    }

    private final int internalFormat;

    /**
     * Points the texture at a range of a buffer ({@code glTexBufferRange}, OpenGL 4.3) and leaves it bound
     * to {@code unit}. Render thread; no allocation.
     *
     * @param unit   texture unit index: one of {@link TextureUnits}
     * @param buffer the buffer's GL name
     * @param offset first byte, a multiple of {@code GL_TEXTURE_BUFFER_OFFSET_ALIGNMENT}
     * @param bytes  bytes in the range, &gt; 0
     */
    public void range(int unit, int buffer, long offset, long bytes) {
        bind(unit);
        org.lwjgl.opengl.GL43C.glTexBufferRange(GL_TEXTURE_BUFFER, internalFormat, buffer, offset, bytes);
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
