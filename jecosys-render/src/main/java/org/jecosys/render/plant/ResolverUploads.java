package org.jecosys.render.plant;

import static org.lwjgl.opengl.GL30C.GL_RG32F;
import static org.lwjgl.opengl.GL30C.GL_RG32I;
import static org.lwjgl.opengl.GL30C.GL_RGBA32I;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BUFFER;

import java.nio.IntBuffer;
import java.util.List;
import org.jecosys.render.gl.GlBuffer;
import org.jecosys.render.gl.GlBufferTexture;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlUploadRing;
import org.jecosys.render.gl.TextureUnits;
import org.jecosys.sim.Frame;
import org.lwjgl.system.MemoryUtil;

/**
 * Where the resolve pass's per-frame bytes go ({@link ComponentResolver}): the drawn plants' instance
 * records, their components' render states and the compute path's list table, each read through a buffer
 * texture. Where the GL has buffer storage, through a {@link GlUploadRing} (a frame copies into its
 * region's mapping, points the textures at that region and fences it after the resolve pass); elsewhere
 * into streaming buffers re-specified each frame. Render thread only; the constructor allocates GL
 * objects (added to the owner's list, which closes them); the per-frame methods allocate nothing.
 */
final class ResolverUploads {
    private static final int INSTANCES = 0;
    private static final int STATES = 1;
    private static final int LISTS = 2;

    /** Null without buffer storage. */
    private final GlUploadRing ring;
    /** The streaming buffers, without a ring (each null with one). */
    private final GlBuffer instanceBuffer;
    private final GlBuffer stateBuffer;
    private final GlBuffer listBuffer;
    private final GlBufferTexture instanceTexture;
    private final GlBufferTexture stateTexture;
    private final GlBufferTexture listTexture;

    /**
     * Makes the ring or the streaming buffers and their textures, each added to {@code owned} as it is made.
     *
     * @param t             the context's tracker
     * @param instanceBytes most bytes of instance records in a frame
     * @param stateBytes    bytes of every component's render state
     * @param listBytes     bytes of the largest list table
     * @param storage       whether the context has buffer storage ({@link GlUploadRing#supported})
     * @param owned         the owner's resources, closed in reverse by it
     */
    ResolverUploads(GlTracker t, long instanceBytes, long stateBytes, long listBytes, boolean storage,
                    List<AutoCloseable> owned) {
        if (storage) {
            ring = own(owned, new GlUploadRing(t, instanceBytes, stateBytes, listBytes));
            instanceBuffer = null;
            stateBuffer = null;
            listBuffer = null;
            instanceTexture = own(owned, new GlBufferTexture(t, ring.id(), GL_RG32I));
            stateTexture = own(owned, new GlBufferTexture(t, ring.id(), GL_RG32F));
            listTexture = own(owned, new GlBufferTexture(t, ring.id(), GL_RGBA32I));
        } else {
            ring = null;
            stateBuffer = own(owned, GlBuffer.dynamic(t, GL_TEXTURE_BUFFER, stateBytes));
            stateTexture = own(owned, new GlBufferTexture(t, stateBuffer, GL_RG32F));
            instanceBuffer = own(owned, GlBuffer.dynamic(t, GL_TEXTURE_BUFFER, instanceBytes));
            instanceTexture = own(owned, new GlBufferTexture(t, instanceBuffer, GL_RG32I));
            listBuffer = own(owned, GlBuffer.dynamic(t, GL_TEXTURE_BUFFER, listBytes));
            listTexture = own(owned, new GlBufferTexture(t, listBuffer, GL_RGBA32I));
        }
    }

    private static <T extends AutoCloseable> T own(List<AutoCloseable> owned, T resource) {
        owned.add(resource);
        return resource;
    }

    /**
     * This frame's instance records (position to limit of {@code instances}) and the render states of the
     * component ranges {@code batches} names, copied from {@code frame}. Returns the bytes of render states.
     */
    long upload(IntBuffer instances, Frame frame, PlantBatches batches) {
        long base = MemoryUtil.memAddress0((java.nio.Buffer) frame.renderStates());
        long states = 0;
        if (ring != null) {
            // straight into this frame's region of the mapped ring: no GL call, nothing re-specified
            ring.next();
            MemoryUtil.memCopy(MemoryUtil.memAddress(instances), MemoryUtil.memAddress(ring.view(INSTANCES)),
                    4L * instances.remaining());
            states = MemoryUtil.memAddress(ring.view(STATES));
        } else {
            instanceBuffer.orphan();
            instanceBuffer.upload(0, instances);
        }
        long bytes = 0;
        ComponentRuns runs = batches.runs();
        for (int i = 0, n = runs.count(); i < n; i++) {
            long c0 = runs.start(i);
            long at = (long) Frame.RENDER_STATE_BYTES * c0;
            long size = (long) Frame.RENDER_STATE_BYTES * (runs.end(i) - c0);
            if (ring != null) {
                MemoryUtil.memCopy(base + at, states + at, size);
            } else {
                stateBuffer.upload(at, base + at, size);
            }
            bytes += size;
        }
        return bytes;
    }

    /** Binds the instance records and render states to their units for the resolve pass. */
    void bind() {
        if (ring != null) {
            instanceTexture.range(TextureUnits.INSTANCES, ring.id(), ring.offset(INSTANCES), ring.bytes(INSTANCES));
            stateTexture.range(TextureUnits.RENDER_STATES, ring.id(), ring.offset(STATES), ring.bytes(STATES));
        } else {
            instanceTexture.bind(TextureUnits.INSTANCES);
            stateTexture.bind(TextureUnits.RENDER_STATES);
        }
    }

    /** Uploads the compute path's list table (position to limit) and binds it to its unit. */
    void lists(IntBuffer table) {
        if (ring != null) {
            MemoryUtil.memCopy(MemoryUtil.memAddress(table), MemoryUtil.memAddress(ring.view(LISTS)),
                    4L * table.remaining());
            listTexture.range(TextureUnits.LIST_TABLE, ring.id(), ring.offset(LISTS), ring.bytes(LISTS));
        } else {
            listBuffer.orphan();
            listBuffer.upload(0, table);
            listTexture.bind(TextureUnits.LIST_TABLE);
        }
    }

    /** Fences the ring's region once the commands that read it (the resolve pass) are issued. */
    void fence() {
        if (ring != null) {
            ring.fence();
        }
    }

    /** {@return whether the uploads go through a ring} */
    boolean ring() {
        return ring != null;
    }

    /** {@return frames that waited for their ring region (0 without a ring)} */
    long waits() {
        return ring == null ? 0 : ring.waits();
    }
}
