package org.jecosys.sim;

import org.jecosys.anim.SpringKinds;
import org.jecosys.field.ForceField;
import org.jecosys.math.Camera;
import org.jecosys.math.ViewLod;
import org.jecosys.wind.WindField;
import org.joml.FrustumIntersection;
import org.joml.Matrix4f;

/**
 * The per-step field side of a {@link Simulation} (paper §3, §5.1): advances the wind clock one
 * fixed step, notes where in the step the flows switched, and samples the force field into one of
 * two buffers (wind X and Z in m/s at each plant's node, visibility, the eye in metres and the view
 * frustum), so that the workers animate from one buffer while the stepping thread fills the other.
 *
 * <p>Threads: {@link #update} and {@link #sample} only on the stepping thread, while the workers
 * read the other buffer (the arrays are handed to {@link ChunkAnimator} at construction). Allocation:
 * the buffers are allocated once at construction; sampling allocates nothing.
 */
final class FieldSampler {
    /** Per buffer, the wind X (m/s) at each plant's node. */
    final float[][] windX = new float[2][];
    /** Per buffer, the wind Z (m/s) at each plant's node. */
    final float[][] windZ = new float[2][];
    /**
     * Per buffer, the wind of the flows that flatten ({@link WindField#flattens}, m/s) at each visible
     * plant whose species leaves trails, evaluated exactly at the plant; null when no species does.
     */
    final float[][] pushX;
    final float[][] pushZ;
    /** Per buffer, whether each plant is visible. */
    final boolean[][] visible = new boolean[2][];
    /** Per buffer, the eye position (x, y, z), metres. */
    final double[][] eye = new double[2][3];
    /** Per buffer, the sub-interval boundary of a switch of the flows in its step, or -1 (SpringKinds.prepare). */
    final int[] edge = {-1, -1};
    /** Per buffer, the camera's view frustum. */
    final FrustumIntersection[] frustum = {new FrustumIntersection(), new FrustumIntersection()};
    /** Per buffer, the camera's view-projection matrix (recorded with the frame's decision). */
    final Matrix4f[] viewProjection = {new Matrix4f(), new Matrix4f()};
    /** Per buffer, the views the step follows: the camera, then the registered others. */
    final int[] viewCount = new int[2];
    final double[][] viewX = new double[2][Simulation.MAX_VIEWS];
    final double[][] viewY = new double[2][Simulation.MAX_VIEWS];
    final double[][] viewZ = new double[2][Simulation.MAX_VIEWS];
    /** Per buffer and view, the level-of-detail metric ({@link ViewLod}). */
    final double[][] scale2 = new double[2][Simulation.MAX_VIEWS];
    final double[][] fixed2 = new double[2][Simulation.MAX_VIEWS];
    /** {@link ViewLod#referenceScale} of the field's LOD lens. */
    final double reference;
    private final Matrix4f scratch = new Matrix4f();
    private final double[] metric = new double[2];
    private final WindField wind;
    private final ForceField field;
    private final Commands commands;
    private final int plants;
    /** Samples {@link #pushX}, {@link #pushZ}; null when no species leaves trails. */
    private final FlatteningPushes pushes;
    private final double fixedStep;
    private final int subIntervals;

    /**
     * Buffers for {@code plants} plants. Build time; allocates.
     *
     * @param wind         the simulation's flows, advanced by {@link #update}
     * @param field        the force field sampled
     * @param commands     frees the ids of blasts that expire
     * @param plants       number of plants
     * @param fixedStep    fixed step, seconds
     * @param subIntervals spring sub-intervals per step
     * @param lodFovY      the lens the level-of-detail distances are meant for, radians
     * @param pushes       the push that may flatten trail plants, or null when no species leaves trails
     */
    FieldSampler(WindField wind, ForceField field, Commands commands, int plants, double fixedStep,
            int subIntervals, double lodFovY, FlatteningPushes pushes) {
        this.pushes = pushes;
        pushX = pushes == null ? null : new float[2][plants];
        pushZ = pushes == null ? null : new float[2][plants];
        this.reference = ViewLod.referenceScale(lodFovY);
        this.wind = wind;
        this.field = field;
        this.commands = commands;
        this.plants = plants;
        this.fixedStep = fixedStep;
        this.subIntervals = subIntervals;
        for (int b = 0; b < 2; b++) {
            windX[b] = new float[plants];
            windZ[b] = new float[plants];
            visible[b] = new boolean[plants];
        }
    }

    /**
     * Refuses, before the step touches anything, a camera or registered view whose eye or
     * view-projection matrix is not finite (a NaN would silently stop every plant from animating).
     * Stepping thread; allocates only the message of a refusal.
     *
     * @throws IllegalArgumentException naming the camera (the step's, or the index of a registered view)
     */
    void checkViews(Camera camera, Camera[] others, int count) {
        Camera.requireFinite("camera", camera, scratch);
        for (int v = 0; v < count; v++) {
            if (!Camera.isFinite(others[v], scratch)) {
                Camera.requireFinite("view " + v + " (registered with addView)", others[v], scratch);
            }
        }
    }

    /**
     * Advances the wind one fixed step, notes where in the step the flows switched (if they did), and
     * writes the field's result for its end into buffer b.
     */
    void update(Camera camera, Camera[] others, int count, int b, boolean fieldEnabled) {
        wind.advance(fixedStep);
        edge[b] = SpringKinds.edgeBoundary(wind.lastEdge(), wind.time(), fixedStep, subIntervals);
        commands.releaseExpiredBlasts(wind.time());
        sample(camera, others, count, b, fieldEnabled);
    }

    /**
     * Advances the wind one fixed step without sampling (a step in which no view sees a plant): the
     * flows move and blasts expire; buffer b keeps its sample and reports no switch of the flows.
     */
    void advance(int b) {
        wind.advance(fixedStep);
        edge[b] = -1;
        commands.releaseExpiredBlasts(wind.time());
    }

    /**
     * Writes the field's result for the wind's current time into buffer b, for the camera and the
     * first {@code count} of {@code others} (visible: seen by any; detail: the finest any asks).
     */
    void sample(Camera camera, Camera[] others, int count, int b, boolean fieldEnabled) {
        eye[b][0] = camera.x();
        eye[b][1] = camera.y();
        eye[b][2] = camera.z();
        frustum[b].set(camera.viewProjection(viewProjection[b]), true); // normalised planes: the draw decision tests spheres
        viewCount[b] = 1 + count;
        for (int v = 0; v <= count; v++) {
            Camera c = v == 0 ? camera : others[v - 1];
            viewX[b][v] = c.x();
            viewY[b][v] = c.y();
            viewZ[b][v] = c.z();
            ViewLod.metric(c, reference, scratch, metric);
            scale2[b][v] = metric[0];
            fixed2[b][v] = metric[1];
        }
        if (fieldEnabled) {
            field.update(camera, others, count);
            field.gather(0, plants, windX[b], windZ[b], visible[b]);
        } else {
            java.util.Arrays.fill(windX[b], 0f);
            java.util.Arrays.fill(windZ[b], 0f);
            java.util.Arrays.fill(visible[b], true);
        }
        if (pushes != null) {
            pushes.sample(b, visible[b], pushX[b], pushZ[b], fieldEnabled);
        }
    }
}
