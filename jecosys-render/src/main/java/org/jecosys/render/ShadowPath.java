package org.jecosys.render;

/**
 * How the plants' sun shadows ({@link RenderSettings#shadows()}) are drawn. The strength and the
 * sun come from the scene ({@code <light shadows>}); the path is the machine's choice, so it is a
 * setting of the renderer, not of the scene file.
 *
 * <p>Immutable; any thread.
 */
public enum ShadowPath {
    /**
     * {@link #MAP} on a GPU, {@link #GROUND} on a software rasteriser (Mesa's llvmpipe or softpipe,
     * SwiftShader), where drawing the plants a second time from the sun costs about as much as the
     * frame itself. The default.
     */
    AUTO,
    /**
     * The cheap path: each plant's rest pose splatted once onto a map of the ground along the sun; the
     * shadows fall on the terrain and the ground cover, do not sway and do not fall on plants.
     */
    GROUND,
    /**
     * A shadow map drawn every frame: the plants as they sway, seen from the sun, over the near part of
     * the view ({@link RenderSettings#shadowReach()}); the plants shade the terrain, the ground cover and
     * each other. Beyond its reach the ground keeps the splatted shadows of {@link #GROUND}.
     */
    MAP;

    /**
     * The path a renderer takes on a GL: this one, or for {@link #AUTO} the one its renderer string
     * calls for. No allocation.
     *
     * @param renderer the GL's {@code GL_RENDERER} string (null: unknown, taken as a GPU)
     * @return {@link #GROUND} or {@link #MAP}
     */
    public ShadowPath on(String renderer) {
        if (this != AUTO) {
            return this;
        }
        return software(renderer) ? GROUND : MAP;
    }

    /**
     * Whether a GL renderer string names a software rasteriser: Mesa's llvmpipe or softpipe, or
     * SwiftShader. No allocation.
     *
     * @param renderer {@code GL_RENDERER}, or null
     * @return whether it is one
     */
    public static boolean software(String renderer) {
        return org.jecosys.render.gl.SoftwareGl.is(renderer);
    }
}
