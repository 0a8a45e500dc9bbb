package org.jecosys.render.ground;

import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.Closing;
import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.GL_UNSIGNED_INT;
import static org.lwjgl.opengl.GL11C.glDrawElements;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_ELEMENT_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glUniform1i;
import static org.lwjgl.opengl.GL20C.glUniform2f;
import static org.lwjgl.opengl.GL20C.glUniform4f;
import static org.lwjgl.opengl.GL20C.glUseProgram;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import org.jecosys.math.Camera;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import org.jecosys.terrain.ResourceMap;
import org.jecosys.terrain.Terrain;
import org.jecosys.terrain.TerrainMaps;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.GlContext;
import org.jecosys.render.RenderSettings;
import org.jecosys.scene.RenderDef;
import org.jecosys.render.gl.GlBuffer;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.TextureUnits;
import org.jecosys.render.gl.GlTexture2D;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlVertexArray;

/**
 * The lit terrain: the heightfield as one indexed triangle mesh (vertex position, normal, colour),
 * optionally tinted by the water or nutrient map (paper §4.3), lit by the sun and the sky's ambient
 * light, coloured by the healthy/dry patches, darkened under the plants by a contact-occlusion map
 * (built once from the plants' footprints), its sun's share taken away in the plants' sun shadows when
 * {@code <light shadows>} is on (both maps in {@link GroundMaps}' texture) and hazed toward the
 * horizon with distance as the plants are. Render thread only; {@link #draw} allocates nothing;
 * {@link #setTint} re-uploads the colours (not per frame).
 */
public final class TerrainRenderer implements AutoCloseable {
    private static final int FLOATS = 9;
    private static final float SOIL_R = 0.34f;
    private static final float SOIL_G = 0.27f;
    private static final float SOIL_B = 0.17f;
    private static final float MOSS_R = 0.21f;
    private static final float MOSS_G = 0.24f;
    private static final float MOSS_B = 0.12f;

    private final Terrain terrain;
    private final int res;
    private final float[] heights;
    private final float[] normals;
    private final GlProgram program;
    private final GlVertexArray vao;
    private final GlBuffer vertices;
    private final GlBuffer indices;
    private final int indexCount;
    /** The view, light, haze, shadow and cover uniforms, set as the cover skin sets its own. */
    private final SurfaceUniforms surface;
    private GlTexture2D bendMap;
    /** Contact occlusion (red), ground cover (green) and sun shadow (blue) over the terrain. */
    private final GroundMaps maps;
    /** The grid of those maps; null when built without plants. */
    private final ContactOcclusion occlusionMap;
    /** The ground cover's grain: a repeating, mipmapped tile. */
    private final GlTexture2D grain;
    /** The frame's sun shadow map, as {@link #useShadowMap} gave it (none until then). */
    private ShadowParams shadow = new ShadowParams();
    private RenderDef.Tint tint;
    private boolean closed;

    /**
     * Builds and uploads the mesh. Render thread; allocates.
     *
     * @param gl      the render context, current on this thread
     * @param terrain the heightfield and the resource maps the tints read
     * @param tint    the initial tint
     */
    public TerrainRenderer(GlContext gl, Terrain terrain, RenderDef.Tint tint) {
        this(gl, terrain, null, tint);
    }

    /**
     * Builds and uploads the mesh and the contact-occlusion map of the world's plants. Render thread;
     * allocates.
     *
     * @param gl    the render context, current on this thread
     * @param world the terrain, and the plants whose bases darken it
     * @param tint  the initial tint
     */
    public TerrainRenderer(GlContext gl, World world, RenderDef.Tint tint) {
        this(gl, world.terrain(), world, tint);
    }

    private TerrainRenderer(GlContext gl, Terrain terrain, World world, RenderDef.Tint tint) {
        gl.checkThread();
        this.terrain = terrain;
        Heightfield h = terrain.heightfield();
        res = h.resolution();
        heights = h.copyHeights(new float[res * res]);
        normals = h.copyNormals(new float[3 * res * res]);
        GlTracker t = GlContexts.tracker(gl);
        GlProgram prog = null;
        GlVertexArray va = null;
        GlBuffer vb = null;
        GlBuffer ib = null;
        GroundMaps occ = null;
        GlTexture2D gr = null;
        FloatBuffer v = MemoryUtil.memAllocFloat(vertexCount() * FLOATS);
        IntBuffer idx = MemoryUtil.memAllocInt(6 * (res - 1) * (res - 1) + 6 * rim());
        ByteBuffer texels = MemoryUtil.memAlloc(CoverGrain.SIDE * CoverGrain.SIDE);
        try {
            occ = new GroundMaps(t, world);
            gr = new GlTexture2D(t, CoverGrain.SIDE, CoverGrain.SIDE, 1, true, CoverGrain.bytes(texels));
            prog = new GlProgram(t, "terrain.vert", "terrain.frag");
            va = new GlVertexArray(t);
            va.bind();
            fill(v, tint);
            for (int j = 0; j < res - 1; j++) {
                for (int i = 0; i < res - 1; i++) {
                    int a = j * res + i;
                    idx.put(a).put(a + res).put(a + 1).put(a + 1).put(a + res).put(a + res + 1);
                }
            }
            // the horizon skirt: a quad from each edge of the rim outward to the far ground
            int rim = rim();
            for (int r = 0; r < rim; r++) {
                int a = rimVertex(r);
                int b = rimVertex((r + 1) % rim);
                int oa = res * res + r;
                int ob = res * res + (r + 1) % rim;
                idx.put(a).put(oa).put(b).put(b).put(oa).put(ob);
            }
            idx.flip();
            vb = GlBuffer.of(t, GL_ARRAY_BUFFER, v, GL_STATIC_DRAW);
            ib = GlBuffer.of(t, GL_ELEMENT_ARRAY_BUFFER, idx, GL_STATIC_DRAW);
        } catch (RuntimeException e) {
            glBindVertexArray(0);
            Closing.closeAll(vb, va, prog, occ, gr);
            throw e;
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) v);
            MemoryUtil.memFree((java.nio.Buffer) idx);
            MemoryUtil.memFree((java.nio.Buffer) texels);
        }
        maps = occ;
        occlusionMap = occ.grid;
        grain = gr;
        program = prog;
        vao = va;
        vertices = vb;
        indices = ib;
        indexCount = 6 * (res - 1) * (res - 1) + 6 * rim();
        for (int a = 0; a < 3; a++) {
            glEnableVertexAttribArray(a);
            glVertexAttribPointer(a, 3, GL_FLOAT, false, FLOATS * 4, a * 12L);
        }
        glBindVertexArray(0);
        this.tint = tint;
        surface = new SurfaceUniforms(program);
        int previous = org.lwjgl.opengl.GL11C.glGetInteger(org.lwjgl.opengl.GL20C.GL_CURRENT_PROGRAM);
        program.use();
        glUniform1i(program.uniform("uOcclusion"), TextureUnits.GROUND_MAPS);
        GroundUniforms.bindShadowSampler(program);
        CoverUniforms.bindSamplers(program);
        if (occlusionMap == null) {
            glUniform4f(program.uniform("uOcclusionMap"), 0, 0, 0, 0);
            glUniform2f(program.uniform("uOcclusionHalf"), 0.5f, 0.5f);
        } else {
            ContactOcclusion m = occlusionMap;
            glUniform4f(program.uniform("uOcclusionMap"), (float) m.minX, (float) m.minZ,
                    (float) (1 / (m.texelX * m.width)), (float) (1 / (m.texelZ * m.height)));
            glUniform2f(program.uniform("uOcclusionHalf"), 0.5f / m.width, 0.5f / m.height);
        }
        glUseProgram(previous);
    }

    /**
     * The contact occlusion the terrain shader reads at a ground point (0 open ground, toward 1 under
     * dense plants), for tests and tools. Any thread; no allocation.
     *
     * @param x world X, metres
     * @param z world Z, metres
     * @return the occlusion in [0, 1]; 0 everywhere when built without plants
     */
    public double occlusion(double x, double z) {
        return occlusionMap == null ? 0 : occlusionMap.sample(x, z);
    }

    /** How far the horizon skirt reaches from the terrain's middle, metres: to the horizon, in effect. */
    public static final float SKIRT = 100_000f;

    /** {@return the vertices on the heightfield's rim, once round} */
    private int rim() {
        return 4 * (res - 1);
    }

    /** {@return the grid vertex of rim position r, anticlockwise from the corner (0, 0)} */
    private int rimVertex(int r) {
        int side = res - 1;
        if (r < side) {
            return r;                                   // along j = 0
        } else if (r < 2 * side) {
            return (r - side) * res + side;             // along i = side
        } else if (r < 3 * side) {
            return side * res + (3 * side - r);         // along j = side, backwards
        }
        return (4 * side - r) * res;                    // along i = 0, backwards
    }

    private int vertexCount() {
        return res * res + rim();
    }

    private void fill(FloatBuffer v, RenderDef.Tint tint) {
        Heightfield h = terrain.heightfield();
        ResourceMap water = terrain.water();
        ResourceMap nutrients = terrain.nutrients();
        float[] rgb = new float[3];
        for (int j = 0; j < res; j++) {
            for (int i = 0; i < res; i++) {
                int k = j * res + i;
                double x = h.minX() + i * h.cellX();
                double z = h.minZ() + j * h.cellZ();
                v.put((float) x).put(heights[k]).put((float) z);
                v.put(normals[3 * k]).put(normals[3 * k + 1]).put(normals[3 * k + 2]);
                colour(tint, water, nutrients, x, z, rgb);
                v.put(rgb[0]).put(rgb[1]).put(rgb[2]);
            }
        }
        // the skirt's far edge: each rim vertex pushed out from the middle to SKIRT metres, at the rim's
        // mean height, facing up, in the colour of the ground it continues (the haze hides it far away)
        double mean = 0;
        for (int r = 0; r < rim(); r++) {
            mean += heights[rimVertex(r)];
        }
        mean /= rim();
        double cx = h.minX() + 0.5 * (res - 1) * h.cellX();
        double cz = h.minZ() + 0.5 * (res - 1) * h.cellZ();
        for (int r = 0; r < rim(); r++) {
            int k = rimVertex(r);
            double x = h.minX() + (k % res) * h.cellX();
            double z = h.minZ() + (k / res) * h.cellZ();
            double dx = x - cx;
            double dz = z - cz;
            double len = Math.max(1e-6, Math.hypot(dx, dz));
            v.put((float) (cx + dx / len * SKIRT)).put((float) mean).put((float) (cz + dz / len * SKIRT));
            v.put(0f).put(1f).put(0f);
            colour(tint, water, nutrients, x, z, rgb);
            v.put(rgb[0]).put(rgb[1]).put(rgb[2]);
        }
        v.flip();
    }

    /** The terrain colour at (x, z) for a tint, linear RGB in [0, 1], into {@code dest}. Pure. */
    public static void colour(RenderDef.Tint tint, ResourceMap water, ResourceMap nutrients, double x, double z, float[] dest) {
        switch (tint) {
            case WATER -> lerp(TerrainMaps.WATER_LOW, TerrainMaps.WATER_HIGH, water.sample(x, z), dest);
            case NUTRIENTS -> lerp(TerrainMaps.NUTRIENTS_LOW, TerrainMaps.NUTRIENTS_HIGH, nutrients.sample(x, z), dest);
            default -> {
                // earthy: dry ground a warm brown, wetter ground a darker mossy green-brown
                float w = (float) Math.max(0, Math.min(1, water.sample(x, z)));
                dest[0] = SOIL_R + (MOSS_R - SOIL_R) * w;
                dest[1] = SOIL_G + (MOSS_G - SOIL_G) * w;
                dest[2] = SOIL_B + (MOSS_B - SOIL_B) * w;
            }
        }
    }

    private static void lerp(int lo, int hi, double level, float[] dest) {
        float w = (float) Math.max(0, Math.min(1, level));
        for (int c = 0; c < 3; c++) {
            int shift = 16 - 8 * c;
            float a = ((lo >> shift) & 255) / 255f;
            float b = ((hi >> shift) & 255) / 255f;
            dest[c] = a + (b - a) * w;
        }
    }

    /** {@return the current tint} */
    public RenderDef.Tint tint() {
        return tint;
    }

    /**
     * Re-colours the mesh for another tint. Render thread; allocates a temporary native buffer; not
     * per frame.
     *
     * @param tint the new tint; nothing happens when it is the current one
     */
    public void setTint(RenderDef.Tint tint) {
        if (tint == this.tint) {
            return;
        }
        FloatBuffer v = MemoryUtil.memAllocFloat(vertexCount() * FLOATS);
        try {
            fill(v, tint);
            vertices.upload(0, v);
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) v);
        }
        this.tint = tint;
    }

    /** {@return the number of triangles of the terrain mesh (the heightfield; the horizon skirt left out)} */
    public int triangles() {
        return 2 * (res - 1) * (res - 1);
    }

    /**
     * Draws the terrain into the bound framebuffer with the current depth state: sun direction and
     * colour, ambient light, contact shadow, patches, ground cover and haze from the settings. Binds the
     * occlusion and cover map to {@link TextureUnits#GROUND_MAPS}, the cover's grain to
     * {@link TextureUnits#COVER_GRAIN} and the bend map to {@link TextureUnits#TILE_BENDS} (the scene
     * renderer's state guard puts them back). Render thread;
     * no allocation, except when the cover's spread differs from the map's or, with shadows on, the sun has moved
     * since the shadow map was built: those rebuild a map.
     *
     * @param camera   the viewer
     * @param settings the light, haze, patch and cover settings
     */
    public void draw(Camera camera, RenderSettings settings) {
        draw(camera, settings, true);
    }

    /**
     * As {@link #draw(Camera, RenderSettings)}, but bare ground whatever the settings' cover: the
     * picture without the vegetation (the scene renderer's terrain-only frames). Render thread; no
     * allocation but as {@link #draw(Camera, RenderSettings)} says.
     *
     * @param camera   the viewer
     * @param settings the light, haze and patch settings
     */
    public void drawBare(Camera camera, RenderSettings settings) {
        draw(camera, settings, false);
    }

    private void draw(Camera camera, RenderSettings settings, boolean cover) {
        boolean withCover = cover && prepareCover(settings);
        boolean shadows = maps.prepareShadows(settings);
        program.use();
        boolean sheen = withCover && bendMap != null && settings.sheen() > 0;
        surface.set(camera, settings, shadow, shadows, withCover, sheen, maps.meanCoverLevel());
        if (sheen) {
            bendMap.bind(TextureUnits.TILE_BENDS);
        }
        grain.bind(TextureUnits.COVER_GRAIN);
        maps.texture().bind(TextureUnits.GROUND_MAPS);
        vao.bind();
        glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, 0L);
        glBindVertexArray(0);
    }

    /**
     * Sets the bend map the ground cover's sheen reads (the plants' bends per tile, {@link CoverBlades}).
     * Render thread; no allocation after the first call.
     *
     * @param map       the bend map
     * @param transform {minX, minZ, 1 / width, 1 / height}: world X, Z to the map's texture coordinates
     */
    public void setBendMap(GlTexture2D map, float[] transform) {
        bendMap = map;
        int previous = org.lwjgl.opengl.GL11C.glGetInteger(org.lwjgl.opengl.GL20C.GL_CURRENT_PROGRAM);
        program.use();
        glUniform4f(program.uniform("uBendMap"), transform[0], transform[1], transform[2], transform[3]);
        glUseProgram(previous);
    }

    /**
     * Makes sure the cover map matches the settings' ground cover (rebuilds it when its spread changed:
     * allocates then). Render thread; no allocation otherwise.
     *
     * @param settings the ground cover
     * @return whether there is cover to draw: it is enabled and this terrain was built with plants
     */
    public boolean prepareCover(RenderSettings settings) {
        return maps.prepareCover(settings);
    }

    /**
     * Makes sure the sun-shadow map is of the settings' sun while shadows are on, and blank while they are
     * off (rebuilds it when the sun moved, allocating then); call before anything reads {@link #maps()}
     * in a frame. Render thread; no allocation otherwise.
     *
     * @param settings the sun and {@code shadows}
     * @return whether shadows are drawn: on, with plants and the sun at least 5 degrees up
     */
    public boolean prepareShadows(RenderSettings settings) {
        return maps.prepareShadows(settings);
    }

    /** {@return the contact-occlusion (red), cover (green) and sun-shadow (blue) texture over the terrain} */
    public GlTexture2D maps() {
        return maps.texture();
    }

    /** {@return the contact-occlusion map, whose grid the cover map shares; null when built without plants} */
    public ContactOcclusion occlusionMap() {
        return occlusionMap;
    }

    /** {@return the mesh's vertex buffer (position, normal, colour: 9 floats a vertex), for the cover skin} */
    GlBuffer vertexBuffer() {
        return vertices;
    }

    /** {@return the mesh's index buffer: the heightfield's {@link #triangles()} first, then the horizon skirt} */
    GlBuffer indexBuffer() {
        return indices;
    }

    /** {@return the cover's grain tile, repeating and mipmapped} */
    GlTexture2D grain() {
        return grain;
    }

    /** Deletes the GL objects. Render thread; idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            Closing.closeAll(vao, vertices, indices, program, maps, grain);
            surface.close();
        }
    }

    /**
     * Reads the sun's shadow map from this holder at every draw from now on ({@code sun_shadow.glsl}:
     * whether a map is drawn this frame, its texel, bias and strength, the eye and the map's reach, the
     * world-to-map matrix); the map itself is bound to {@link TextureUnits#SUN_SHADOW} by the caller,
     * who fills the holder each frame. Until then no map is read. Render thread; no allocation.
     *
     * @param params the frame's shadow map, kept (not copied)
     * @throws IllegalArgumentException when params is null
     */
    public void useShadowMap(ShadowParams params) {
        shadow = org.jecosys.math.Require.nonNull("params", params);
    }
}
