package org.jecosys.render.plant;

import static org.lwjgl.opengl.GL11C.GL_BLEND;
import static org.lwjgl.opengl.GL11C.GL_ONE;
import static org.lwjgl.opengl.GL11C.GL_ONE_MINUS_SRC_ALPHA;
import static org.lwjgl.opengl.GL11C.GL_SRC_ALPHA;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL13C.GL_SAMPLE_ALPHA_TO_COVERAGE;
import static org.lwjgl.opengl.GL13C.GL_SAMPLE_ALPHA_TO_ONE;
import static org.lwjgl.opengl.GL14C.glBlendFuncSeparate;

/**
 * How {@link PlantRenderer} puts the plants' partial coverage on the bound target: the share of a pixel
 * a thin part covers (its alpha) is blended, on the samples its geometry covers where the target has
 * samples, in two passes for the triangle levels (an opaque core writing depth, then the fringe that only
 * blends, so a faint edge never hides what is behind it) and one blended pass for the line levels; or,
 * on a multisampled target where blending on samples is off, the GL's alpha-to-coverage with opaque
 * plants. Render thread; no allocation.
 */
final class CoverageDraws {
    private boolean blendOnSamples = true;

    /** Sets whether multisampled targets blend thin parts too (else alpha-to-coverage). */
    void setBlendOnSamples(boolean on) {
        blendOnSamples = on;
    }

    /** {@return whether the near plants are blended for a target as {@code c} describes} */
    boolean blends(PassContext c) {
        return !c.multisampled || blendOnSamples;
    }

    /** Draws the prepared triangle levels (the split programs compiled on first use). */
    void near(PassContext c, PlantGpu gpu, PlantPasses passes, PlantBatches batches, PlantLook look, int levelMask) {
        if (!blends(c)) {
            // coverage to samples, and alpha 1 stored (alpha-to-one): plants are opaque
            glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
            glEnable(GL_SAMPLE_ALPHA_TO_ONE);
            passes.drawTriangles(batches, gpu.vaos, gpu.indexCount, look, levelMask);
            glDisable(GL_SAMPLE_ALPHA_TO_ONE);
            glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
            return;
        }
        if (!passes.hasSplit()) {
            gpu.compileSplit(passes);
            passes.frame(look, c); // this frame's values onto the new programs
            passes.shadow(look);
        }
        glEnable(GL_BLEND);
        // colour blended by coverage; alpha composited "over": opaque over an opaque target. The opaque
        // core writes depth; the fringe (soft edges, thin parts) only blends, so it hides nothing
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        passes.drawTrianglesSplit(true, batches, gpu.vaos, gpu.indexCount, look, levelMask);
        glDepthMask(false);
        passes.drawTrianglesSplit(false, batches, gpu.vaos, gpu.indexCount, look, levelMask);
        glDepthMask(true);
        glDisable(GL_BLEND);
    }

    /** Draws the prepared line levels. */
    void far(PassContext c, PlantGpu gpu, PlantPasses passes, PlantBatches batches, PlantLook look, int levelMask) {
        if (!blends(c)) {
            // multisampled: coverage to samples, as the triangle levels, depth written, alpha 1 stored
            glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
            glEnable(GL_SAMPLE_ALPHA_TO_ONE);
            passes.drawLines(batches, gpu.vaos, gpu.indexCount, look, levelMask);
            glDisable(GL_SAMPLE_ALPHA_TO_ONE);
            glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
            return;
        }
        glEnable(GL_BLEND);
        // colour blended by coverage; alpha composited "over" (a + d (1 - a)): opaque over an opaque target
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(false);
        passes.drawLines(batches, gpu.vaos, gpu.indexCount, look, levelMask);
        glDepthMask(true);
        glDisable(GL_BLEND);
    }
}
