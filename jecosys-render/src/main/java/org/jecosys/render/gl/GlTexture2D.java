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
import static org.lwjgl.opengl.GL11C.glGetIntegerv;
import static org.lwjgl.opengl.GL11C.glPixelStorei;
import static org.lwjgl.opengl.GL11C.glTexImage2D;
import static org.lwjgl.opengl.GL11C.glTexParameteri;
import static org.lwjgl.opengl.GL11C.GL_LINEAR_MIPMAP_LINEAR;
import static org.lwjgl.opengl.GL11C.GL_REPEAT;
import static org.lwjgl.opengl.GL11C.glTexSubImage2D;
import static org.lwjgl.opengl.GL12C.GL_CLAMP_TO_EDGE;
import static org.lwjgl.opengl.GL30C.GL_RG;
import static org.lwjgl.opengl.GL30C.GL_RG8;
import static org.lwjgl.opengl.GL30C.glGenerateMipmap;
import static org.lwjgl.opengl.GL13C.GL_ACTIVE_TEXTURE;
import static org.lwjgl.opengl.GL13C.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13C.glActiveTexture;
import static org.lwjgl.opengl.GL30C.GL_R8;
import static org.lwjgl.opengl.GL11C.GL_RGBA8;

import java.nio.ByteBuffer;

/**
 * An 8-bit 2D texture of one, two or four channels ({@code GL_R8}, {@code GL_RG8}, {@code GL_RGBA8}),
 * linearly filtered, read in shaders as a {@code sampler2D} in [0, 1]: either clamped at its edges (a
 * map over the terrain: the contact occlusion, the ground cover and the sun's shadows) or repeating with mipmaps (a tile, such as the ground cover's
 * grain, which the mipmaps band-limit at any distance). Render thread only.
 */
public final class GlTexture2D extends GlResource {
    private final int width;
    private final int height;
    private final int channels;
    /** The answer of {@link #query}, so that {@link #upload} allocates nothing. */
    private final int[] queried = new int[1];

    /**
     * Makes and fills a one-channel texture clamped at its edges. Puts back the active unit, its 2D
     * binding and the unpack alignment.
     *
     * @param tracker counts the object
     * @param width   texels along S (X)
     * @param height  texels along T (Z)
     * @param texels  {@code width * height} bytes, rows of S, from its position
     */
    public GlTexture2D(GlTracker tracker, int width, int height, ByteBuffer texels) {
        this(tracker, width, height, 1, false, texels);
    }

    /**
     * Makes and fills the texture. Puts back the active unit, its 2D binding and the unpack alignment.
     *
     * @param tracker  counts the object
     * @param width    texels along S (X)
     * @param height   texels along T (Z)
     * @param channels 1 (red), 2 (red, green) or 4 (red, green, blue, alpha)
     * @param tile     true: repeating, with mipmaps; false: clamped at the edges, no mipmaps
     * @param texels   {@code width * height * channels} bytes, rows of S, channels interleaved, from its
     *                 position
     */
    public GlTexture2D(GlTracker tracker, int width, int height, int channels, boolean tile, ByteBuffer texels) {
        super(tracker, glGenTextures());
        if (channels != 1 && channels != 2 && channels != 4) {
            throw new IllegalArgumentException("channels must be 1, 2 or 4, got " + channels);
        }
        this.width = width;
        this.height = height;
        this.channels = channels;
        int unit = glGetInteger(GL_ACTIVE_TEXTURE);
        glActiveTexture(GL_TEXTURE0 + TextureUnits.UPLOAD);
        int bound = glGetInteger(GL_TEXTURE_BINDING_2D);
        int align = glGetInteger(GL_UNPACK_ALIGNMENT);
        try {
            glBindTexture(GL_TEXTURE_2D, id());
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexImage2D(GL_TEXTURE_2D, 0, channels == 1 ? GL_R8 : channels == 2 ? GL_RG8 : GL_RGBA8, width,
                    height, 0, format(), GL_UNSIGNED_BYTE, texels);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, tile ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, tile ? GL_REPEAT : GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, tile ? GL_REPEAT : GL_CLAMP_TO_EDGE);
            if (tile) {
                glGenerateMipmap(GL_TEXTURE_2D);
            }
        } finally {
            glPixelStorei(GL_UNPACK_ALIGNMENT, align);
            glBindTexture(GL_TEXTURE_2D, bound);
            glActiveTexture(unit);
        }
    }

    /** The pixel format of the texels handed over: one byte per channel. */
    private int format() {
        return channels == 1 ? GL_RED : channels == 2 ? GL_RG : org.lwjgl.opengl.GL11C.GL_RGBA;
    }

    /**
     * Replaces the texels of a texture made without mipmaps. Puts back the active unit, its 2D binding
     * and the unpack alignment. Render thread; no allocation.
     *
     * @param texels {@code width * height * channels} bytes, rows of S, from its position
     */
    public void upload(ByteBuffer texels) {
        if (texels.remaining() < width * height * channels) {
            throw new IllegalArgumentException("need " + width * height * channels + " bytes, got " + texels.remaining());
        }
        int unit = query(GL_ACTIVE_TEXTURE);
        glActiveTexture(GL_TEXTURE0 + TextureUnits.UPLOAD);
        int bound = query(GL_TEXTURE_BINDING_2D);
        int align = query(GL_UNPACK_ALIGNMENT);
        try {
            glBindTexture(GL_TEXTURE_2D, id());
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, format(), GL_UNSIGNED_BYTE, texels);
        } finally {
            glPixelStorei(GL_UNPACK_ALIGNMENT, align);
            glBindTexture(GL_TEXTURE_2D, bound);
            glActiveTexture(unit);
        }
    }

    /**
     * One integer state query into {@link #queried}: LWJGL's {@code glGetInteger(pname)} wraps its stack
     * word in a new {@code IntBuffer} (56 bytes), which only C2's escape analysis removes, so a ground
     * cover's per-frame bend-map upload allocated 168 bytes a frame until C2 compiled it.
     */
    private int query(int pname) {
        glGetIntegerv(pname, queried);
        return queried[0];
    }

    /**
     * Binds to a texture unit's 2D target (and makes that unit active).
     *
     * @param unit texture unit index, 0 for {@code GL_TEXTURE0}: one of {@link TextureUnits}
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
