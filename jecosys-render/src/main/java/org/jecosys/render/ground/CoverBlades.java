package org.jecosys.render.ground;

import org.jecosys.render.Lighting;
import org.jecosys.render.gl.GlContexts;
import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniform1i;
import static org.lwjgl.opengl.GL20C.glUniform2f;
import static org.lwjgl.opengl.GL20C.glUniform3f;
import static org.lwjgl.opengl.GL20C.glUniform4f;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.GL_R32F;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BUFFER;
import static org.lwjgl.opengl.GL31C.glDrawArraysInstanced;
import static org.lwjgl.opengl.GL33C.glVertexAttribDivisor;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import org.jecosys.math.Camera;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.render.GlContext;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.gl.Closing;
import org.jecosys.render.gl.GlBuffer;
import org.jecosys.render.gl.GlBufferTexture;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.TextureUnits;
import org.jecosys.render.gl.GlTexture2D;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlVertexArray;
import org.jecosys.scene.RenderDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import org.joml.FrustumIntersection;
import org.joml.Matrix4f;
import org.lwjgl.system.MemoryUtil;

/**
 * The near part of the ground cover ({@code <groundCover>}): short blades on the ground around the eye,
 * out to the cover's reach, where the cover map says cover grows, bending with the plants around them.
 * One triangle per blade, made in the vertex shader from its index (no per-blade data): the ground is
 * cut into 1 m tiles on a world lattice, the tiles within the reach that the view's frustum meets are
 * drawn as instances, and each blade of a tile takes its place, height, lean, width and shade from a hash
 * of the tile and its index, so blades stay where they are as the eye moves. Fewer blades are drawn in
 * far tiles (the count falls with the square of the distance beyond a third of the reach; blades
 * beyond the count shrink away smoothly) and all fade into the ground's cover colour at the reach.
 * A frame never submits more than {@link RenderDef.GroundCover#MAX_BLADES_PER_VIEW} blades: the scene
 * check refuses a cover that could ask for more, and a cover set at run time that does is thinned
 * evenly, every tile keeping the same share of its blades (see {@link #bladesPerTile(int, int)}).
 *
 * <p>Wind: once per frame the plants' bends are averaged per tile over the whole terrain (each plant's
 * first component: bend angle over the species' largest, toward its azimuth) into a small two-channel
 * texture, which the blades read bilinearly, so a gust that bends the plants bends the cover under
 * them as it travels. Render thread only; {@link #draw} allocates nothing.
 */
public final class CoverBlades implements AutoCloseable {
    /** Side of a tile, metres ({@link RenderDef.GroundCover#BLADE_TILE}, which the scene check's bound uses). */
    static final float TILE = (float) RenderDef.GroundCover.BLADE_TILE;
    /** Most tiles drawn at once ({@link RenderDef.GroundCover#MAX_BLADE_TILES}). */
    static final int MAX_TILES = RenderDef.GroundCover.MAX_BLADE_TILES;
    /** Floats per tile instance: origin X, Z, blade count, 0. */
    private static final int INSTANCE_FLOATS = 4;

    private final World world;
    private final Heightfield field;
    private final GlProgram program;
    private final GlVertexArray vao;
    private final GlBuffer instances;
    private final GlBuffer heights;
    private final GlBufferTexture heightTexture;
    private final GlTexture2D bendTexture;
    private final FloatBuffer instanceData;
    private final ByteBuffer bendData;
    private final float[] bendSum;
    private final float[] bendWeight;
    /** Per plant: its first component, 1 / (poses - 1) of that component's table, largest bend (rad). */
    private final int[] firstComponent;
    private final float[] poseScale;
    private final float[] maxBend;
    private final int bendWidth;
    private final int bendHeight;
    private final FloatBuffer matrix;
    private final Matrix4f viewProj = new Matrix4f();
    private final FrustumIntersection frustum = new FrustumIntersection();
    private final int uViewProj;
    private final int uEye;
    private final int uBlade;
    private final int uReach;
    private final int uSheen;
    private final int uShadows;
    /** The light, haze, patch, contact-shadow and cover-colour uniforms, shared with the terrain. */
    private final GroundUniforms ground;
    /** The frame's sun shadow map, as {@link #useShadowMap} gave it (none until then). */
    private ShadowParams shadow = new ShadowParams();
    private long bendFrame = Long.MIN_VALUE;
    private Frame bendOf;
    private int lastTiles;
    private int lastBlades;
    private boolean closed;

    /**
     * Builds the programs and buffers. Render thread; allocates.
     *
     * @param gl      the render context, current on this thread
     * @param world   the terrain the blades stand on and the plants whose bends they follow
     * @param terrain the terrain renderer, whose occlusion and cover map the blades read
     */
    public CoverBlades(GlContext gl, World world, TerrainRenderer terrain) {
        gl.checkThread();
        this.world = world;
        this.field = world.terrain().heightfield();
        GlTracker t = GlContexts.tracker(gl);
        int res = field.resolution();
        bendWidth = (int) Math.ceil((res - 1) * field.cellX() / TILE) + 1;
        bendHeight = (int) Math.ceil((res - 1) * field.cellZ() / TILE) + 1;
        bendSum = new float[2 * bendWidth * bendHeight];
        bendWeight = new float[bendWidth * bendHeight];
        int plants = world.plantCount();
        firstComponent = new int[plants];
        poseScale = new float[plants];
        maxBend = new float[plants];
        for (int p = 0; p < plants; p++) {
            SpeciesModel m = world.plants().species().get(world.plantSpecies(p));
            firstComponent[p] = world.firstComponent(p);
            int poses = world.componentsOf(p) == 0 ? 1 : m.slotPoseTable(0, world.plantVariant(p)).poses();
            poseScale[p] = poses > 1 ? 1f / (poses - 1) : 0f;
            maxBend[p] = (float) m.def().maxBend();
        }
        GlProgram prog = null;
        GlVertexArray va = null;
        GlBuffer inst = null;
        GlBuffer hb = null;
        GlBufferTexture ht = null;
        GlTexture2D bt = null;
        FloatBuffer hv = MemoryUtil.memAllocFloat(res * res);
        ByteBuffer bendInit = MemoryUtil.memAlloc(2 * bendWidth * bendHeight);
        try {
            prog = new GlProgram(t, "cover.vert", "cover.frag");
            hv.put(field.copyHeights(new float[res * res])).flip();
            hb = GlBuffer.of(t, GL_TEXTURE_BUFFER, hv, org.lwjgl.opengl.GL15C.GL_STATIC_DRAW);
            ht = new GlBufferTexture(t, hb, GL_R32F);
            while (bendInit.hasRemaining()) {
                bendInit.put((byte) 128);
            }
            bt = new GlTexture2D(t, bendWidth, bendHeight, 2, false, bendInit.flip());
            va = new GlVertexArray(t);
            va.bind();
            inst = GlBuffer.dynamic(t, GL_ARRAY_BUFFER, (long) MAX_TILES * INSTANCE_FLOATS * 4);
            inst.bind();
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 4, GL_FLOAT, false, INSTANCE_FLOATS * 4, 0L);
            glVertexAttribDivisor(0, 1);
            glBindVertexArray(0);
        } catch (RuntimeException e) {
            glBindVertexArray(0);
            Closing.closeAll(inst, va, bt, ht, hb, prog);
            throw e;
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) hv);
            MemoryUtil.memFree((java.nio.Buffer) bendInit);
        }
        program = prog;
        vao = va;
        instances = inst;
        heights = hb;
        heightTexture = ht;
        bendTexture = bt;
        instanceData = MemoryUtil.memAllocFloat(MAX_TILES * INSTANCE_FLOATS);
        bendData = MemoryUtil.memAlloc(2 * bendWidth * bendHeight);
        matrix = MemoryUtil.memAllocFloat(16);
        uViewProj = program.uniform("uViewProj");
        uEye = program.uniform("uEye");
        uBlade = program.uniform("uBlade");
        uReach = program.uniform("uReach");
        uSheen = program.uniform("uSheen");
        uShadows = program.uniform("uShadows");
        ground = new GroundUniforms(program);
        int previous = org.lwjgl.opengl.GL11C.glGetInteger(org.lwjgl.opengl.GL20C.GL_CURRENT_PROGRAM);
        program.use();
        glUniform1i(program.uniform("uHeights"), TextureUnits.GROUND_HEIGHTS);
        GroundUniforms.bindShadowSampler(program);
        glUniform1i(program.uniform("uMaps"), TextureUnits.GROUND_MAPS);
        glUniform1i(program.uniform("uBend"), TextureUnits.TILE_BENDS);
        ContactOcclusion m = terrain.occlusionMap();
        glUniform4f(program.uniform("uMap"), (float) m.minX, (float) m.minZ,
                (float) (1 / (m.texelX * m.width)), (float) (1 / (m.texelZ * m.height)));
        glUniform4f(program.uniform("uField"), (float) field.minX(), (float) field.minZ(),
                (float) (1 / field.cellX()), (float) (1 / field.cellZ()));
        glUniform1i(program.uniform("uFieldRes"), res);
        glUniform4f(program.uniform("uBendMap"), (float) field.minX(), (float) field.minZ(),
                1f / (TILE * bendWidth), 1f / (TILE * bendHeight));
        glUniform1f(program.uniform("uTile"), TILE);
        org.lwjgl.opengl.GL20C.glUseProgram(previous);
    }

    /** {@return the tiles drawn by the last {@link #draw}} */
    public int tiles() {
        return lastTiles;
    }

    /** {@return the blades (triangles) submitted by the last {@link #draw}, the ones shrunk away included} */
    public int blades() {
        return lastBlades;
    }

    /**
     * Draws the blades for a camera into the bound framebuffer with the current depth state. Binds the
     * terrain's maps to {@link TextureUnits#GROUND_MAPS}, the bend map to {@link TextureUnits#TILE_BENDS}
     * and the heights to {@link TextureUnits#GROUND_HEIGHTS} (the scene renderer's state guard puts
     * them back). Render
     * thread; no allocation.
     *
     * @param frame    the frame whose plant bends the cover follows
     * @param camera   the viewer
     * @param settings the light, haze, patches and the cover
     * @param maps     the terrain's occlusion and cover texture
     */
    public void draw(Frame frame, Camera camera, RenderSettings settings, GlTexture2D maps) {
        RenderDef.GroundCover gc = settings.groundCover();
        lastTiles = 0;
        lastBlades = 0;
        double reach = gc.reach();
        int perTile = gc.bladesPerTile();
        if (!gc.enabled() || reach <= 0 || perTile <= 0) {
            return;
        }
        updateBends(frame);
        camera.viewProjection(viewProj);
        frustum.set(viewProj, false);
        double ex = camera.x();
        double ez = camera.z();
        int i0 = (int) Math.floor((ex - reach - field.minX()) / TILE);
        int i1 = (int) Math.floor((ex + reach - field.minX()) / TILE);
        int j0 = (int) Math.floor((ez - reach - field.minZ()) / TILE);
        int j1 = (int) Math.floor((ez + reach - field.minZ()) / TILE);
        double sizeX = (field.resolution() - 1) * field.cellX();
        double sizeZ = (field.resolution() - 1) * field.cellZ();
        i0 = Math.max(i0, 0);
        j0 = Math.max(j0, 0);
        i1 = Math.min(i1, (int) Math.ceil(sizeX / TILE) - 1);
        j1 = Math.min(j1, (int) Math.ceil(sizeZ / TILE) - 1);
        float lo = (float) field.minHeight() - 0.1f;
        float hi = (float) (field.minHeight() + heightSpan()) + (float) gc.height() * 2;
        double full = reach / 3;
        // at most the tiles of the box around the eye are drawn: thinned evenly if they could pass the ceiling
        long box = (long) Math.max(0, i1 - i0 + 1) * Math.max(0, j1 - j0 + 1);
        perTile = bladesPerTile(perTile, (int) Math.min(MAX_TILES, box));
        instanceData.clear();
        int tiles = 0;
        for (int j = j0; j <= j1 && tiles < MAX_TILES; j++) {
            for (int i = i0; i <= i1 && tiles < MAX_TILES; i++) {
                float x0 = (float) (field.minX() + i * TILE);
                float z0 = (float) (field.minZ() + j * TILE);
                double dx = Math.max(Math.max(x0 - ex, ex - (x0 + TILE)), 0);
                double dz = Math.max(Math.max(z0 - ez, ez - (z0 + TILE)), 0);
                double d = Math.sqrt(dx * dx + dz * dz);
                if (d >= reach || !frustum.testAab(x0, lo, z0, x0 + TILE, hi, z0 + TILE)) {
                    continue;
                }
                double share = d <= full ? 1 : (full / d) * (full / d);
                instanceData.put(x0).put(z0).put((float) (share * perTile)).put(0f);
                tiles++;
            }
        }
        if (tiles == 0) {
            return;
        }
        instanceData.flip();
        instances.upload(0, instanceData);
        program.use();
        glUniformMatrix4fv(uViewProj, false, viewProj.get(matrix));
        glUniform3f(uEye, (float) ex, (float) camera.y(), (float) ez);
        ground.set(settings);
        ground.setShadowMap(shadow);
        Lighting l = settings.lighting();
        float k = l.sunIntensity();
        glUniform4f(uBlade, (float) gc.height(), (float) gc.amount(), perTile, 0f);
        glUniform1f(uReach, (float) reach);
        glUniform1f(uSheen, settings.sheen());
        // the sun's share of the light on flat ground: what a blade in a plant's shadow loses (times the
        // shadow's strength and its share in the map's blue channel, 0 while shadows are off)
        float sunLight = k * Math.max(0f, l.sunY()) * (0.2126f * l.sunR() + 0.7152f * l.sunG() + 0.0722f * l.sunB());
        float skyLight = 0.2126f * l.ambientR() + 0.7152f * l.ambientG() + 0.0722f * l.ambientB();
        glUniform2f(uShadows, settings.shadows(), sunLight / Math.max(1e-6f, sunLight + skyLight));
        maps.bind(TextureUnits.GROUND_MAPS);
        bendTexture.bind(TextureUnits.TILE_BENDS);
        heightTexture.bind(TextureUnits.GROUND_HEIGHTS);
        vao.bind();
        glDrawArraysInstanced(GL_TRIANGLES, 0, 3 * perTile, tiles);
        glBindVertexArray(0);
        lastTiles = tiles;
        lastBlades = tiles * perTile;
    }

    /**
     * Blades per tile for a frame of at most {@code tiles} tiles: the cover's {@code perTile}, thinned
     * when needed so that the frame submits at most {@link RenderDef.GroundCover#MAX_BLADES_PER_VIEW}
     * blades (a cover set at run time is not checked as a scene's is). Any thread; no allocation.
     *
     * @param perTile the cover's blades per tile, &gt;= 0
     * @param tiles   the most tiles drawn this frame, &gt;= 0
     * @return blades per tile, in [0, perTile]
     */
    static int bladesPerTile(int perTile, int tiles) {
        if (tiles <= 0) {
            return perTile;
        }
        return (int) Math.min(perTile, RenderDef.GroundCover.MAX_BLADES_PER_VIEW / tiles);
    }

    /** {@return the heightfield the blades stand on} */
    Heightfield heightfield() {
        return field;
    }

    private double heightSpan() {
        return field.maxHeight() - field.minHeight();
    }

    /**
     * Brings the bend map up to date with a frame: the plants' bends averaged per 1 m tile (what the
     * blades lean by and the ground cover's sheen reads). Once per frame number; later calls for the same
     * frame do nothing. Render thread; no allocation.
     *
     * @param frame the frame
     */
    public void prepare(Frame frame) {
        updateBends(frame);
    }

    /** {@return the bend map: per 1 m tile the plants' mean bend (radians, x and z, as bytes 128 + 127 b / 1.6)} */
    public GlTexture2D bendMap() {
        return bendTexture;
    }

    /** {@return {minX, minZ, 1 / width, 1 / height} of the bend map, metres: world X, Z to texture coordinates} */
    public float[] bendMapTransform() {
        return new float[] {(float) field.minX(), (float) field.minZ(), 1f / (TILE * bendWidth), 1f / (TILE * bendHeight)};
    }

    /** Averages the plants' bends per tile into the bend map, once per frame. */
    private void updateBends(Frame frame) {
        if (frame == bendOf && frame.number() == bendFrame) {
            return;
        }
        bendOf = frame;
        bendFrame = frame.number();
        java.util.Arrays.fill(bendSum, 0f);
        java.util.Arrays.fill(bendWeight, 0f);
        double minX = field.minX();
        double minZ = field.minZ();
        org.jecosys.anim.BendGeometry g = frame.geometry();
        for (int p = 0; p < firstComponent.length; p++) {
            int i = (int) ((world.plantX(p) - minX) / TILE);
            int j = (int) ((world.plantZ(p) - minZ) / TILE);
            if (i < 0 || j < 0 || i >= bendWidth || j >= bendHeight) {
                continue;
            }
            int c = firstComponent[p];
            float dx = frame.deviationX(c);
            float dz = frame.deviationZ(c);
            float bend = g.poseCoordinate(c, dx, dz) * poseScale[p] * maxBend[p];
            // the bend's heading is the direction of the tip T = L + D (Frame.bendAzimuth), taken
            // straight from T: no arc tangent, cosine or sine
            float tx = g.leanX(c) + dx;
            float tz = g.leanZ(c) + dz;
            float r = (float) Math.sqrt(tx * tx + tz * tz);
            int t = j * bendWidth + i;
            bendSum[2 * t] += r > 0 ? bend * tx / r : 0f;
            bendSum[2 * t + 1] += r > 0 ? bend * tz / r : bend;
            bendWeight[t] += 1f;
        }
        bendData.clear();
        for (int t = 0; t < bendWeight.length; t++) {
            float w = bendWeight[t] > 0 ? 1f / bendWeight[t] : 0f;
            // radians in [-1.6, 1.6] to bytes, 128 for none
            bendData.put(toByte(bendSum[2 * t] * w)).put(toByte(bendSum[2 * t + 1] * w));
        }
        bendData.flip();
        bendTexture.upload(bendData);
    }

    private static byte toByte(float radians) {
        return (byte) Math.round(Math.max(0, Math.min(255, 128 + radians * (127 / 1.6f))));
    }

    /** Deletes the GL objects. Render thread; idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            Closing.closeAll(vao, instances, bendTexture, heightTexture, heights, program);
            MemoryUtil.memFree((java.nio.Buffer) instanceData);
            MemoryUtil.memFree((java.nio.Buffer) bendData);
            MemoryUtil.memFree((java.nio.Buffer) matrix);
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
