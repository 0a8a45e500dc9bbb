package org.jecosys.render.plant;

import static org.lwjgl.opengl.GL11C.GL_BLEND;
import static org.lwjgl.opengl.GL11C.GL_LEQUAL;
import static org.lwjgl.opengl.GL11C.GL_LESS;
import static org.lwjgl.opengl.GL11C.glDepthFunc;
import static org.lwjgl.opengl.GL11C.GL_ONE;
import static org.lwjgl.opengl.GL11C.GL_ONE_MINUS_SRC_ALPHA;
import static org.lwjgl.opengl.GL11C.GL_SRC_ALPHA;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL13C.GL_MULTISAMPLE;
import static org.lwjgl.opengl.GL13C.GL_SAMPLE_ALPHA_TO_COVERAGE;
import static org.lwjgl.opengl.GL13C.GL_SAMPLE_ALPHA_TO_ONE;
import static org.lwjgl.opengl.GL14C.glBlendFuncSeparate;
import static org.lwjgl.opengl.GL30C.glDisablei;

/**
 * How {@link PlantRenderer} puts the plants' partial coverage on the bound target: the share of a pixel
 * a thin part covers (its alpha) is blended, in two passes for the triangle levels (an opaque core
 * writing depth, then the fringe that only blends, so a faint edge never hides what is behind it) and
 * one blended pass for the line levels; or, on a multisampled target where blending on samples is off,
 * the GL's alpha-to-coverage with opaque plants.
 *
 * <p>Without samples the two passes use the split programs, which discard what is not theirs, and both
 * have the soft edge ({@link PlantUniforms#FEATHER}). With samples the core goes to the samples its
 * geometry covers, without a soft edge, and the fringe is drawn on pixel centres with one
 * ({@link #FRINGE_FEATHER}; multisampling off for its pass): each of its fragments blends into every sample of its pixel that
 * passes a strict depth test. Both passes use the ordinary programs, which never discard (a software
 * rasteriser then tests depth before shading): the core's pass cuts alpha to 0 or 1 ({@code uCoreCut})
 * and writes it through alpha-to-coverage, so only the core reaches the samples, and its vertex shader
 * leaves out, before any pose or light work, the blades and stems whose widest half width is under the
 * least half width wherever they reach (they have no core); the fringe's pass gives alpha 0 to every
 * fragment whose coverage (the soft edge left out) reaches the core's, so what the core drew, its edges
 * anti-aliased on the samples included, is left to it. The picture is the split programs' (with the
 * fringe on pixel centres too) but for rounding ({@code CoreCutTest}).
 *
 * <p>Cost on llvmpipe at 1920x1080, the meadow: the core cut takes the near plants about a fifth under
 * drawing them twice whole; the fringe on pixel centres takes them to about 0.7 of the fringe on
 * samples, whose long thin triangles were set up, binned and depth-tested per sample. Render thread; no
 * allocation.
 */
final class CoverageDraws {
    /** The least alpha of the opaque core (the split programs' threshold, plant.frag). */
    private static final float CORE = 0.996f;
    private boolean blendOnSamples = true;
    private boolean coreCut = true;
    /**
     * The soft edge of the fringe drawn on a multisampled target's pixel centres, pixels: wider than a
     * target without samples takes ({@link PlantUniforms#FEATHER}), so that the thin parts step from
     * pixel to pixel no more than they did on the samples. Measured on the meadow's start view at
     * 960x540 (0.5 / 0.625 / 0.7 / 0.75 / 1.0): half a pixel of camera motion held still 16 frames
     * 2.01 / 1.93 / 1.88 / 1.85 / 1.71 per 255 (bound 2; 1.91 on the samples), fine detail held still
     * 0.86 / 0.84 / 0.83 / 0.82 / 0.78 of the supersampled view (bound 0.8; 0.83 on the samples).
     */
    static final float FRINGE_FEATHER = 0.7f;
    /** {@code uCoreCut} of the fringe's pass: parts that are all core are left out. */
    private static final float FRINGE = -1f;

    /** Sets whether multisampled targets blend thin parts too (else alpha-to-coverage). */
    void setBlendOnSamples(boolean on) {
        blendOnSamples = on;
    }

    /** Sets whether multisampled targets draw the core with the alpha cut (else the split programs). */
    void setCoreCut(boolean on) {
        coreCut = on;
    }

    /** {@return whether the near plants are blended for a target as {@code c} describes} */
    boolean blends(PassContext c) {
        return !c.multisampled || blendOnSamples;
    }

    /**
     * {@return whether a target with or without samples gets the near plants in two passes on its samples,
     * the core and then the fringe (the core cut or the split programs)}
     */
    boolean twoPassesOnSamples(boolean multisampled) {
        return multisampled && blendOnSamples;
    }

    /** Draws the prepared triangle levels (the split programs compiled on first use). */
    void near(PassContext c, PlantGpu gpu, PlantPasses passes, PlantBatches batches, PlantLook look, int levelMask) {
        if (!blends(c)) {
            // coverage to samples, and alpha 1 stored (alpha-to-one): plants are opaque
            coverageToSamples(true);
            passes.drawTriangles(batches, gpu.vaos, gpu.indexCount, look, levelMask);
            coverageToSamples(false);
            return;
        }
        if (c.multisampled && coreCut) {
            // the core: alpha cut to 0 or 1, to samples by alpha-to-coverage, depth written, no discard
            passes.setCoreCut(CORE);
            coverageToSamples(true);
            passes.drawTrianglesCore(batches, gpu.vaos, gpu.indexCount, look, levelMask);
            coverageToSamples(false);
            // the fringe: blended, depth tested but not written; the core's own fragments, at exactly the
            // depth they wrote (the same programs), fail the strict test and are not blended again; parts
            // that are all core (flower parts, meshes) are left out in the vertex shader (plant.vert)
            passes.setCoreCut(FRINGE);
            blendByCoverage(true);
            glDepthMask(false);
            glDepthFunc(GL_LESS);
            fringeOnPixels(passes, true);
            passes.drawTrianglesAgain(batches, gpu.vaos, gpu.indexCount, look, levelMask);
            fringeOnPixels(passes, false);
            glDepthFunc(GL_LEQUAL);
            glDepthMask(true);
            blendByCoverage(false);
            passes.setCoreCut(0f);
            return;
        }
        if (!passes.hasSplit()) {
            gpu.compileSplit(passes);
            passes.frame(look, c); // this frame's values onto the new programs
            passes.shadow(look);
        }
        // the opaque core writes depth; the fringe (soft edges, thin parts) only blends, so it hides nothing
        blendByCoverage(true);
        passes.drawTrianglesSplit(true, false, batches, gpu.vaos, gpu.indexCount, look, levelMask);
        glDepthMask(false);
        if (c.multisampled) {
            glDepthFunc(GL_LESS);
            fringeOnPixels(passes, true);
        }
        passes.drawTrianglesSplit(false, c.multisampled, batches, gpu.vaos, gpu.indexCount, look, levelMask);
        if (c.multisampled) {
            fringeOnPixels(passes, false);
            glDepthFunc(GL_LEQUAL);
        }
        glDepthMask(true);
        blendByCoverage(false);
    }

    /** Draws the prepared line levels. */
    void far(PassContext c, PlantGpu gpu, PlantPasses passes, PlantBatches batches, PlantLook look, int levelMask) {
        if (!blends(c)) {
            // multisampled: coverage to samples, as the triangle levels, depth written, alpha 1 stored
            coverageToSamples(true);
            passes.drawLines(batches, gpu.vaos, gpu.indexCount, look, levelMask);
            coverageToSamples(false);
            return;
        }
        blendByCoverage(true);
        glDepthMask(false);
        passes.drawLines(batches, gpu.vaos, gpu.indexCount, look, levelMask);
        glDepthMask(true);
        blendByCoverage(false);
    }

    /**
     * Turns the fringe's rasterisation on pixel centres on (multisampling off, the soft edge on) or back
     * to the target's samples. A multisampled target's fringe is the thin parts and the outer edges of
     * the wide ones, blended by the share of a pixel they cover; rasterised on its samples, each of its
     * long, thin triangles was set up, binned and depth-tested four times over on a software rasteriser,
     * most of the near plants' cost. On pixel centres it is drawn once per pixel into every sample it
     * passes the depth test on, with a soft edge ({@link #FRINGE_FEATHER}: the ribbon that much wider,
     * fading over it), so its edges step from pixel to pixel no more than on the samples
     * ({@code AntiAliasingTest}). The core stays on the samples. The host's multisampling switch is
     * saved and put back by the guard.
     */
    private static void fringeOnPixels(PlantPasses passes, boolean on) {
        if (on) {
            glDisable(GL_MULTISAMPLE);
            passes.setFeather(FRINGE_FEATHER);
        } else {
            passes.setFeather(0f);
            glEnable(GL_MULTISAMPLE);
        }
    }

    /** Turns alpha-to-coverage with alpha-to-one (plants opaque, coverage to samples) on or off. */
    private static void coverageToSamples(boolean on) {
        if (on) {
            glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
            glEnable(GL_SAMPLE_ALPHA_TO_ONE);
        } else {
            glDisable(GL_SAMPLE_ALPHA_TO_ONE);
            glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
        }
    }

    /**
     * Turns blending by coverage on or off: colour blended by alpha, alpha composited "over"
     * (a + d (1 - a)), so plants stay opaque over an opaque target. Draw buffer 1, the library
     * framebuffer's detail mask ({@code plant.frag}'s {@code fragDetail}, 1 from every plant fragment,
     * alpha 1), is written rather than blended: blending 1 over anything by its alpha 1 gives 1, the same
     * value, without reading each sample first (on llvmpipe at 1920x1080 the meadow's near plants cost
     * about a tenth less). A host's other draw buffers are masked off ({@code GlStateGuard}).
     */
    private static void blendByCoverage(boolean on) {
        if (on) {
            glEnable(GL_BLEND);
            glDisablei(GL_BLEND, 1);
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        } else {
            glDisable(GL_BLEND);
        }
    }
}
