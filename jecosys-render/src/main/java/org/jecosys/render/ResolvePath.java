package org.jecosys.render;

import org.lwjgl.opengl.GLCapabilities;

/**
 * How the plants of a {@link SceneRenderer} run their per-component pass, the step between the animation workers'
 * 8 bytes per component and the instanced draws (paper §4.1-4.2: each drawn component's base, bend
 * azimuth, pose pair and weight, and colour). Both paths run the same shader code
 * ({@code plant_resolve.glsl}) and give the same records; they differ in how the GPU is asked.
 * Chosen once per renderer from the context's capabilities and renderer
 * ({@link #best(GLCapabilities, String)}) unless the caller names one; the HUD and the benchmark
 * reports name it ({@link #description}).
 *
 * <p>Immutable; any thread.
 */
public enum ResolvePath {
    /**
     * OpenGL 3.3 core: one vertex per drawn component, rasterisation discarded, the records captured
     * by transform feedback. Runs everywhere the renderer runs. A software rasteriser (Mesa's
     * llvmpipe) runs vertex shaders on the calling thread only.
     */
    TRANSFORM_FEEDBACK("GL 3.3 core: worker-written states, GPU resolve (transform feedback), instanced draws"),
    /**
     * OpenGL 4.3 and later: one compute invocation per drawn component, the records stored into a
     * shader storage buffer. A software rasteriser runs compute on all its threads.
     */
    COMPUTE("GL 4.3: worker-written states, GPU resolve (compute shader), instanced draws");

    private final String description;

    ResolvePath(String description) {
        this.description = description;
    }

    /** {@return a one-line description for the HUD and benchmark reports} */
    public String description() {
        return description;
    }

    /**
     * Whether a context with these capabilities can run this path. No allocation.
     *
     * @param caps the context's capabilities ({@link GlContext#capabilities()})
     * @return true for {@link #TRANSFORM_FEEDBACK} always; for {@link #COMPUTE} when the context
     *         is OpenGL 4.3 or later
     */
    public boolean supported(GLCapabilities caps) {
        return this == TRANSFORM_FEEDBACK || caps.OpenGL43;
    }

    /**
     * The faster path a context supports: {@link #COMPUTE} where it can run, else
     * {@link #TRANSFORM_FEEDBACK}. No allocation.
     *
     * @param caps the context's capabilities
     * @return the path to use
     */
    public static ResolvePath best(GLCapabilities caps) {
        return COMPUTE.supported(caps) ? COMPUTE : TRANSFORM_FEEDBACK;
    }

    /**
     * {@link #best(GLCapabilities, String)} for the context {@code gl} wraps. Render thread (the
     * context current); no allocation past the renderer string.
     *
     * @param gl the context
     * @return the path a renderer on it takes by itself
     */
    public static ResolvePath best(GlContext gl) {
        return best(gl.capabilities(), org.lwjgl.opengl.GL11C.glGetString(org.lwjgl.opengl.GL11C.GL_RENDERER));
    }

    /**
     * The path a renderer takes by itself: {@link #best(GLCapabilities)}, except on a software
     * rasteriser (Mesa's llvmpipe or softpipe, SwiftShader), which gets {@link #TRANSFORM_FEEDBACK}:
     * measured with llvmpipe on 2 cores, compute was slower for small scenes (C1: 8.3-8.9 ms per
     * frame against 7.8-7.9), alike or a little faster for the meadow, and llvmpipe's storage blocks
     * (128 MiB) cannot hold the records of the larger shipped scenes at all. No allocation.
     *
     * @param caps     the context's capabilities
     * @param renderer the context's {@code GL_RENDERER} string (null: unknown)
     * @return the path to use
     */
    public static ResolvePath best(GLCapabilities caps, String renderer) {
        return org.jecosys.render.gl.SoftwareGl.is(renderer) ? TRANSFORM_FEEDBACK : best(caps);
    }
}
