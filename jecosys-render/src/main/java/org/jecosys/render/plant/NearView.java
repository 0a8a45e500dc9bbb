package org.jecosys.render.plant;

import java.nio.FloatBuffer;
import org.jecosys.math.Camera;
import org.jecosys.render.gl.GlInts;
import org.jecosys.sim.Frame;
import org.jecosys.sim.ViewDecision;
import org.joml.Matrix4f;
import org.lwjgl.opengl.GL13C;
import org.lwjgl.system.MemoryUtil;

/**
 * The camera and target a {@link PlantRenderer}'s near plants are prepared for
 * ({@link PlantRenderer#prepareNear}): the samples per pixel of the bound target (and whether plants in
 * a band are drawn whole on it), which decision the
 * frame's lists take (the frame's own when its step followed this very camera, else one made here by a
 * {@link ViewDecision}: the frustum and levels of that camera, with a warning, once per renderer, when
 * it draws many plants no view of the simulation animates), and the pass context's view values from
 * the camera (view-projection, eye, a pixel's size, the flower parts' scale). Owns the view-projection's
 * native floats and the integer query, freed by {@link #close()}. Render thread; built with the
 * renderer (allocates), no allocation after.
 */
final class NearView implements AutoCloseable {
    /** Plants a camera may draw unanimated before {@link #decide} says so (the field's one-step lag). */
    static final int STILL_PLANTS = 50;

    /** The decision for a camera the frame's own decision was not made for (another view, a cut). */
    private final ViewDecision view;
    /** How far each list's plants keep a core, for the core's pass of a multisampled target. */
    private final CoreReach reach;
    private final Matrix4f viewProj = new Matrix4f();
    /** The view-projection as the passes read it, 16 floats column-major (native memory). */
    final FloatBuffer matrix;
    private final GlInts query;
    /** Whether a camera no view covers was reported (once per renderer). */
    private boolean saidStill;
    /** Band plants are drawn whole below this many samples per pixel ({@link PlantRenderer#setWholePlantsBelow}). */
    int wholePlantsBelow = 2;
    private boolean closed;

    /**
     * Allocates the view-projection's floats and the query (freed again if this fails). Render thread.
     *
     * @param view  the decision for other cameras, made for the renderer's world
     * @param reach the distances beyond which the world's plants have no core
     */
    NearView(ViewDecision view, CoreReach reach) {
        this.view = view;
        this.reach = reach;
        FloatBuffer mat = MemoryUtil.memAllocFloat(16);
        try {
            query = new GlInts();
        } catch (RuntimeException | Error e) {
            MemoryUtil.memFree((java.nio.Buffer) mat);
            throw e;
        }
        matrix = mat;
    }

    /**
     * Reads the samples per pixel of the bound draw target and tells {@code batches} whether plants in a
     * band are drawn whole there (fewer samples than {@link #wholePlantsBelow}). No allocation.
     *
     * @return the samples per pixel
     */
    int target(PlantBatches batches) {
        int samples = query.get(GL13C.GL_SAMPLES);
        batches.setWholePlants(samples < wholePlantsBelow);
        return samples;
    }

    /**
     * Tells {@code batches} whether to list apart the whole plants that have no core where they stand
     * for {@code camera} ({@link PlantBatches#setCoreless}): only when the near plants' core is drawn in a
     * pass of its own on a multisampled target ({@code twoPasses}; whether that pass then leaves them out
     * is {@link PlantPasses#setLeaveOutCoreless}'s), with the values the draw programs get this frame. No
     * allocation.
     */
    void coreless(boolean twoPasses, Camera camera, int viewportHeight, float minPixels, Frame frame,
                  PlantBatches batches) {
        if (!twoPasses) {
            batches.setCoreless(null, 0, 0);
            return;
        }
        reach.update(minPixels, (float) (camera.viewHeightAtEye() / viewportHeight),
                (float) (camera.viewHeightPerMetre() / viewportHeight), frame.thinStart(), frame.thinEnd(),
                frame.thinMinFraction());
        batches.setCoreless(reach, (float) camera.x(), (float) camera.z());
    }

    /**
     * Fills {@code batches} with what {@code frame} draws for {@code camera}: the frame's own decision
     * when made for this very camera, else one decided here (every plant's state is in the frame); warns
     * once when such a camera draws many plants standing still. No allocation (but the warning's).
     */
    void decide(Frame frame, Camera camera, PlantBatches batches) {
        if (frame.decidedFor(camera, viewProj)) {
            batches.update(frame); // the step's own decision, made by the workers for this very camera
        } else {
            view.decide(frame, camera); // any other view: decided here, every plant's state is in the frame
            batches.update(frame, view.levels(), view.keeps());
            // (a frame no step has written yet, before the first fixed step, stands still for every view)
            if (!saidStill && frame.decided() && view.unanimated() > Math.max(STILL_PLANTS, view.drawn() / 10)) {
                saidStill = true;
                java.util.logging.Logger.getLogger("org.jecosys.render").warning("JEcoSys: a camera draws "
                        + view.unanimated() + " of its " + view.drawn() + " plants standing still: no view of the "
                        + "simulation sees them; register the camera with Simulation.addView (said once)");
            }
        }
    }

    /**
     * Sets the view values of {@code context} from {@code camera} drawn into a viewport
     * {@code viewportHeight} pixels high: the view-projection (into {@link #matrix}), the eye, a pixel's
     * size and the flower parts' scale. No allocation.
     */
    void setCamera(Camera camera, int viewportHeight, PassContext context) {
        camera.viewProjection(viewProj);
        viewProj.get(matrix);
        context.setEye((float) camera.x(), (float) camera.y(), (float) camera.z());
        context.setPixel((float) (camera.viewHeightAtEye() / viewportHeight),
                (float) (camera.viewHeightPerMetre() / viewportHeight));
        context.headScale = viewportHeight / (float) PlantRenderer.HEAD_REFERENCE_HEIGHT;
    }

    /** Frees the floats and the query. Idempotent. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        MemoryUtil.memFree((java.nio.Buffer) matrix);
        query.close();
    }
}
