package org.jecosys.plant;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import org.jecosys.math.Require;

/**
 * The per-plant render record proposed for the renderer: exactly {@link #BYTES} = 16 bytes per
 * plant beyond the simulation state (the per-plant memory budget), uploaded once per scene (plants do not move)
 * into a preallocated instance buffer. The bend of each component (deviation, pose coordinate,
 * azimuth) is simulation state and is not counted here.
 *
 * <pre>
 * offset size  field
 *  0     4     x        float32, metres (world)
 *  4     4     y        float32, metres (terrain height of the base)
 *  8     4     z        float32, metres
 * 12     2     azimuth  uint16, rest azimuth about Y, radians * 65536 / (2 pi)  (resolution 0.0055 deg)
 * 14     2     kind     uint16, species index &lt;&lt; 6 | shape variant  (species &lt; 1024, variant &lt; 64)
 * </pre>
 * Little-endian (GL's native order on every supported platform). Shader side: attribute
 * {@code vec3 pos} (float) plus {@code uvec2 azimuthKind} (GL_UNSIGNED_SHORT, integer attribute).
 *
 * <p>Static pure functions; any thread; no allocation.
 */
public final class InstanceLayout {
    /** Bytes per plant instance. */
    public static final int BYTES = 16;
    /** Byte offset of x (float32). */
    public static final int X = 0;
    /** Byte offset of y (float32). */
    public static final int Y = 4;
    /** Byte offset of z (float32). */
    public static final int Z = 8;
    /** Byte offset of the packed rest azimuth (uint16). */
    public static final int AZIMUTH = 12;
    /** Byte offset of the packed species and variant (uint16). */
    public static final int KIND = 14;
    /** Largest species index that fits. */
    public static final int MAX_SPECIES = 1023;
    /** Largest shape variant that fits (VariationDef allows at most 64 variants). */
    public static final int MAX_VARIANT = 63;

    private InstanceLayout() {
    }

    /**
     * The rest azimuth as a uint16.
     *
     * @param azimuth rest azimuth, radians (any value; wrapped to one turn)
     * @return in [0, 65535], 65536 steps per turn
     */
    public static int packAzimuth(double azimuth) {
        double turns = azimuth / (2 * Math.PI);
        turns -= Math.floor(turns);
        return (int) Math.round(turns * 65536.0) & 0xFFFF;
    }

    /**
     * The azimuth of a packed value.
     *
     * @param packed a value of {@link #packAzimuth} (only the low 16 bits are read)
     * @return radians, in [0, 2 pi)
     */
    public static double unpackAzimuth(int packed) {
        return (packed & 0xFFFF) * (2 * Math.PI / 65536.0);
    }

    /**
     * Species and variant packed into a uint16: {@code species << 6 | variant}.
     *
     * @param species species index, in [0, {@link #MAX_SPECIES}]
     * @param variant shape variant, in [0, {@link #MAX_VARIANT}]
     * @return the packed kind, in [0, 65535]
     * @throws IllegalArgumentException when an index does not fit
     */
    public static int packKind(int species, int variant) {
        Require.range("species", species, 0, MAX_SPECIES);
        Require.range("variant", variant, 0, MAX_VARIANT);
        return species << 6 | variant;
    }

    /**
     * {@return the species index of a packed kind}
     *
     * @param kind a value of {@link #packKind}
     */
    public static int species(int kind) {
        return (kind & 0xFFFF) >>> 6;
    }

    /**
     * {@return the shape variant of a packed kind}
     *
     * @param kind a value of {@link #packKind}
     */
    public static int variant(int kind) {
        return kind & 0x3F;
    }

    /**
     * Writes instance {@code instance} at byte {@code instance * BYTES} of {@code dest} (absolute
     * puts; the buffer's position is unchanged; its order must be little-endian).
     *
     * @param dest     the instance buffer, little-endian
     * @param instance instance index, in [0, dest.limit() / BYTES)
     * @param x        world X of the plant's base, metres
     * @param y        terrain height of the base, metres
     * @param z        world Z of the base, metres
     * @param azimuth  rest azimuth, radians (packed by {@link #packAzimuth})
     * @param species  species index, in [0, {@link #MAX_SPECIES}]
     * @param variant  shape variant, in [0, {@link #MAX_VARIANT}]
     * @throws IllegalArgumentException when dest is null or big-endian or an index is out of range
     */
    public static void put(ByteBuffer dest, int instance, float x, float y, float z, double azimuth,
                           int species, int variant) {
        Require.nonNull("dest", dest);
        if (dest.order() != ByteOrder.LITTLE_ENDIAN) {
            throw new IllegalArgumentException("dest must be little-endian");
        }
        int o = Require.range("instance", instance, 0, dest.limit() / BYTES - 1) * BYTES;
        dest.putFloat(o + X, x);
        dest.putFloat(o + Y, y);
        dest.putFloat(o + Z, z);
        dest.putShort(o + AZIMUTH, (short) packAzimuth(azimuth));
        dest.putShort(o + KIND, (short) packKind(species, variant));
    }
}
