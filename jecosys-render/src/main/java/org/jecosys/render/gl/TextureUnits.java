package org.jecosys.render.gl;

/**
 * Every texture unit the renderers use, one meaning per unit: the number a texture is bound to
 * ({@code bind(unit)}) and the value its sampler uniform is set to ({@code glUniform1i}); no shader
 * fixes a unit with a {@code layout(binding)}. Units {@code 0} to {@link #GUARDED} - 1 are the ones
 * {@link GlStateGuard} saves and puts back around a frame (their buffer-texture and 2D bindings and
 * sampler objects); the resolve filter of {@link GlFramebuffer} runs outside the guard and puts back
 * its two units itself.
 *
 * <p>The per-component resolve pass reads units {@link #POSES} to {@link #BEND_GEOMETRY}; the plants'
 * draws read {@link #POSES}, {@link #RECORDS}, {@link #SUN_SHADOW} and {@link #PLANT_TEXTURES}; the terrain reads
 * {@link #GROUND_MAPS}, {@link #COVER_GRAIN}, {@link #TILE_BENDS} and {@link #SUN_SHADOW}; the ground
 * cover's blades {@link #GROUND_MAPS}, {@link #TILE_BENDS}, {@link #GROUND_HEIGHTS} and
 * {@link #SUN_SHADOW}. OpenGL 3.3 guarantees 48 combined units, so each meaning has its own.
 */
public final class TextureUnits {
    private TextureUnits() {
    }

    /** The pose tables (buffer texture, RGBA32F, 3 texels per skeleton point): resolve pass and draws. */
    public static final int POSES = 0;
    /** The drawn plants' instance records (buffer texture, RG32I): resolve pass. */
    public static final int INSTANCES = 1;
    /** The components' render states, their deviations (buffer texture, RG32F): resolve pass. */
    public static final int RENDER_STATES = 2;
    /** The components' static data, root base and first pose texel (buffer texture, RGBA32F): resolve pass. */
    public static final int STATIC = 3;
    /** The components' links to their parents (buffer texture, RGBA32I): resolve pass. */
    public static final int LINKS = 4;
    /** The components' baked colour variation (buffer texture, RG32UI): resolve pass. */
    public static final int LOOKS = 5;
    /** The species slots' looks, colour and vertex kind (buffer texture, RGBA32F): resolve pass. */
    public static final int SLOT_LOOKS = 6;
    /** The list table of the compute resolve path (buffer texture, RGBA32I): compute resolve pass. */
    public static final int LIST_TABLE = 7;
    /** The components' bend geometry, rest lean, length and pose scale (buffer texture, RGBA32F): resolve pass. */
    public static final int BEND_GEOMETRY = 8;
    /** The resolved component records (buffer texture, RGBA32F, 3 texels each): the plants' draws. */
    public static final int RECORDS = 9;
    /** The sun's shadow map (2D depth texture, compared): the plants' receivers, the terrain, the cover. */
    public static final int SUN_SHADOW = 10;
    /** The ground's maps: contact occlusion, cover level, splatted sun shadow (2D): terrain and cover. */
    public static final int GROUND_MAPS = 11;
    /** The ground cover's grain tile (2D, mipmapped, repeating): terrain. */
    public static final int COVER_GRAIN = 12;
    /** The plants' mean bend per ground tile (2D): the terrain's sheen and the cover's blades. */
    public static final int TILE_BENDS = 13;
    /** The heightfield (buffer texture, R32F): the cover's blades. */
    public static final int GROUND_HEIGHTS = 14;
    /**
     * The unit the GL wrappers bind a texture on while they make or fill it, putting the unit's binding
     * back after ({@link GlTexture2D}, {@link GlDepthMap}, the framebuffer's images); the active unit
     * after {@link GlStateGuard#setGuestState()}, so a buffer texture made then is bound on a guarded unit.
     */
    public static final int UPLOAD = 15;
    /**
     * The images drawn on components (2D array, mipmapped, a layer per image: {@link GlTextureArray}): the
     * plants' triangle draws. The guard puts back this unit's 2D-array binding too.
     */
    public static final int PLANT_TEXTURES = 16;
    /** Units {@code 0} to this - 1 are saved and put back by {@link GlStateGuard}. */
    public static final int GUARDED = 17;
    /** The box-averaged image the framebuffer's resolve filter reads (2D), outside the guard. */
    public static final int FILTER_IMAGE = 17;
    /** The detail mask the framebuffer's resolve filter reads (2D), outside the guard. */
    public static final int FILTER_DETAIL = 18;
    /** The depth of the frame a temporal resolve reprojects its history with (2D), outside the guard. */
    public static final int TEMPORAL_DEPTH = 19;
    /** The running mean of earlier frames a temporal resolve reads (2D), outside the guard. */
    public static final int TEMPORAL_HISTORY = 20;
    /** Every unit the library uses is below this. */
    public static final int COUNT = 21;
}
