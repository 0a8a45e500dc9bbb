package org.jecosys.render.ground;

import static org.lwjgl.opengl.GL11C.GL_BLEND;
import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_ONE;
import static org.lwjgl.opengl.GL11C.GL_ONE_MINUS_SRC_ALPHA;
import static org.lwjgl.opengl.GL11C.GL_POLYGON_OFFSET_FILL;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.GL_UNSIGNED_INT;
import static org.lwjgl.opengl.GL11C.GL_ZERO;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glDrawElements;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glPolygonOffset;
import static org.lwjgl.opengl.GL14C.glBlendFuncSeparate;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniform1i;
import static org.lwjgl.opengl.GL20C.glUniform2f;
import static org.lwjgl.opengl.GL20C.glUniform4f;
import static org.lwjgl.opengl.GL20C.glUseProgram;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;

import org.jecosys.math.Camera;
import org.jecosys.math.Require;
import org.jecosys.render.GlContext;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.gl.Closing;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlVertexArray;
import org.jecosys.render.gl.TextureUnits;
import org.jecosys.terrain.Heightfield;

/**
 * The ground cover's skin: the far part of the ground cover ({@code <groundCover>}) for a host that
 * draws its own ground ({@link RenderSettings#terrain()} off). A mesh on the scene's heightfield (the
 * terrain renderer's own vertex and index buffers, its horizon skirt left out) carrying what the
 * terrain shader lays over its soil ({@code ground_cover.glsl}: the cover's colour and grain, the dry
 * patches, the wind's sheen from the plants' bends, the contact darkening and the plants' sun
 * shadows, the haze), drawn over whatever the host drew: depth-tested against the host's depth
 * without writing it, each vertex moved 0.2% of its distance toward the eye along its view ray plus
 * a polygon offset of (-1, -2), so it wins over a host's ground at the same height and loses to
 * things standing on it; blended with premultiplied alpha, open in the cover's gaps and where it thins
 * out at its extent (the cover map), faded out over the last {@code max(spread, 2 cells)} metres inside
 * the terrain's border. Where the host's ground shows through, the contact darkening and the plants'
 * shadows still darken it. The near blades ({@link CoverBlades}) stand in it.
 *
 * <p>Render thread only; made at the first frame that draws it (allocates), then {@link #draw}
 * allocates nothing. Sets the blend function, polygon offset and depth mask it needs and leaves blend
 * and polygon offset off and the depth mask on (the scene renderer's state guard puts back the
 * host's).
 */
public final class CoverSkin implements AutoCloseable {
    /** Share of its distance to the eye a skin vertex is moved toward the eye (the depth bias). */
    public static final float LIFT = 0.002f;
    /** Polygon offset factor and units of the skin: toward the eye. */
    static final float OFFSET_FACTOR = -1f;
    static final float OFFSET_UNITS = -2f;

    private final TerrainRenderer terrain;
    private final GlProgram program;
    private final GlVertexArray vao;
    private final int indexCount;
    private final SurfaceUniforms surface;
    private final int uEdge;
    private final CoverBlades blades;
    private ShadowParams shadow = new ShadowParams();
    private boolean closed;

    /**
     * Makes the program and a vertex array over the terrain renderer's mesh. Render thread; allocates.
     * The terrain renderer and the blades must outlive this skin.
     *
     * @param gl      the render context, current on this thread
     * @param terrain the mesh, the ground maps (contact occlusion, cover, sun shadow) and the grain
     * @param blades  the near blades, whose bend map the sheen reads
     */
    public CoverSkin(GlContext gl, TerrainRenderer terrain, CoverBlades blades) {
        gl.checkThread();
        this.terrain = Require.nonNull("terrain", terrain);
        this.blades = Require.nonNull("blades", blades);
        ContactOcclusion m = Require.nonNull("the terrain's occlusion map (a world with plants)", terrain.occlusionMap());
        GlTracker t = GlContexts.tracker(gl);
        GlProgram prog = null;
        GlVertexArray va = null;
        try {
            prog = GlProgram.variant(t, "terrain.vert", "cover_skin.frag", "COVER_SKIN");
            va = new GlVertexArray(t);
            va.bind();
            terrain.vertexBuffer().bind();
            terrain.indexBuffer().bind();
            for (int a = 0; a < 3; a++) {
                glEnableVertexAttribArray(a);
                glVertexAttribPointer(a, 3, GL_FLOAT, false, 9 * 4, a * 12L);
            }
            glBindVertexArray(0);
        } catch (RuntimeException e) {
            glBindVertexArray(0);
            Closing.closeAll(va, prog);
            throw e;
        }
        program = prog;
        vao = va;
        indexCount = 3 * terrain.triangles();
        surface = new SurfaceUniforms(program);
        uEdge = program.uniform("uEdge");
        int previous = org.lwjgl.opengl.GL11C.glGetInteger(org.lwjgl.opengl.GL20C.GL_CURRENT_PROGRAM);
        program.use();
        glUniform1i(program.uniform("uOcclusion"), TextureUnits.GROUND_MAPS);
        GroundUniforms.bindShadowSampler(program);
        CoverUniforms.bindSamplers(program);
        glUniform4f(program.uniform("uOcclusionMap"), (float) m.minX, (float) m.minZ,
                (float) (1 / (m.texelX * m.width)), (float) (1 / (m.texelZ * m.height)));
        glUniform2f(program.uniform("uOcclusionHalf"), 0.5f / m.width, 0.5f / m.height);
        float[] bend = blades.bendMapTransform();
        glUniform4f(program.uniform("uBendMap"), bend[0], bend[1], bend[2], bend[3]);
        Heightfield h = blades.heightfield();
        glUniform4f(program.uniform("uBounds"), (float) h.minX(), (float) h.minZ(),
                (float) (h.minX() + (h.resolution() - 1) * h.cellX()), (float) (h.minZ() + (h.resolution() - 1) * h.cellZ()));
        glUniform1f(program.uniform("uLift"), LIFT);
        glUseProgram(previous);
    }

    /**
     * Draws the skin into the bound framebuffer, depth-tested (the caller's depth test and function)
     * against what is there, without writing depth. Binds the ground maps to
     * {@link TextureUnits#GROUND_MAPS}, the grain to {@link TextureUnits#COVER_GRAIN} and the bend map
     * to {@link TextureUnits#TILE_BENDS}; call after {@link TerrainRenderer#prepareCover} returned true
     * and after the blades' {@link CoverBlades#prepare} for this frame. Render thread; no allocation.
     *
     * @param camera   the viewer
     * @param settings the light, haze, patches, shadows and the cover
     */
    public void draw(Camera camera, RenderSettings settings) {
        boolean shadows = terrain.prepareShadows(settings);
        program.use();
        boolean sheen = settings.sheen() > 0;
        surface.set(camera, settings, shadow, shadows, true, sheen, 0f); // the skin stays on the terrain's square
        Heightfield h = blades.heightfield();
        glUniform1f(uEdge, (float) Math.max(settings.groundCover().spread(), 2 * Math.max(h.cellX(), h.cellZ())));
        if (sheen) {
            blades.bendMap().bind(TextureUnits.TILE_BENDS);
        }
        terrain.grain().bind(TextureUnits.COVER_GRAIN);
        terrain.maps().bind(TextureUnits.GROUND_MAPS);
        glDepthMask(false);
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(OFFSET_FACTOR, OFFSET_UNITS);
        vao.bind();
        glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, 0L);
        glBindVertexArray(0);
        glPolygonOffset(0f, 0f);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_BLEND);
        glDepthMask(true);
    }

    /** {@return the triangles the skin draws: the heightfield's} */
    public int triangles() {
        return indexCount / 3;
    }

    /**
     * Reads the sun's shadow map from this holder at every draw from now on (as
     * {@link TerrainRenderer#useShadowMap}). Render thread; no allocation.
     *
     * @param params the frame's shadow map, kept (not copied)
     * @throws IllegalArgumentException when params is null
     */
    public void useShadowMap(ShadowParams params) {
        shadow = Require.nonNull("params", params);
    }

    /** Deletes the program and vertex array (the mesh is the terrain renderer's). Render thread; idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            Closing.closeAll(vao, program);
            surface.close();
        }
    }
}
