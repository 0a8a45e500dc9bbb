package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL11C.GL_LINEAR;
import static org.lwjgl.opengl.GL11C.GL_LINEAR_MIPMAP_LINEAR;
import static org.lwjgl.opengl.GL11C.GL_RGBA;
import static org.lwjgl.opengl.GL11C.GL_RGBA8;
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
import static org.lwjgl.opengl.GL11C.glTexParameteri;
import static org.lwjgl.opengl.GL12C.GL_CLAMP_TO_EDGE;
import static org.lwjgl.opengl.GL12C.GL_TEXTURE_MAX_LEVEL;
import static org.lwjgl.opengl.GL12C.glTexImage3D;
import static org.lwjgl.opengl.GL12C.glTexSubImage3D;
import static org.lwjgl.opengl.GL13C.GL_ACTIVE_TEXTURE;
import static org.lwjgl.opengl.GL13C.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13C.glActiveTexture;
import static org.lwjgl.opengl.GL30C.GL_TEXTURE_2D_ARRAY;
import static org.lwjgl.opengl.GL30C.GL_TEXTURE_BINDING_2D_ARRAY;

import java.nio.ByteBuffer;
import org.lwjgl.system.MemoryUtil;

/**
 * A square RGBA8 2D array texture with its whole mip chain given level by level (the images drawn on
 * components, {@code org.jecosys.plant.PlantTextures}): trilinear filtering (or bilinear in the nearest
 * mip level, for a software rasteriser, where a trilinear fetch per fragment made the textured meadow's
 * frame 1.34 times the plain one's at 1080p, and the nearest level 1.13 times), clamped at the edges.
 * Render thread; the constructor allocates (a native staging buffer, freed before it returns).
 */
public final class GlTextureArray extends GlResource {
    /** The texels of one level of one layer. */
    @FunctionalInterface
    public interface Levels {
        /**
         * {@return RGBA bytes, {@code (side >> level)^2 * 4} of them, rows from t = 0}
         *
         * @param layer the layer
         * @param level the mip level
         */
        byte[] texels(int layer, int level);
    }

    private final int side;
    private final int layers;

    /**
     * Makes and fills the texture. Puts back the active unit, its 2D-array binding and the unpack
     * alignment.
     *
     * @param tracker   counts the object
     * @param side      texels a side of level 0, a power of two
     * @param layers    layers, &gt;= 1
     * @param levels    the texels of each level of each layer, levels 0 to log2(side)
     * @param trilinear blend the two nearest mip levels (else bilinear in the nearest one)
     */
    public GlTextureArray(GlTracker tracker, int side, int layers, Levels levels, boolean trilinear) {
        super(tracker, glGenTextures());
        if (side < 1 || Integer.bitCount(side) != 1) {
            throw new IllegalArgumentException("side must be a power of two, got " + side);
        }
        if (layers < 1) {
            throw new IllegalArgumentException("layers must be >= 1, got " + layers);
        }
        this.side = side;
        this.layers = layers;
        int count = Integer.numberOfTrailingZeros(side) + 1;
        int unit = glGetInteger(GL_ACTIVE_TEXTURE);
        glActiveTexture(GL_TEXTURE0 + TextureUnits.UPLOAD);
        int bound = glGetInteger(GL_TEXTURE_BINDING_2D_ARRAY);
        int align = glGetInteger(GL_UNPACK_ALIGNMENT);
        ByteBuffer staging = MemoryUtil.memAlloc(4 * side * side);
        try {
            glBindTexture(GL_TEXTURE_2D_ARRAY, id());
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            for (int m = 0; m < count; m++) {
                int s = side >> m;
                glTexImage3D(GL_TEXTURE_2D_ARRAY, m, GL_RGBA8, s, s, layers, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                        (ByteBuffer) null);
                for (int k = 0; k < layers; k++) {
                    byte[] t = levels.texels(k, m);
                    if (t.length != 4 * s * s) {
                        throw new IllegalArgumentException("layer " + k + " level " + m + ": " + t.length
                                + " bytes, not " + 4 * s * s);
                    }
                    staging.clear();
                    staging.put(t).flip();
                    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, m, 0, 0, k, s, s, 1, GL_RGBA, GL_UNSIGNED_BYTE, staging);
                }
            }
            glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, count - 1);
            glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, trilinear ? GL_LINEAR_MIPMAP_LINEAR
                    : org.lwjgl.opengl.GL11C.GL_LINEAR_MIPMAP_NEAREST);
            glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        } catch (RuntimeException e) {
            glBindTexture(GL_TEXTURE_2D_ARRAY, bound);
            glActiveTexture(unit);
            close();
            throw e;
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) staging);
            glPixelStorei(GL_UNPACK_ALIGNMENT, align);
            glBindTexture(GL_TEXTURE_2D_ARRAY, bound);
            glActiveTexture(unit);
        }
    }

    /** {@return texels a side of level 0} */
    public int side() {
        return side;
    }

    /** {@return the number of layers} */
    public int layers() {
        return layers;
    }

    /**
     * Binds to a texture unit's 2D-array target (and makes that unit active). No allocation.
     *
     * @param unit texture unit index: {@link TextureUnits#PLANT_TEXTURES}
     */
    public void bind(int unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D_ARRAY, id());
    }

    @Override
    public void delete(int name) {
        glDeleteTextures(name);
    }
}
