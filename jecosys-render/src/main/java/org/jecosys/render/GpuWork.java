package org.jecosys.render;

import static org.lwjgl.opengl.GL15C.GL_QUERY_RESULT;
import static org.lwjgl.opengl.GL15C.GL_SAMPLES_PASSED;
import static org.lwjgl.opengl.GL15C.glBeginQuery;
import static org.lwjgl.opengl.GL15C.glDeleteQueries;
import static org.lwjgl.opengl.GL15C.glEndQuery;
import static org.lwjgl.opengl.GL15C.glGenQueries;
import static org.lwjgl.opengl.GL30C.GL_PRIMITIVES_GENERATED;
import static org.lwjgl.opengl.GL33C.glGetQueryObjectui64;

import org.lwjgl.opengl.ARBPipelineStatisticsQuery;
import org.lwjgl.opengl.GLCapabilities;

/**
 * Counts the GPU work of what is drawn between {@link #begin()} and {@link #end()}, so that the
 * render path's cost can be judged on any machine, without timing a GPU: vertex and fragment shader
 * invocations, compute invocations and the primitives that enter clipping, from the pipeline-statistics
 * queries ({@code ARB_pipeline_statistics_query}, OpenGL 4.6 core), and the samples that pass the
 * depth test; where the GL lacks pipeline statistics, the primitives generated and the samples passed
 * only (the other counts are then -1). Render thread; made once (allocates its query objects), then
 * no allocation; reading the results waits for the GPU to finish the counted work.
 */
public final class GpuWork implements AutoCloseable {
    private static final int VERTICES = 0;
    private static final int FRAGMENTS = 1;
    private static final int PRIMITIVES = 2;
    private static final int COMPUTE = 3;
    private static final int SAMPLES = 4;
    private static final int GENERATED = 5;

    private final GlContext gl;
    private final boolean statistics;
    private final boolean compute;
    private final int[] queries = new int[6];
    private final long[] results = new long[6];
    private boolean counting;
    private boolean ready;
    private boolean closed;

    /**
     * Makes the queries. Render thread; allocates.
     *
     * @param gl the render context, current on this thread
     */
    public GpuWork(GlContext gl) {
        gl.checkThread();
        this.gl = gl;
        GLCapabilities caps = gl.capabilities();
        statistics = caps.GL_ARB_pipeline_statistics_query;
        compute = statistics && caps.OpenGL43;
        for (int i = 0; i < queries.length; i++) {
            queries[i] = glGenQueries();
        }
    }

    /** {@return whether the GL has pipeline statistics (else only primitives and samples are counted)} */
    public boolean pipelineStatistics() {
        return statistics;
    }

    /**
     * Starts counting. The counted work is every draw and dispatch until {@link #end()}, the host's
     * too. Render thread; no allocation.
     *
     * @throws IllegalStateException when already counting
     */
    public void begin() {
        gl.checkThread();
        if (counting) {
            throw new IllegalStateException("already counting: call end() first");
        }
        counting = true;
        ready = false;
        if (statistics) {
            glBeginQuery(ARBPipelineStatisticsQuery.GL_VERTEX_SHADER_INVOCATIONS_ARB, queries[VERTICES]);
            glBeginQuery(ARBPipelineStatisticsQuery.GL_FRAGMENT_SHADER_INVOCATIONS_ARB, queries[FRAGMENTS]);
            glBeginQuery(ARBPipelineStatisticsQuery.GL_CLIPPING_INPUT_PRIMITIVES_ARB, queries[PRIMITIVES]);
            if (compute) {
                glBeginQuery(ARBPipelineStatisticsQuery.GL_COMPUTE_SHADER_INVOCATIONS_ARB, queries[COMPUTE]);
            }
        }
        glBeginQuery(GL_SAMPLES_PASSED, queries[SAMPLES]);
        glBeginQuery(GL_PRIMITIVES_GENERATED, queries[GENERATED]);
    }

    /**
     * Stops counting and reads the results (waits for the GPU). Render thread; no allocation.
     *
     * @throws IllegalStateException when not counting
     */
    public void end() {
        gl.checkThread();
        if (!counting) {
            throw new IllegalStateException("not counting: call begin() first");
        }
        counting = false;
        if (statistics) {
            glEndQuery(ARBPipelineStatisticsQuery.GL_VERTEX_SHADER_INVOCATIONS_ARB);
            glEndQuery(ARBPipelineStatisticsQuery.GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
            glEndQuery(ARBPipelineStatisticsQuery.GL_CLIPPING_INPUT_PRIMITIVES_ARB);
            if (compute) {
                glEndQuery(ARBPipelineStatisticsQuery.GL_COMPUTE_SHADER_INVOCATIONS_ARB);
            }
        }
        glEndQuery(GL_SAMPLES_PASSED);
        glEndQuery(GL_PRIMITIVES_GENERATED);
        for (int i = 0; i < queries.length; i++) {
            boolean used = i == SAMPLES || i == GENERATED || (statistics && (i != COMPUTE || compute));
            results[i] = used ? glGetQueryObjectui64(queries[i], GL_QUERY_RESULT) : -1;
        }
        ready = true;
    }

    private long result(int i) {
        if (!ready) {
            throw new IllegalStateException("no counts yet: begin() and end() first");
        }
        return results[i];
    }

    /** {@return vertex shader invocations of the last count, or -1 without pipeline statistics} */
    public long vertexInvocations() {
        return result(VERTICES);
    }

    /** {@return fragment shader invocations of the last count, or -1 without pipeline statistics} */
    public long fragmentInvocations() {
        return result(FRAGMENTS);
    }

    /**
     * {@return primitives that entered clipping in the last count (the rasteriser's input), or, without
     * pipeline statistics, the primitives the vertex stage generated}
     */
    public long primitives() {
        return statistics ? result(PRIMITIVES) : result(GENERATED);
    }

    /** {@return compute shader invocations of the last count, or -1 without pipeline statistics on OpenGL 4.3} */
    public long computeInvocations() {
        return result(COMPUTE);
    }

    /** {@return samples that passed the depth test in the last count} */
    public long samplesPassed() {
        return result(SAMPLES);
    }

    /** Deletes the queries. Render thread; idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            gl.checkThread();
            glDeleteQueries(queries);
        }
    }
}
