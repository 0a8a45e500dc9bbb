package org.jecosys.render;

import java.util.logging.Logger;
import org.jecosys.math.Require;
import org.jecosys.sim.DrawQuality;
import org.jecosys.sim.Simulation;

/**
 * The draw quality an embedded meadow starts with, as the desktop viewer chooses it: the game's own
 * choice when it made one, otherwise {@link DrawQuality#LOW} on a software rasteriser (Mesa's llvmpipe
 * or softpipe, SwiftShader: thinning far plants is what keeps a frame there under a second) and the
 * scene's own {@code <field thinStart thinEnd thinMinFraction>} on a GPU. The engine adapters call it
 * when they make their renderer; a raw LWJGL game may too.
 */
public final class SoftwareQuality {
    private static final Logger LOG = Logger.getLogger("org.jecosys.render");

    private SoftwareQuality() {
    }

    /**
     * Applies the start quality to a simulation ({@link DrawQuality#applyTo}). When it picks the low
     * quality by itself it says so, once per call (an adapter calls it once, when it makes its
     * renderer), at INFO on the {@code org.jecosys.render} logger. Render thread, with {@code gl} current (it reads {@code GL_RENDERER}); allocates (once).
     *
     * @param gl        the context the plants are drawn in
     * @param sim       the simulation to set
     * @param requested the game's choice, or null to choose by the renderer
     * @return what was applied: {@code requested}, {@link DrawQuality#LOW} on a software rasteriser, or
     *         null when the scene's own thinning was kept
     * @throws IllegalArgumentException when gl or sim is null
     */
    public static DrawQuality apply(GlContext gl, Simulation sim, DrawQuality requested) {
        Require.nonNull("gl", gl);
        Require.nonNull("sim", sim);
        if (requested != null) {
            requested.applyTo(sim);
            return requested;
        }
        String renderer = gl.describe();
        if (!ShadowPath.software(renderer)) {
            return null;
        }
        DrawQuality.LOW.applyTo(sim);
        LOG.info("JEcoSys: a software renderer (" + renderer + "): the plants are drawn at the low quality "
                + "(far plants thinned); choose another quality to override");
        return DrawQuality.LOW;
    }
}
