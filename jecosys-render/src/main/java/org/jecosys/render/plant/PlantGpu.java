package org.jecosys.render.plant;

import static org.lwjgl.opengl.GL31C.GL_MAX_TEXTURE_BUFFER_SIZE;
import static org.lwjgl.opengl.GL43C.GL_MAX_SHADER_STORAGE_BLOCK_SIZE;

import java.util.ArrayList;
import java.util.List;
import org.jecosys.plant.PlantTextures;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.render.GlContext;
import org.jecosys.render.ResolvePath;
import org.jecosys.render.gl.Closing;
import org.jecosys.render.gl.GlBufferTexture;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.GlTextureArray;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlVertexArray;
import org.jecosys.render.gl.TextureUnits;
import org.jecosys.sim.World;
import org.lwjgl.opengl.GL11C;

/**
 * The GL objects of one {@link PlantRenderer} and their upload layout, made at its construction: the
 * {@link PlantPasses#COUNT} draw programs, every pose table of the world in one buffer texture (3
 * RGBA32F texels per skeleton point, {@link PlantMeshes#poseTexelLayout}), one mesh per species and
 * level (a vertex array and its index count, by list of {@link PlantBatches}), and the per-component
 * resolve pass ({@link ComponentResolver}) on the path chosen for the context; later the shadow map's
 * programs ({@link #own}). First checks that the world fits the renderer and this GL (levels per
 * species, pose tables, texel counts). Render thread; the constructor allocates and, when it fails
 * part way, deletes what it had made again; {@link #close()} deletes everything in reverse order.
 */
final class PlantGpu implements AutoCloseable {
    /** Most levels of detail a species may have. */
    static final int MAX_LEVELS = 8;

    private final List<AutoCloseable> owned = new ArrayList<>();
    /** The context's live-object counter. */
    final GlTracker tracker;
    /** The draw programs, program k from {@link PlantPasses#compile}{@code (tracker, k)}. */
    final GlProgram[] programs = new GlProgram[PlantPasses.COUNT];
    /** The pose tables as one buffer texture. */
    final GlBufferTexture poseTexture;
    /** The per-component resolve pass and its buffers. */
    final ComponentResolver resolver;
    /** Whether components are textured: the triangle programs are compiled with {@code TEXTURED}. */
    final boolean textured;
    /** The images drawn on components, a layer each; null without textures. */
    final GlTextureArray textures;
    /** Per list: its level's mesh and the mesh's index count. */
    final GlVertexArray[] vaos;
    final int[] indexCount;

    /**
     * Checks the world, compiles the draw programs and uploads the pose tables, the meshes and the
     * resolve pass's static data. Render thread; allocates.
     *
     * @param gl      the render context, current on this thread
     * @param world   the plants
     * @param batches the renderer's lists (their count and the most components drawn at once)
     * @param path    the resolve path; null: the best for this context
     * @throws IllegalArgumentException when a species does not fit the renderer, or the context cannot
     *                                  run {@code path}
     * @throws IllegalStateException    when the world's tables do not fit this GL's buffer textures
     */
    PlantGpu(GlContext gl, World world, PlantBatches batches, ResolvePath path) {
        this(gl, world, batches, path, null);
    }

    /**
     * As the other constructor, with the draw and resolve programs of {@code shared} (made for this
     * context), not closed by this set; null compiles and owns its own. Its resolve path is
     * {@code shared}'s then. The shared programs are taken when they read textures exactly when the
     * world has them (else this set compiles its own), and their image array with them.
     */
    PlantGpu(GlContext gl, World world, PlantBatches batches, ResolvePath path, PlantPrograms shared) {
        tracker = GlContexts.tracker(gl);
        List<SpeciesModel> models = world.plants().species();
        PlantTextures images = world.plants().textures();
        textured = !images.isEmpty();
        check(models);
        int[][][] poseTexel = new int[models.size()][][];
        long texels = PlantMeshes.poseTexelLayout(models, poseTexel);
        long maxComponents = Math.max(1, batches.maxComponents());
        int components = Math.max(1, world.componentCount());
        ResolvePath resolvePath = shared != null ? shared.path()
                : choosePath(gl, path, 4L * PlantRenderer.RECORD_FLOATS * maxComponents);
        try {
            int maxTexels = GL11C.glGetInteger(GL_MAX_TEXTURE_BUFFER_SIZE);
            checkTexels("pose tables", texels, Math.min(maxTexels, PlantRenderer.MAX_EXACT));
            checkTexels("component records", 3 * maxComponents, maxTexels);
            checkTexels("components", components, Math.min(maxTexels, PlantRenderer.MAX_EXACT));
            for (int k = 0; k < programs.length; k++) {
                programs[k] = shared != null && shared.textured() == textured ? shared.draw(k)
                        : own(PlantPasses.compile(tracker, k, textured));
            }
            // the model's tables and meshes: the shared programs' when they are of this model, else its own
            SpeciesGpu common = shared != null ? shared.species(tracker, world.plants()) : null;
            if (common == null) {
                common = own(new SpeciesGpu(tracker, world.plants()));
            }
            poseTexture = common.poseTexture;
            resolver = own(new ComponentResolver(tracker, world, batches, poseTexture, poseTexel, components,
                    maxComponents, PlantMeshes.slotLooks(models, images), resolvePath,
                    shared == null ? null : shared.resolve()));
            int lists = batches.listCount();
            vaos = new GlVertexArray[lists];
            indexCount = new int[lists];
            for (int s = 0; s < models.size(); s++) {
                SpeciesModel m = models.get(s);
                for (int l = 0; l < m.levels(); l++) {
                    int li = batches.list(s, l);
                    indexCount[li] = m.mesh(l).indexCount();
                    vaos[li] = common.mesh(s, l);
                }
            }
            // trilinear on a GPU; the nearest level's bilinear on a software rasteriser (GlTextureArray)
            textures = !textured ? null : shared != null && shared.textures() != null ? shared.textures()
                    : own(new GlTextureArray(tracker, images.side(), images.layers(), images::level,
                    !org.jecosys.render.gl.SoftwareGl.is(gl.describe())));
        } catch (RuntimeException | Error e) {
            Closing.closeReverse(owned);
            throw e;
        }
    }

    /** Refuses a species with more levels than the renderer draws, or variants whose pose tables differ in points. */
    private static void check(List<SpeciesModel> models) {
        for (SpeciesModel m : models) {
            if (m.levels() > MAX_LEVELS) {
                throw new IllegalArgumentException("species '" + m.def().id() + "' has " + m.levels()
                        + " levels; the renderer supports at most " + MAX_LEVELS);
            }
            for (int slot = 0; slot < m.slotCount(); slot++) {
                for (int v = 1; v < m.variants(); v++) {
                    if (m.slotPoseTable(slot, v).points() != m.slotPoseTable(slot, 0).points()) {
                        throw new IllegalArgumentException("species '" + m.def().id() + "' slot " + slot
                                + ": pose tables of different variants differ in point count");
                    }
                }
            }
        }
    }

    /** The path asked for, or the best for the context; transform feedback when the records would not fit compute's buffer. */
    private static ResolvePath choosePath(GlContext gl, ResolvePath asked, long recordBytes) {
        ResolvePath want = asked == null ? ResolvePath.best(gl) : asked;
        if (want != ResolvePath.COMPUTE) {
            return want;
        }
        boolean supported = ResolvePath.COMPUTE.supported(gl.capabilities());
        long most = supported ? Integer.toUnsignedLong(GL11C.glGetInteger(GL_MAX_SHADER_STORAGE_BLOCK_SIZE)) : 0;
        if (supported && recordBytes <= most) {
            return want;
        }
        if (asked == null) {
            return ResolvePath.TRANSFORM_FEEDBACK;
        }
        throw new IllegalArgumentException(supported
                ? "the compute resolve path needs a shader storage buffer of " + recordBytes
                        + " bytes for this world's component records; this GL allows " + most
                : "the compute resolve path needs OpenGL 4.3; this context is " + gl.describe());
    }

    private static void checkTexels(String what, long texels, int max) {
        if (texels > max) {
            throw new IllegalStateException("the scene's " + what + " need " + texels
                    + " buffer-texture texels; this GL allows " + max);
        }
    }

    /** Takes a GL object made later (the shadow map's programs) into this set, closed with it. */
    <T extends AutoCloseable> T own(T resource) {
        owned.add(resource);
        return resource;
    }

    /** Binds what the draw programs read: the pose tables and the resolved component records. No allocation. */
    void bindForDraws() {
        poseTexture.bind(TextureUnits.POSES);
        resolver.bindRecords();
        if (textures != null) {
            textures.bind(TextureUnits.PLANT_TEXTURES);
        }
    }

    /** Deletes every GL object, in reverse order of making. Render thread; idempotent. */
    @Override
    public void close() {
        Closing.closeReverse(owned);
        owned.clear();
    }

    /**
     * Compiles the shadow map's caster and receiver programs and takes them into use in {@code passes}
     * (at the first frame that draws the map). Render thread; allocates.
     */
    void compileCasters(PlantPasses passes) {
        GlProgram[] casters = new GlProgram[PlantPasses.CASTERS];
        GlProgram[] receivers = new GlProgram[PlantPasses.CASTERS];
        for (int k = 0; k < casters.length; k++) {
            casters[k] = own(PlantPasses.compileCaster(tracker, k, textured));
            receivers[k] = own(PlantPasses.compileReceiver(tracker, k, textured));
        }
        passes.useCasters(casters, receivers);
    }

    /**
     * Compiles the split programs a target without samples needs and takes them into use in
     * {@code passes} (at its first frame, and those that read the shadow map at the first such frame that
     * draws one). Render thread; allocates.
     */
    void compileSplit(PlantPasses passes) {
        for (int mapped = 0; mapped < 2; mapped++) {
            if (mapped == 0 ? passes.hasPlainSplit() : !passes.hasCasters() || passes.hasSplitReceivers()) {
                continue;
            }
            GlProgram[] programs = new GlProgram[PlantPasses.CASTERS];
            for (int k = 0; k < programs.length; k++) {
                programs[k] = own(PlantPasses.compileSplit(tracker, k, mapped == 1, textured));
            }
            if (mapped == 0) {
                passes.useSplit(programs);
            } else {
                passes.useSplitReceivers(programs);
            }
        }
    }
}
