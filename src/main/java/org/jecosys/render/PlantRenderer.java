package org.jecosys.render;

import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_LINES;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.GL_UNSIGNED_INT;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_ELEMENT_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniform1fv;
import static org.lwjgl.opengl.GL20C.glUniform1i;
import static org.lwjgl.opengl.GL20C.glUniform3f;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.GL_RG32F;
import static org.lwjgl.opengl.GL30C.GL_RGBA32F;
import static org.lwjgl.opengl.GL30C.GL_RGBA32I;
import static org.lwjgl.opengl.GL30C.GL_RGBA32UI;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL31C.GL_MAX_TEXTURE_BUFFER_SIZE;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BUFFER;
import static org.lwjgl.opengl.GL31C.glDrawElementsInstanced;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.util.List;
import org.jecosys.math.Rgb;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.InstanceLayout;
import org.jecosys.plant.LodMesh;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.joml.Matrix4f;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.system.MemoryUtil;

/**
 * Draws every plant of a {@link World} from a {@link Frame} (paper §4.1-4.2, DESIGN.md "Rendering").
 * At construction every pose table goes to the GPU once (a buffer texture, 3 RGBA32F texels per
 * skeleton point), with a per-species slot table (pose table, parent slot, ground offset and colour
 * of each (variant, slot)) and one mesh per species and level. Per frame, {@link #draw} uploads only
 * per-instance data into preallocated buffers: the 16-byte {@link InstanceLayout} record of each
 * drawn plant and the (pose coordinate, azimuth) pair of each of its components, then issues one
 * instanced draw per species and level (triangles near, lines far: Table 3).
 *
 * <p>Render thread only; {@link #draw} allocates nothing. Owns its GL objects; {@link #close()} is
 * idempotent.
 */
public final class PlantRenderer implements AutoCloseable {
    private static final int MAX_LEVELS = 8;

    private final World world;
    private final PlantBatches batches;
    private final GlProgram program;
    private final GlBuffer poseBuffer;
    private final GlBufferTexture poseTexture;
    private final GlBuffer slotBuffer;
    private final GlBufferTexture slotTexture;
    private final GlBuffer instanceBuffer;
    private final GlBufferTexture instanceTexture;
    private final GlBuffer bendBuffer;
    private final GlBufferTexture bendTexture;
    private final GlVertexArray[] vaos;
    private final GlBuffer[] vertexBuffers;
    private final GlBuffer[] indexBuffers;
    private final int[] indexCount;
    private final int[] slotBase;
    private final ByteBuffer instanceStaging;
    private final FloatBuffer bendStaging;
    private final FloatBuffer matrix;
    private final float[] edgeUniform = new float[MAX_LEVELS];
    private final Matrix4f viewProj = new Matrix4f();
    private final int uViewProj;
    private final int uEye;
    private final int uLightDir;
    private final int uInstanceBase;
    private final int uSlotBase;
    private final int uSlotCount;
    private final int uComponentBase;
    private final int uLevel;
    private final int uLevels;
    private final int uEdges;
    private final int uBand;
    private final int uFogColour;
    private final int uFogStart;
    private final int uFogEnd;
    private int draws;
    private boolean closed;

    /**
     * Uploads pose tables, slot tables and meshes, and preallocates the per-frame buffers. Render
     * thread; allocates.
     *
     * @param bandWidth LOD transition band, metres (RenderDef.lodTransition)
     */
    public PlantRenderer(GlContext gl, World world, double bandWidth) {
        gl.checkThread();
        this.world = world;
        this.batches = new PlantBatches(world, bandWidth);
        GlTracker t = gl.tracker();
        List<SpeciesModel> models = world.plants().species();
        for (SpeciesModel m : models) {
            if (m.levels() > MAX_LEVELS) {
                throw new IllegalArgumentException("species '" + m.def().id() + "' has " + m.levels()
                        + " levels; the renderer supports at most " + MAX_LEVELS);
            }
        }
        int maxTexels = GL11C.glGetInteger(GL_MAX_TEXTURE_BUFFER_SIZE);
        program = new GlProgram(t, "plant.vert", "plant.frag");
        // pose tables: per species, per component type, per variant; 3 texels (12 floats) per point
        int[][][] poseTexel = new int[models.size()][][];
        long texels = 0;
        for (int s = 0; s < models.size(); s++) {
            SpeciesModel m = models.get(s);
            poseTexel[s] = new int[m.componentCount()][m.variants()];
            for (int c = 0; c < m.componentCount(); c++) {
                for (int v = 0; v < m.variants(); v++) {
                    poseTexel[s][c][v] = (int) texels;
                    PoseTable pt = m.component(c).poseTable(v);
                    texels += 3L * pt.poses() * pt.points();
                }
            }
        }
        checkTexels("pose tables", texels, maxTexels);
        FloatBuffer poses = MemoryUtil.memAllocFloat((int) (texels * 4));
        try {
            for (int s = 0; s < models.size(); s++) {
                SpeciesModel m = models.get(s);
                for (int c = 0; c < m.componentCount(); c++) {
                    for (int v = 0; v < m.variants(); v++) {
                        PoseTable pt = m.component(c).poseTable(v);
                        for (int i = 0; i < pt.floatCount(); i += 3) {
                            poses.put(pt.get(i)).put(pt.get(i + 1)).put(pt.get(i + 2)).put(0f);
                        }
                    }
                }
            }
            poses.flip();
            poseBuffer = GlBuffer.of(t, GL_TEXTURE_BUFFER, poses, GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree(poses);
        }
        poseTexture = new GlBufferTexture(t, poseBuffer, GL_RGBA32F);
        // slot tables: per species, per plant variant, per slot: 2 RGBA32I texels
        slotBase = new int[models.size()];
        int slotTexels = 0;
        for (int s = 0; s < models.size(); s++) {
            slotBase[s] = slotTexels;
            slotTexels += 2 * models.get(s).variants() * models.get(s).slotCount();
        }
        IntBuffer slots = MemoryUtil.memAllocInt(slotTexels * 4);
        try {
            for (int s = 0; s < models.size(); s++) {
                SpeciesModel m = models.get(s);
                for (int v = 0; v < m.variants(); v++) {
                    for (int slot = 0; slot < m.slotCount(); slot++) {
                        int c = m.slotComponent(slot);
                        PoseTable pt = m.slotPoseTable(slot, v);
                        slots.put(poseTexel[s][c][m.slotVariant(slot, v)]).put(pt.points()).put(m.slotParent(slot))
                                .put(pt.poses());
                        Rgb rgb = m.component(c).def().colour();
                        int packed = Math.round(rgb.r() * 255) | Math.round(rgb.g() * 255) << 8
                                | Math.round(rgb.b() * 255) << 16;
                        slots.put(Float.floatToRawIntBits((float) m.slotBaseX(slot)))
                                .put(Float.floatToRawIntBits((float) m.slotBaseZ(slot))).put(packed).put(0);
                    }
                }
            }
            slots.flip();
            slotBuffer = GlBuffer.of(t, GL_TEXTURE_BUFFER, slots, GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree(slots);
        }
        slotTexture = new GlBufferTexture(t, slotBuffer, GL_RGBA32I);
        // per-frame streams, sized for the worst case
        int maxInstances = Math.max(1, batches.maxInstances());
        long maxComponents = Math.max(1, batches.maxComponents());
        checkTexels("instances", maxInstances, maxTexels);
        checkTexels("components", maxComponents, maxTexels);
        instanceStaging = MemoryUtil.memAlloc(maxInstances * InstanceLayout.BYTES);
        bendStaging = MemoryUtil.memAllocFloat((int) (2 * maxComponents));
        matrix = MemoryUtil.memAllocFloat(16);
        instanceBuffer = GlBuffer.dynamic(t, GL_TEXTURE_BUFFER, (long) maxInstances * InstanceLayout.BYTES);
        instanceTexture = new GlBufferTexture(t, instanceBuffer, GL_RGBA32UI);
        bendBuffer = GlBuffer.dynamic(t, GL_TEXTURE_BUFFER, 8L * maxComponents);
        bendTexture = new GlBufferTexture(t, bendBuffer, GL_RG32F);
        // meshes: one VAO per species and level
        int lists = batches.listCount();
        vaos = new GlVertexArray[lists];
        vertexBuffers = new GlBuffer[lists];
        indexBuffers = new GlBuffer[lists];
        indexCount = new int[lists];
        for (int s = 0; s < models.size(); s++) {
            SpeciesModel m = models.get(s);
            for (int l = 0; l < m.levels(); l++) {
                int li = batches.list(s, l);
                LodMesh mesh = m.mesh(l);
                float[] v = new float[Math.max(4, 4 * mesh.vertexCount())];
                int[] idx = new int[Math.max(1, mesh.indexCount())];
                mesh.copyVertices(v, 0);
                mesh.copyIndices(idx, 0);
                indexCount[li] = mesh.indexCount();
                vaos[li] = new GlVertexArray(t);
                vaos[li].bind();
                FloatBuffer fv = MemoryUtil.memAllocFloat(v.length).put(v).flip();
                IntBuffer iv = MemoryUtil.memAllocInt(idx.length).put(idx).flip();
                try {
                    vertexBuffers[li] = GlBuffer.of(t, GL_ARRAY_BUFFER, fv, GL_STATIC_DRAW);
                    glEnableVertexAttribArray(0);
                    glVertexAttribPointer(0, 4, GL_FLOAT, false, 16, 0);
                    indexBuffers[li] = GlBuffer.of(t, GL_ELEMENT_ARRAY_BUFFER, iv, GL_STATIC_DRAW);
                } finally {
                    MemoryUtil.memFree(fv);
                    MemoryUtil.memFree(iv);
                }
                glBindVertexArray(0);
            }
        }
        program.use();
        uViewProj = program.uniform("uViewProj");
        uEye = program.uniform("uEye");
        uLightDir = program.uniform("uLightDir");
        uInstanceBase = program.uniform("uInstanceBase");
        uSlotBase = program.uniform("uSlotBase");
        uSlotCount = program.uniform("uSlotCount");
        uComponentBase = program.uniform("uComponentBase");
        uLevel = program.uniform("uLevel");
        uLevels = program.uniform("uLevels");
        uEdges = program.uniform("uEdges");
        uBand = program.uniform("uBand");
        uFogColour = program.uniform("uFogColour");
        uFogStart = program.uniform("uFogStart");
        uFogEnd = program.uniform("uFogEnd");
        glUniform1i(program.uniform("uInstances"), 0);
        glUniform1i(program.uniform("uPoses"), 1);
        glUniform1i(program.uniform("uSlots"), 2);
        glUniform1i(program.uniform("uBend"), 3);
    }

    private static void checkTexels(String what, long texels, int max) {
        if (texels > max) {
            throw new IllegalStateException("the scene's " + what + " need " + texels
                    + " buffer-texture texels; this GL allows " + max);
        }
    }

    /** The GL-free lists, LOD choice and counters (read them after {@link #draw}). */
    public PlantBatches batches() {
        return batches;
    }

    /** Instanced draw calls issued by the last {@link #draw}. */
    public int drawCalls() {
        return draws;
    }

    /**
     * Culls, chooses levels, uploads the per-instance data of {@code frame} and draws. Render thread;
     * no allocation.
     *
     * @param frame    the frame to show (sizes match the world)
     * @param camera   the viewer
     * @param lightDir unit vector toward the sun
     * @param fog      fog colour (the sky)
     * @param fogStart distance where fog starts, metres
     * @param fogEnd   distance of full fog, metres
     */
    public void draw(Frame frame, ViewCamera camera, float lx, float ly, float lz, Rgb fog, float fogStart,
                     float fogEnd) {
        if (frame.componentCount() != world.componentCount()) {
            throw new IllegalArgumentException("frame has " + frame.componentCount() + " components, the world "
                    + world.componentCount());
        }
        batches.update(camera);
        draws = 0;
        if (batches.instances() == 0) {
            return;
        }
        batches.writeInstances(instanceStaging);
        batches.writeComponents(frame, bendStaging);
        instanceBuffer.orphan();
        instanceBuffer.upload(0, instanceStaging);
        bendBuffer.orphan();
        bendBuffer.upload(0, bendStaging);
        program.use();
        camera.viewProjection(viewProj);
        glUniformMatrix4fv(uViewProj, false, viewProj.get(matrix));
        glUniform3f(uEye, (float) camera.x(), (float) camera.y(), (float) camera.z());
        glUniform3f(uLightDir, lx, ly, lz);
        glUniform3f(uFogColour, fog.r(), fog.g(), fog.b());
        glUniform1f(uFogStart, fogStart);
        glUniform1f(uFogEnd, fogEnd);
        instanceTexture.bind(0);
        poseTexture.bind(1);
        slotTexture.bind(2);
        bendTexture.bind(3);
        for (int s = 0; s < batches.speciesCount(); s++) {
            int levels = batches.levels(s);
            for (int l = 0; l < levels - 1; l++) {
                edgeUniform[l] = (float) batches.edge(s, l);
            }
            glUniform1fv(uEdges, edgeUniform);
            glUniform1f(uBand, (float) batches.bandWidth(s));
            glUniform1i(uLevels, levels);
            glUniform1i(uSlotBase, slotBase[s]);
            glUniform1i(uSlotCount, batches.slots(s));
            for (int l = 0; l < levels; l++) {
                int li = batches.list(s, l);
                int n = batches.count(li);
                if (n == 0 || indexCount[li] == 0) {
                    continue;
                }
                glUniform1i(uLevel, l);
                glUniform1i(uInstanceBase, batches.instanceOffset(li));
                glUniform1i(uComponentBase, batches.componentOffset(li));
                vaos[li].bind();
                glDrawElementsInstanced(batches.lines(li) ? GL_LINES : GL_TRIANGLES, indexCount[li], GL_UNSIGNED_INT,
                        0L, n);
                draws++;
            }
        }
        glBindVertexArray(0);
    }

    /** Deletes every GL object and frees the staging memory. Render thread; idempotent. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        for (int i = 0; i < vaos.length; i++) {
            closeAll(vaos[i], vertexBuffers[i], indexBuffers[i]);
        }
        closeAll(bendTexture, bendBuffer, instanceTexture, instanceBuffer, slotTexture, slotBuffer, poseTexture,
                poseBuffer, program);
        MemoryUtil.memFree(instanceStaging);
        MemoryUtil.memFree(bendStaging);
        MemoryUtil.memFree(matrix);
    }

    static void closeAll(AutoCloseable... resources) {
        for (AutoCloseable r : resources) {
            if (r != null) {
                try {
                    r.close();
                } catch (Exception e) {
                    throw new IllegalStateException("closing " + r, e);
                }
            }
        }
    }
}
