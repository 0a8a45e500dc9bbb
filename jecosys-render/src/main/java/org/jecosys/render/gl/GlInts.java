package org.jecosys.render.gl;

import org.lwjgl.opengl.GL11C;
import org.lwjgl.opengl.GL30C;
import org.lwjgl.opengl.GL32C;
import org.lwjgl.system.MemoryUtil;

/**
 * Integer state queries that allocate nothing: LWJGL's {@code glGetInteger(pname)} wraps a stack
 * buffer in a fresh {@code IntBuffer} object, which the JIT removes only when it inlines the call, so a
 * render loop with many queries can allocate a few bytes a frame or not, depending on its inlining
 * budget. These read through one native scratch word instead. Render thread only; owned by one
 * renderer, freed by {@link #close()}.
 */
public final class GlInts implements AutoCloseable {
    private final long scratch = MemoryUtil.nmemAlloc(16);
    private boolean closed;

    /** {@return the integer value of {@code pname}, as glGetIntegerv} */
    public int get(int pname) {
        GL11C.nglGetIntegerv(pname, scratch);
        return MemoryUtil.memGetInt(scratch);
    }

    /** {@return the indexed integer value of {@code target} at {@code index}, as glGetIntegeri_v} */
    public int get(int target, int index) {
        GL30C.nglGetIntegeri_v(target, index, scratch);
        return MemoryUtil.memGetInt(scratch);
    }

    /** {@return the indexed 64-bit value of {@code target} at {@code index}, as glGetInteger64i_v} */
    public long get64(int target, int index) {
        GL32C.nglGetInteger64i_v(target, index, scratch);
        return MemoryUtil.memGetLong(scratch);
    }

    @Override
    public void close() {
        if (!closed) {
            closed = true;
            MemoryUtil.nmemFree(scratch);
        }
    }
}
