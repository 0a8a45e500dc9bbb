package org.jecosys.render.plant;

import org.jecosys.render.ResolvePath;
import org.jecosys.render.gl.Closing;
import static org.lwjgl.opengl.GL11C.GL_POINTS;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glDrawArrays;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniform1i;
import static org.lwjgl.opengl.GL20C.glUseProgram;
import static org.lwjgl.opengl.GL30C.GL_RASTERIZER_DISCARD;
import static org.lwjgl.opengl.GL30C.GL_RG32UI;
import static org.lwjgl.opengl.GL30C.GL_RGBA32F;
import static org.lwjgl.opengl.GL30C.GL_RGBA32I;
import static org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER;
import static org.lwjgl.opengl.GL30C.glBeginTransformFeedback;
import static org.lwjgl.opengl.GL30C.glBindBufferBase;
import static org.lwjgl.opengl.GL30C.glBindBufferRange;
import static org.lwjgl.opengl.GL30C.glEndTransformFeedback;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BUFFER;
import static org.lwjgl.opengl.GL42C.GL_BUFFER_UPDATE_BARRIER_BIT;
import static org.lwjgl.opengl.GL42C.GL_TEXTURE_FETCH_BARRIER_BIT;
import static org.lwjgl.opengl.GL42C.glMemoryBarrier;
import static org.lwjgl.opengl.GL43C.GL_SHADER_STORAGE_BUFFER;
import static org.lwjgl.opengl.GL43C.glDispatchCompute;

import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlBuffer;
import org.jecosys.render.gl.GlBufferTexture;
import org.jecosys.render.gl.GlUploadRing;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlVertexArray;
import org.jecosys.render.gl.TextureUnits;

/**
 * The GPU per-component resolve pass of {@link PlantRenderer} (paper §4.1-4.2; docs/ARCHITECTURE.md,
 * "Rendering"): per frame it uploads the drawn plants' render states (8 bytes per component: the
 * deviation D the animation workers wrote) and 8 bytes per drawn plant and level, then resolves each
 * drawn component's record from D and its bend geometry (3 RGBA32F texels: base, cos/sin of the bend
 * azimuth, pose texel and weight, dither window, colour variation) into the component buffer the
 * instanced draws read, on its
 * {@link ResolvePath}: a compute shader ({@code plant_resolve.comp}) or transform feedback
 * ({@code plant_resolve.vert}), both around {@code plant_resolve.glsl}, each compiled twice: with
 * the parent walk ({@code ATTACHED}) for species with attached components, without it for the others.
 *
 * <p>Holds the resolve programs, the static per-component data (root bases and pose texels; parent
 * links; bend geometry: rest lean, length, pose scale; made by {@link PlantMeshes}), the dynamic render-state and instance buffers with their
 * buffer textures, the component record buffer, the compute path's list table, an empty VAO for the
 * points and the staging memory. It reads the renderer's pose texture and {@link PlantBatches}, which
 * it does not own.
 *
 * <p>Render thread only. The constructor allocates (and releases what it had made if it fails);
 * {@link #upload}, {@link #resolve} and {@link #bindRecords} allocate nothing. {@link #close()} is
 * idempotent; {@link PlantRenderer} closes it.
 */
public final class ComponentResolver implements AutoCloseable {
    private final PlantBatches batches;
    private final GlBufferTexture poseTexture;
    private final List<AutoCloseable> owned = new ArrayList<>();
    private final ResolvePath path;
    /** The resolve programs: [0] for species whose components all stand on the ground, [1] with ATTACHED. */
    private final Pass[] passes = new Pass[2];
    /** Per species: whether a component is attached to another (its list needs the ATTACHED variant). */
    private final boolean[] attached;
    private final GlBuffer componentBuffer;
    private final GlBufferTexture componentTexture;
    private final GlBuffer staticBuffer;
    private final GlBufferTexture staticTexture;
    private final GlBuffer bendBuffer;
    private final GlBufferTexture bendTexture;
    private final GlBuffer linkBuffer;
    private final GlBufferTexture linkTexture;
    /** The per-frame bytes: instance records, render states, the list table (a mapped ring or streaming buffers). */
    private final ResolverUploads uploads;
    private final GlVertexArray pointsVao;
    private final IntBuffer instanceStaging;
    private final int[] slotBase;
    private final GlBuffer slotLookBuffer;
    private final GlBufferTexture slotLookTexture;
    /** Per variant, this frame: its first entry in the list table, its entries, its invocations. */
    private final int[] listFirst = new int[2];
    private final int[] listCount = new int[2];
    private final int[] listInvocations = new int[2];
    /** The list table of the compute path (8 ints per non-empty list), staged and uploaded per frame. */
    private final IntBuffer listStaging;
    /** Invocations per compute work group ({@code local_size_x} of {@code plant_resolve.comp}). */
    private static final int GROUP = 64;
    /** Most invocations in one dispatch: 65535 groups, the least every 4.3 context allows. */
    private static final int MAX_DISPATCH = GROUP * 65535;
    private final ComponentLooks looks;
    private final GlBuffer lookBuffer;
    private final GlBufferTexture lookTexture;
    private final int components;
    /** The {@link PlantLook#version} the looks were baked for; -1 before the first bake. */
    private int lookVersion = -1;
    private long uploadedBytes;
    private boolean closed;

    /**
     * Compiles the resolve program, uploads the static per-component data and preallocates the
     * per-frame buffers. Render thread, context current; allocates. If it throws, every GL object it
     * had made is deleted again.
     *
     * @param t             the tracker of the current context
     * @param world         the plants
     * @param batches       the renderer's decision lists (sizes the buffers; read each frame)
     * @param poseTexture   the renderer's pose table texture (bound to unit 0 while resolving)
     * @param poseTexel     first texel of each pose table, {@link PlantRenderer#poseTexelLayout}
     * @param components    component slots to hold render states for, &ge; 1
     * @param maxComponents most components drawn in one frame, &ge; 1
     */
    public ComponentResolver(GlTracker t, World world, PlantBatches batches, GlBufferTexture poseTexture,
                      int[][][] poseTexel, int components, long maxComponents, float[] slotLooks, ResolvePath path) {
        this(t, world, batches, poseTexture, poseTexel, components, maxComponents, slotLooks, path, null);
    }

    /**
     * As the other constructor, with the two resolve programs of {@code path} given ({@link #compile}),
     * shared with other resolvers and not closed by this one; null compiles and owns its own.
     */
    ComponentResolver(GlTracker t, World world, PlantBatches batches, GlBufferTexture poseTexture,
                      int[][][] poseTexel, int components, long maxComponents, float[] slotLooks, ResolvePath path,
                      GlProgram[] shared) {
        this.batches = batches;
        this.path = path;
        this.poseTexture = poseTexture;
        this.components = components;
        this.looks = new ComponentLooks(world);
        IntBuffer instances = null;
        IntBuffer lists = null;
        int tableInts = 8 * Math.max(1, batches.listCount());
        try {
            detach();
            for (int k = 0; k < passes.length; k++) {
                passes[k] = new Pass(shared != null ? shared[k] : own(compile(t, path, k)));
            }
            instances = MemoryUtil.memAllocInt(2 * Math.max(1, batches.maxInstances()));
            componentBuffer = own(GlBuffer.dynamic(t, GL_TEXTURE_BUFFER,
                    4L * PlantRenderer.RECORD_FLOATS * maxComponents));
            componentTexture = own(new GlBufferTexture(t, componentBuffer, GL_RGBA32F));
            staticBuffer = own(PlantMeshes.uploadStatic(t, world, poseTexel));
            staticTexture = own(new GlBufferTexture(t, staticBuffer, GL_RGBA32F));
            bendBuffer = own(PlantMeshes.uploadBend(t, world.bendGeometry()));
            bendTexture = own(new GlBufferTexture(t, bendBuffer, GL_RGBA32F));
            linkBuffer = own(PlantMeshes.uploadLinks(t, world));
            linkTexture = own(new GlBufferTexture(t, linkBuffer, GL_RGBA32I));
            uploads = new ResolverUploads(t, 8L * Math.max(1, batches.maxInstances()),
                    (long) Frame.RENDER_STATE_BYTES * components, 4L * tableInts,
                    GlUploadRing.supported(org.lwjgl.opengl.GL.getCapabilities()), owned);
            pointsVao = own(new GlVertexArray(t));
            slotLookBuffer = own(PlantMeshes.uploadFloats(t, slotLooks));
            slotLookTexture = own(new GlBufferTexture(t, slotLookBuffer, GL_RGBA32F));
            lookBuffer = own(GlBuffer.dynamic(t, GL_TEXTURE_BUFFER, 8L * components));
            lookTexture = own(new GlBufferTexture(t, lookBuffer, GL_RG32UI));
            lists = MemoryUtil.memAllocInt(tableInts);
        } catch (RuntimeException | Error e) {
            MemoryUtil.memFree((java.nio.Buffer) instances);
            MemoryUtil.memFree((java.nio.Buffer) lists);
            Closing.closeReverse(owned);
            throw e;
        }
        detach();
        instanceStaging = instances;
        listStaging = lists;
        slotBase = new int[world.plants().species().size()];
        attached = new boolean[slotBase.length];
        for (int s = 0; s < slotBase.length; s++) {
            SpeciesModel m = world.plants().species().get(s);
            slotBase[s] = s == 0 ? 0 : slotBase[s - 1] + world.plants().species().get(s - 1).slotCount();
            for (int slot = 0; slot < m.slotCount(); slot++) {
                attached[s] |= m.slotParent(slot) >= 0;
            }
        }
    }

    /** {@return the path this resolver runs} */
    public ResolvePath path() {
        return path;
    }

    /**
     * Sets the per-frame uniforms (view, light, fog, pixel size, thinning: the line levels' records
     * are lit and carry what their vertices share) on every resolve program. Render thread; no
     * allocation; leaves a resolve program in use (none on the compute path).
     */
    void frame(PlantLook look, PassContext context) {
        detach();
        for (Pass p : passes) {
            p.uniforms.program.use();
            p.uniforms.frame(look, context, 1f);
        }
        detach();
    }

    /**
     * On the compute path, makes no program current: Mesa (22.3, llvmpipe) keeps the graphics
     * program that was current when a compute program is made current directly, or the other way
     * round, alive past its deletion; going through program 0 avoids it (the GL object census
     * tests catch it). No allocation.
     */
    private void detach() {
        if (path == ResolvePath.COMPUTE) {
            glUseProgram(0);
        }
    }

    /**
     * One resolve program, its samplers bound to their units, and the locations of its per-dispatch
     * uniforms: per list on the transform-feedback path, per variant (the list table's range) on the
     * compute path; a location the program lacks is -1, which GL ignores.
     */
    private static final class Pass {
        final PlantUniforms uniforms;
        final int instanceBase;
        final int slots;
        final int lines;
        final int slotBase;
        final int dryTips;
        final int listFirst;
        final int listCount;
        final int count;
        final int first;

        Pass(GlProgram p) {
            uniforms = new PlantUniforms(p);
            glUniform1i(p.uniform("uInstances"), TextureUnits.INSTANCES);
            glUniform1i(p.uniform("uDynamic"), TextureUnits.RENDER_STATES);
            glUniform1i(p.uniform("uStatic"), TextureUnits.STATIC);
            glUniform1i(p.optionalUniform("uLinks"), TextureUnits.LINKS);
            glUniform1i(p.uniform("uBend"), TextureUnits.BEND_GEOMETRY);
            glUniform1i(p.uniform("uSlotLooks"), TextureUnits.SLOT_LOOKS);
            glUniform1i(p.uniform("uLooks"), TextureUnits.LOOKS);
            glUniform1i(p.optionalUniform("uLists"), TextureUnits.LIST_TABLE);
            instanceBase = p.optionalUniform("uInstanceBase");
            slots = p.optionalUniform("uSlots");
            lines = p.optionalUniform("uLines");
            slotBase = p.optionalUniform("uSlotBase");
            dryTips = p.optionalUniform("uDryTips");
            listFirst = p.optionalUniform("uListFirst");
            listCount = p.optionalUniform("uListCount");
            count = p.optionalUniform("uCount");
            first = p.optionalUniform("uFirst");
        }
    }

    /**
     * Compiles resolve program k of {@code path}: 0 for species standing on the ground, 1 with the
     * parent walk ({@code ATTACHED}). Render thread; allocates.
     */
    static GlProgram compile(GlTracker t, ResolvePath path, int k) {
        String[] defines = k == 0 ? new String[0] : new String[] {"ATTACHED"};
        return path == ResolvePath.COMPUTE
                ? GlProgram.compute(t, "plant_resolve.comp", defines)
                : GlProgram.captureVariant(t, "plant_resolve.vert", defines, "vRecord0", "vRecord1", "vRecord2");
    }

    private <T extends AutoCloseable> T own(T resource) {
        owned.add(resource);
        return resource;
    }

    /**
     * Uploads this frame's instance records (8 bytes per drawn plant and level) and the render states
     * of the drawn plants' components (8 bytes per component, {@link Frame#renderStates()}, as the
     * workers wrote them), in the few ranges that hold them ({@link PlantBatches#runStart}; the
     * plants' spatial order keeps them few). Call after {@link PlantBatches#update}. Render thread;
     * no allocation.
     *
     * @param frame the frame being drawn
     */
    public void upload(Frame frame) {
        int n = batches.writeInstances(instanceStaging);
        long bytes = uploads.upload(instanceStaging, frame, batches);
        uploadedBytes = 8L * n + bytes;
    }

    /**
     * The per-component pass on the GPU, each list's records at its place in the component buffer:
     * on the compute path one dispatch per program variant over all its lists (one invocation per
     * drawn component, its list found in a table uploaded here), on the transform-feedback path one
     * draw of points per list with rasterisation discarded. Leaves a resolve program in use (none on
     * the compute path). Render thread; no allocation.
     */
    public void resolve(PlantLook look) {
        if (look.version() != lookVersion) {
            bakeLooks(look);
        }
        poseTexture.bind(TextureUnits.POSES);
        uploads.bind();
        staticTexture.bind(TextureUnits.STATIC);
        linkTexture.bind(TextureUnits.LINKS);
        bendTexture.bind(TextureUnits.BEND_GEOMETRY);
        slotLookTexture.bind(TextureUnits.SLOT_LOOKS);
        lookTexture.bind(TextureUnits.LOOKS);
        detach();
        if (path == ResolvePath.COMPUTE) {
            resolveByCompute(look);
            fenceUploads();
            return;
        }
        glEnable(GL_RASTERIZER_DISCARD);
        pointsVao.bind();
        for (int li = 0, lists = batches.listCount(); li < lists; li++) {
            int n = batches.count(li);
            if (n == 0) {
                continue;
            }
            int species = batches.speciesOf(li);
            int slots = batches.slots(species);
            Pass p = passes[attached[species] ? 1 : 0];
            p.uniforms.program.use();
            glUniform1i(p.lines, batches.lines(li) ? 1 : 0);
            glUniform1i(p.slotBase, slotBase[species]);
            glUniform1f(p.dryTips, look.dryTips(species));
            glUniform1i(p.instanceBase, batches.instanceOffset(li));
            glUniform1i(p.slots, slots);
            int count = n * slots;
            long bytes = 4L * PlantRenderer.RECORD_FLOATS;
            glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, componentBuffer.id(),
                    bytes * batches.componentOffset(li), bytes * count);
            glBeginTransformFeedback(GL_POINTS);
            glDrawArrays(GL_POINTS, 0, count);
            glEndTransformFeedback();
        }
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
        glDisable(GL_RASTERIZER_DISCARD);
        fenceUploads();
    }

    /** The uploads are read by the resolve pass only: a ring's region is fenced once its commands are issued. */
    private void fenceUploads() {
        uploads.fence();
    }

    /**
     * {@return frames whose upload region the GPU was still reading, so that they waited for it (0 with
     * no ring: the streaming buffers are re-specified instead)} Render thread; no allocation.
     */
    public long uploadWaits() {
        return uploads.waits();
    }

    /** {@return whether the per-frame uploads go through a persistently mapped ring (buffer storage)} */
    public boolean uploadRing() {
        return uploads.ring();
    }

    /** The compute path of {@link #resolve}: the list table, then at most one dispatch per variant. */
    private void resolveByCompute(PlantLook look) {
        listStaging.clear();
        int entries = 0;
        for (int k = 0; k < passes.length; k++) {
            listFirst[k] = entries;
            int invocations = 0;
            for (int li = 0, lists = batches.listCount(); li < lists; li++) {
                int n = batches.count(li);
                int species = batches.speciesOf(li);
                if (n == 0 || attached[species] != (k == 1)) {
                    continue;
                }
                int slots = batches.slots(species);
                listStaging.put(invocations).put(batches.instanceOffset(li)).put(slots)
                        .put(batches.componentOffset(li));
                listStaging.put(slotBase[species]).put(batches.lines(li) ? 1 : 0)
                        .put(Float.floatToRawIntBits(look.dryTips(species))).put(0);
                invocations += n * slots;
                entries++;
            }
            listCount[k] = entries - listFirst[k];
            listInvocations[k] = invocations;
        }
        listStaging.flip();
        uploads.lists(listStaging);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, componentBuffer.id());
        for (int k = 0; k < passes.length; k++) {
            int count = listInvocations[k];
            if (count == 0) {
                continue;
            }
            Pass p = passes[k];
            p.uniforms.program.use();
            glUniform1i(p.listFirst, listFirst[k]);
            glUniform1i(p.listCount, listCount[k]);
            glUniform1i(p.count, count);
            for (int at = 0; at < count; at += MAX_DISPATCH) {
                glUniform1i(p.first, at);
                glDispatchCompute((Math.min(MAX_DISPATCH, count - at) + GROUP - 1) / GROUP, 1, 1);
            }
        }
        detach();
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    }

    /**
     * Works out every component's look again ({@link ComponentLooks}) and uploads it: when the
     * variation, patches or seed changed, not per frame. Render thread; allocates native memory for
     * the staging copy and frees it.
     */
    private void bakeLooks(PlantLook look) {
        IntBuffer staging = MemoryUtil.memAllocInt(2 * components);
        try {
            looks.bake(look, staging);
            staging.flip();
            lookBuffer.upload(0, staging);
            lookVersion = look.version();
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) staging);
        }
    }

    /**
     * Binds the component records to {@link TextureUnits#RECORDS} for the draw programs. Render
     * thread; no allocation.
     */
    public void bindRecords() {
        componentTexture.bind(TextureUnits.RECORDS);
    }

    /**
     * Reads back the component records of the last {@link #resolve} (tests). Render thread; waits
     * for the GPU.
     *
     * @param dest a direct buffer of at least {@link PlantRenderer#RECORD_FLOATS} floats per drawn
     *             component
     */
    public void readRecords(FloatBuffer dest) {
        if (!dest.isDirect()) {
            throw new IllegalArgumentException("dest must be a direct buffer");
        }
        dest.clear();
        dest.limit(PlantRenderer.RECORD_FLOATS * batches.components());
        if (path == ResolvePath.COMPUTE) {
            glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        }
        componentBuffer.bind();
        org.lwjgl.opengl.GL15C.glGetBufferSubData(GL_TEXTURE_BUFFER, 0, dest);
    }

    /** {@return bytes uploaded by the last {@link #upload}: instance records and component render states} */
    public long uploadedBytes() {
        return uploadedBytes;
    }

    /** Deletes every GL object it made and frees the staging memory. Render thread; idempotent. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        Closing.closeReverse(owned);
        MemoryUtil.memFree((java.nio.Buffer) instanceStaging);
        MemoryUtil.memFree((java.nio.Buffer) listStaging);
    }
}
