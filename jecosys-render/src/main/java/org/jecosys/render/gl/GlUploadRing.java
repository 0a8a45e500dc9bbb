package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL11C.glGetInteger;
import static org.lwjgl.opengl.GL15C.glBindBuffer;
import static org.lwjgl.opengl.GL15C.glDeleteBuffers;
import static org.lwjgl.opengl.GL15C.glGenBuffers;
import static org.lwjgl.opengl.GL30C.GL_MAP_WRITE_BIT;
import static org.lwjgl.opengl.GL30C.glMapBufferRange;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BUFFER;
import static org.lwjgl.opengl.GL32C.GL_ALREADY_SIGNALED;
import static org.lwjgl.opengl.GL32C.GL_CONDITION_SATISFIED;
import static org.lwjgl.opengl.GL32C.GL_SYNC_FLUSH_COMMANDS_BIT;
import static org.lwjgl.opengl.GL32C.GL_SYNC_GPU_COMMANDS_COMPLETE;
import static org.lwjgl.opengl.GL32C.GL_WAIT_FAILED;
import static org.lwjgl.opengl.GL32C.glClientWaitSync;
import static org.lwjgl.opengl.GL32C.glDeleteSync;
import static org.lwjgl.opengl.GL32C.glFenceSync;
import static org.lwjgl.opengl.GL43C.GL_TEXTURE_BUFFER_OFFSET_ALIGNMENT;
import static org.lwjgl.opengl.GL44C.GL_MAP_COHERENT_BIT;
import static org.lwjgl.opengl.GL44C.GL_MAP_PERSISTENT_BIT;
import static org.lwjgl.opengl.GL44C.glBufferStorage;

import java.nio.ByteBuffer;
import org.lwjgl.opengl.GLCapabilities;

/**
 * Per-frame uploads without a stall: one buffer of immutable storage ({@code glBufferStorage}), mapped
 * once, persistently and coherently, for writing, and cut into {@link #REGIONS} regions that frames
 * take in turn. A frame writes its data straight into its region's mapping (no {@code glBufferSubData},
 * no re-specified storage) and fences the region once the GPU commands that read it are issued
 * ({@link #fence}); the region is written again {@code REGIONS} frames later, when its fence has long
 * signalled: {@link #next} only polls it (a zero timeout), and a frame that finds it still unsignalled
 * (the GPU more than two frames behind) waits for it and is counted ({@link #waits}), never silently.
 * Each region holds parts at offsets aligned for texture-buffer ranges, bound with
 * {@link GlBufferTexture#range}.
 *
 * <p>Needs {@code glBufferStorage} and {@code glTexBufferRange} (OpenGL 4.4, or
 * {@code ARB_buffer_storage} with 4.3): {@link #supported}. Render thread only; the constructor
 * allocates (direct views of the mapping, made once); {@link #next}, {@link #view} and {@link #fence}
 * allocate nothing.
 */
public final class GlUploadRing extends GlResource {
    /** Regions in the ring: the frame being written and two the GPU may still read. */
    public static final int REGIONS = 3;

    private final long[] partOffset;
    private final long[] partBytes;
    private final long regionBytes;
    private final ByteBuffer[][] views;
    private final long[] fences = new long[REGIONS];
    private int region = REGIONS - 1;
    private long waits;

    /**
     * Whether a context has what the ring needs.
     *
     * @param caps the context's capabilities
     * @return true with OpenGL 4.4, or 4.3 with {@code ARB_buffer_storage}
     */
    public static boolean supported(GLCapabilities caps) {
        return caps.OpenGL44 || (caps.OpenGL43 && caps.GL_ARB_buffer_storage);
    }

    /**
     * Makes the buffer and maps it. Render thread, context current; allocates.
     *
     * @param tracker counts the object
     * @param parts   bytes of each part of a region, each &gt; 0 (e.g. instance records, render states)
     * @throws IllegalArgumentException when a part is empty
     * @throws IllegalStateException when the mapping fails
     */
    public GlUploadRing(GlTracker tracker, long... parts) {
        super(tracker, glGenBuffers());
        int align = Math.max(4, glGetInteger(GL_TEXTURE_BUFFER_OFFSET_ALIGNMENT));
        partOffset = new long[parts.length];
        partBytes = parts.clone();
        long at = 0;
        for (int p = 0; p < parts.length; p++) {
            if (parts[p] <= 0) {
                close();
                throw new IllegalArgumentException("part " + p + " of an upload ring must be > 0 bytes, got " + parts[p]);
            }
            partOffset[p] = at;
            at = (at + parts[p] + align - 1) / align * align;
        }
        regionBytes = at;
        long total = regionBytes * REGIONS;
        int flags = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
        glBindBuffer(GL_TEXTURE_BUFFER, id());
        glBufferStorage(GL_TEXTURE_BUFFER, total, flags);
        ByteBuffer mapped = glMapBufferRange(GL_TEXTURE_BUFFER, 0, total, flags);
        glBindBuffer(GL_TEXTURE_BUFFER, 0);
        if (mapped == null) {
            close();
            throw new IllegalStateException("the GL could not map an upload ring of " + total + " bytes");
        }
        views = new ByteBuffer[REGIONS][parts.length];
        for (int r = 0; r < REGIONS; r++) {
            for (int p = 0; p < parts.length; p++) {
                views[r][p] = mapped.slice((int) (r * regionBytes + partOffset[p]), (int) parts[p])
                        .order(java.nio.ByteOrder.nativeOrder());
            }
        }
    }

    /**
     * Moves to the next region, waiting only if the GPU has not finished the frame that last used it
     * (counted). No allocation.
     */
    public void next() {
        region = (region + 1) % REGIONS;
        long f = fences[region];
        if (f == 0) {
            return;
        }
        int status = glClientWaitSync(f, 0, 0); // a poll: returns at once
        if (status != GL_ALREADY_SIGNALED && status != GL_CONDITION_SATISFIED) {
            waits++;
            do {
                status = glClientWaitSync(f, GL_SYNC_FLUSH_COMMANDS_BIT, 1_000_000_000L);
            } while (status != GL_ALREADY_SIGNALED && status != GL_CONDITION_SATISFIED && status != GL_WAIT_FAILED);
        }
        glDeleteSync(f);
        fences[region] = 0;
    }

    /**
     * {@return the current region's part {@code p}, mapped: position 0, limit its size, native order}
     * Writes reach the GPU with no call (coherent mapping). No allocation.
     *
     * @param p part index
     */
    public ByteBuffer view(int p) {
        ByteBuffer b = views[region][p];
        b.clear();
        return b;
    }

    /**
     * {@return the byte offset of the current region's part {@code p} in the buffer}
     *
     * @param p part index
     */
    public long offset(int p) {
        return region * regionBytes + partOffset[p];
    }

    /**
     * {@return the size of part {@code p}, bytes}
     *
     * @param p part index
     */
    public long bytes(int p) {
        return partBytes[p];
    }

    /** Fences the current region after the commands that read it were issued. No allocation. */
    public void fence() {
        if (fences[region] != 0) {
            glDeleteSync(fences[region]);
        }
        fences[region] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        // sent on its way now, so that it can signal before anyone asks (a poll does not flush)
        org.lwjgl.opengl.GL11C.glFlush();
    }

    /** {@return the frames that found their region still in use by the GPU and waited for it, since creation} */
    public long waits() {
        return waits;
    }

    @Override
    public void delete(int name) {
        for (int r = 0; fences != null && r < REGIONS; r++) { // null: the tracker refused the buffer in super()
            if (fences[r] != 0) {
                glDeleteSync(fences[r]);
                fences[r] = 0;
            }
        }
        glDeleteBuffers(name); // unmaps it
    }
}
