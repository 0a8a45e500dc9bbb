package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL15C.GL_DYNAMIC_DRAW;
import static org.lwjgl.opengl.GL15C.glBindBuffer;
import static org.lwjgl.opengl.GL15C.glBufferData;
import static org.lwjgl.opengl.GL15C.glBufferSubData;
import static org.lwjgl.opengl.GL15C.glDeleteBuffers;
import static org.lwjgl.opengl.GL15C.glGenBuffers;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;

/**
 * A GL buffer object of fixed capacity (vertex, index, instance or texture-buffer storage).
 * Render thread only; uploads do not allocate on the Java heap.
 */
public final class GlBuffer extends GlResource {
    private final int target;
    private final long capacity;

    /**
     * Allocates {@code bytes} of uninitialised storage; leaves the buffer bound to its target.
     *
     * @param tracker counts the object (the renderer's {@code GlContext.tracker()})
     * @param target  binding target, e.g. {@code GL_ARRAY_BUFFER}
     * @param bytes   capacity, &gt; 0
     * @param usage   usage hint, e.g. {@code GL_STATIC_DRAW}
     * @throws IllegalArgumentException when {@code bytes} &le; 0
     */
    public GlBuffer(GlTracker tracker, int target, long bytes, int usage) {
        super(tracker, glGenBuffers());
        if (bytes <= 0) {
            close();
            throw new IllegalArgumentException("buffer size must be > 0, got " + bytes);
        }
        this.target = target;
        this.capacity = bytes;
        glBindBuffer(target, id());
        glBufferData(target, bytes, usage);
    }

    /**
     * A buffer holding {@code data} (position to limit); at least 4 bytes.
     *
     * @param tracker counts the object
     * @param target  binding target, e.g. {@code GL_ARRAY_BUFFER}
     * @param data    the floats to upload; its position is not changed
     * @param usage   usage hint, e.g. {@code GL_STATIC_DRAW}
     * @return the new buffer
     */
    public static GlBuffer of(GlTracker tracker, int target, FloatBuffer data, int usage) {
        GlBuffer b = new GlBuffer(tracker, target, Math.max(4, (long) data.remaining() * 4), usage);
        b.upload(0, data);
        return b;
    }

    /**
     * A buffer holding {@code data} (position to limit); at least 4 bytes.
     *
     * @param tracker counts the object
     * @param target  binding target, e.g. {@code GL_ELEMENT_ARRAY_BUFFER}
     * @param data    the ints to upload; its position is not changed
     * @param usage   usage hint, e.g. {@code GL_STATIC_DRAW}
     * @return the new buffer
     */
    public static GlBuffer of(GlTracker tracker, int target, IntBuffer data, int usage) {
        GlBuffer b = new GlBuffer(tracker, target, Math.max(4, (long) data.remaining() * 4), usage);
        b.upload(0, data);
        return b;
    }

    /**
     * A streaming buffer ({@code GL_DYNAMIC_DRAW}) of {@code bytes}.
     *
     * @param tracker counts the object
     * @param target  binding target
     * @param bytes   capacity, &gt; 0
     * @return the new buffer
     */
    public static GlBuffer dynamic(GlTracker tracker, int target, long bytes) {
        return new GlBuffer(tracker, target, bytes, GL_DYNAMIC_DRAW);
    }

    /** {@return the binding target, e.g. {@code GL_ARRAY_BUFFER}} */
    public int target() {
        return target;
    }

    /** {@return the capacity, bytes} */
    public long capacity() {
        return capacity;
    }

    /** Binds to the buffer's target. */
    public void bind() {
        glBindBuffer(target, id());
    }

    /**
     * Orphans the storage (re-specifies it with no data, same size and a streaming hint) so the
     * driver need not wait for draws still reading the old contents. Per frame; no heap allocation.
     */
    public void orphan() {
        glBindBuffer(target, id());
        glBufferData(target, capacity, org.lwjgl.opengl.GL15C.GL_STREAM_DRAW);
    }

    /**
     * Writes {@code data}'s remaining bytes at byte {@code offset}. No heap allocation.
     *
     * @param offset first byte written, &gt;= 0
     * @param data   position to limit is written; its position is not changed
     * @throws IllegalArgumentException when the upload does not fit the capacity
     */
    public void upload(long offset, ByteBuffer data) {
        check(offset, data.remaining());
        glBindBuffer(target, id());
        glBufferSubData(target, offset, data);
    }

    /**
     * Writes {@code data}'s remaining floats at byte {@code offset}. No heap allocation.
     *
     * @param offset first byte written, &gt;= 0
     * @param data   position to limit is written; its position is not changed
     * @throws IllegalArgumentException when the upload does not fit the capacity
     */
    public void upload(long offset, FloatBuffer data) {
        check(offset, 4L * data.remaining());
        glBindBuffer(target, id());
        glBufferSubData(target, offset, data);
    }

    /**
     * Writes {@code data}'s remaining ints at byte {@code offset}. No heap allocation.
     *
     * @param offset first byte written, &gt;= 0
     * @param data   position to limit is written; its position is not changed
     * @throws IllegalArgumentException when the upload does not fit the capacity
     */
    public void upload(long offset, IntBuffer data) {
        check(offset, 4L * data.remaining());
        glBindBuffer(target, id());
        glBufferSubData(target, offset, data);
    }

    /**
     * Writes {@code bytes} bytes read from native memory at {@code address} to byte {@code offset}:
     * for a range of a direct buffer without slicing it. Render thread; no heap allocation.
     *
     * @param offset  first byte written, &gt;= 0
     * @param address native address of the first byte to read (e.g. {@code MemoryUtil.memAddress0((java.nio.Buffer) buf)
     *                + start}); the caller keeps the memory alive and unchanged during the call
     * @param bytes   bytes to write, &gt;= 0
     * @throws IllegalArgumentException when the upload does not fit the capacity
     */
    public void upload(long offset, long address, long bytes) {
        check(offset, bytes);
        if (bytes == 0) {
            return;
        }
        glBindBuffer(target, id());
        org.lwjgl.opengl.GL15C.nglBufferSubData(target, offset, bytes, address);
    }

    private void check(long offset, long bytes) {
        if (offset < 0 || offset + bytes > capacity) {
            throw new IllegalArgumentException("upload of " + bytes + " bytes at " + offset
                    + " exceeds the buffer's " + capacity + " bytes");
        }
    }

    @Override
    public void delete(int name) {
        glDeleteBuffers(name);
    }
}
