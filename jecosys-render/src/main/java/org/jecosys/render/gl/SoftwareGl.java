package org.jecosys.render.gl;

/**
 * Recognises software rasterisers by their {@code GL_RENDERER} string: Mesa's llvmpipe and softpipe,
 * and SwiftShader. The renderers choose cheaper paths there (the resolve by transform feedback, the
 * splatted sun shadows). Any thread; no allocation.
 */
public final class SoftwareGl {
    private SoftwareGl() {
    }

    /**
     * Whether a GL renderer string names a software rasteriser.
     *
     * @param renderer {@code GL_RENDERER}, or null (unknown: taken as a GPU)
     * @return whether it is llvmpipe, softpipe or SwiftShader
     */
    public static boolean is(String renderer) {
        return renderer != null && (renderer.startsWith("llvmpipe") || renderer.startsWith("softpipe")
                || renderer.contains("SwiftShader"));
    }
}
