package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL11C.GL_LINEAR;
import static org.lwjgl.opengl.GL11C.GL_RED;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_2D;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_BINDING_2D;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_MAG_FILTER;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_MIN_FILTER;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_WRAP_S;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_WRAP_T;
import static org.lwjgl.opengl.GL11C.GL_UNPACK_ALIGNMENT;
import static org.lwjgl.opengl.GL11C.GL_UNSIGNED_BYTE;
import static org.lwjgl.opengl.GL11C.glBindTexture;
import static org.lwjgl.opengl.GL11C.glDeleteTextures;
import static org.lwjgl.opengl.GL11C.glGenTextures;
import static org.lwjgl.opengl.GL11C.glGetInteger;
import static org.lwjgl.opengl.GL11C.glPixelStorei;
import static org.lwjgl.opengl.GL11C.glTexImage2D;
import static org.lwjgl.opengl.GL11C.glTexParameteri;
import static org.lwjgl.opengl.GL12C.GL_CLAMP_TO_EDGE;
import static org.lwjgl.opengl.GL13C.GL_ACTIVE_TEXTURE;
import static org.lwjgl.opengl.GL13C.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13C.glActiveTexture;
import static org.lwjgl.opengl.GL30C.GL_R8;

import java.nio.ByteBuffer;

/**
 * A single-channel 8-bit 2D texture ({@code GL_R8}), linearly filtered and clamped at its edges, read
 * in shaders as a {@code sampler2D} in [0, 1]: the terrain's contact-occlusion map. Render thread only.
 */
public final class GlTexture2D extends GlResource {
    /**
     * Makes and fills the texture. Puts back the active unit, its 2D binding and the unpack alignment.
     *
     * @param tracker counts the object
     * @param width   texels along S (X)
     * @param height  texels along T (Z)
     * @param texels  {@code width * height} bytes, rows of S, from its position
     */
    public GlTexture2D(GlTracker tracker, int width, int height, ByteBuffer texels) {
        super(tracker, glGenTextures());
        int unit = glGetInteger(GL_ACTIVE_TEXTURE);
        glActiveTexture(GL_TEXTURE0);
        int bound = glGetInteger(GL_TEXTURE_BINDING_2D);
        int align = glGetInteger(GL_UNPACK_ALIGNMENT);
        try {
            glBindTexture(GL_TEXTURE_2D, id());
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, width, height, 0, GL_RED, GL_UNSIGNED_BYTE, texels);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        } finally {
            glPixelStorei(GL_UNPACK_ALIGNMENT, align);
            glBindTexture(GL_TEXTURE_2D, bound);
            glActiveTexture(unit);
        }
    }

    /**
     * Binds to a texture unit's 2D target (and makes that unit active).
     *
     * @param unit texture unit index, 0 for {@code GL_TEXTURE0}
     */
    public void bind(int unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, id());
    }

    @Override
    public void delete(int name) {
        glDeleteTextures(name);
    }
}
