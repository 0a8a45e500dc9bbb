package org.jecosys.render.plant;

import java.util.List;
import org.jecosys.plant.LodMesh;
import org.jecosys.plant.Primitive;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.DrawDecision;

/**
 * How far from the eye a species' level still has a core: the horizontal distance beyond which a plant
 * at that level draws nothing in the core's pass of a multisampled target ({@link CoverageDraws}), so
 * that {@link PlantBatches} can list such plants apart and the pass can leave them out whole rather
 * than send every vertex of theirs outside the view one at a time.
 *
 * <p>The vertex shader ({@code plant.vert}) leaves a vertex out of the core's pass when its part is a
 * blade or a stem (not a flower part, not a glTF mesh) and {@code w * widen(d + r) < 0.996 * least(d)},
 * with {@code w} the part's widest half width and {@code r} 1.5 times its reach (both per slot, as
 * {@link PlantMeshes#uploadMesh} writes them), {@code d} the eye's distance to the component's base,
 * {@code widen} the thinning's widening ({@code plant_far.glsl}, nondecreasing, at most 4) and
 * {@code least(d) = minPixels / 2 * (pixelX + max(d - r, 0) * pixelY)}. Here that test is run on
 * intervals of distance from far to near, each side bounded the safe way (the widening at the interval's
 * far end, the least width at its near end, with a 2% margin), down to the first interval where some
 * part may keep a core. A plant counts as coreless when its base is horizontally farther than that
 * distance plus its bounding radius ({@link DrawDecision#boundingRadius}), which holds every component
 * base of it in any pose: then every vertex of it is one the shader leaves out, and the picture is the
 * same. A level with a flower part or a glTF mesh always has a core.
 *
 * <p>Render thread; built with the renderer (allocates), {@link #update} allocates nothing.
 */
final class CoreReach {
    /** The shader's cut with a 2% margin for its single-precision arithmetic. */
    private static final double CUT = 0.996 * 0.98;
    /** Interval steps from far to near: each interval's near end is this share of its far end. */
    private static final double STEP = 0.98;
    /** Per list: the distinct (widest half width, 1.5 x reach) pairs of its mesh's blade and stem slots. */
    private final double[][] half;
    private final double[][] reach;
    /** Per list: whether it always has a core (flower parts, glTF meshes, lines). */
    private final boolean[] always;
    /** Per list: its species' bounding radius, metres. */
    private final double[] radius;
    /** Per list: the squared horizontal distance beyond which its plants are coreless (+inf: never). */
    private final float[] beyondSq;
    private float lastMinPixels = Float.NaN;
    private float lastX = Float.NaN;
    private float lastY = Float.NaN;
    private double lastStart = Double.NaN;
    private double lastEnd = Double.NaN;
    private double lastMin = Double.NaN;

    /** Reads every list's mesh. Build time; allocates. */
    CoreReach(List<SpeciesModel> models, PlantBatches batches) {
        int lists = batches.listCount();
        half = new double[lists][];
        reach = new double[lists][];
        always = new boolean[lists];
        radius = new double[lists];
        beyondSq = new float[lists];
        java.util.Arrays.fill(beyondSq, Float.POSITIVE_INFINITY);
        for (int s = 0; s < models.size(); s++) {
            SpeciesModel m = models.get(s);
            double r = DrawDecision.boundingRadius(m);
            for (int l = 0; l < m.levels(); l++) {
                int li = batches.list(s, l);
                radius[li] = r;
                read(m, m.mesh(l), li);
            }
        }
    }

    private void read(SpeciesModel m, LodMesh mesh, int li) {
        boolean[] seen = new boolean[m.slotCount()];
        int pairs = 0;
        boolean core = mesh.primitive() == Primitive.LINES;
        for (int v = 0; v < mesh.vertexCount() && !core; v++) {
            int slot = mesh.vertexSlot(v);
            int look = m.slotComponent(mesh.vertexLookSlot(v));
            core = mesh.vertexFromFile(v) || PlantMeshes.kind(m.component(look).def()) > PlantMeshes.STEM;
            if (!seen[slot]) {
                seen[slot] = true;
                pairs++;
            }
        }
        always[li] = core;
        half[li] = new double[core ? 0 : pairs];
        reach[li] = new double[core ? 0 : pairs];
        for (int slot = 0, i = 0; slot < seen.length && !core; slot++) {
            if (seen[slot]) {
                half[li][i] = m.slotWidestHalfWidth(slot);
                reach[li][i++] = 1.5 * PlantMeshes.reach(m.slotPoseTable(slot, 0));
            }
        }
    }

    /**
     * Works out every list's distance for the values the draw programs get this frame (recomputed only
     * when one changed). No allocation.
     *
     * @param minPixels least width of thin parts, pixels ({@code uMinPixels}); 0: no part is left out
     * @param pixelX    a pixel's size at the eye, metres ({@code uPixelScale.x})
     * @param pixelY    a pixel's size per metre of distance ({@code uPixelScale.y})
     * @param thinStart the frame's thinning start, metres ({@code uThin.x})
     * @param thinEnd   the frame's thinning end, metres
     * @param thinMin   the share of plants kept beyond the end
     */
    void update(float minPixels, float pixelX, float pixelY, double thinStart, double thinEnd, double thinMin) {
        if (minPixels == lastMinPixels && pixelX == lastX && pixelY == lastY && thinStart == lastStart
                && thinEnd == lastEnd && thinMin == lastMin) {
            return;
        }
        lastMinPixels = minPixels;
        lastX = pixelX;
        lastY = pixelY;
        lastStart = thinStart;
        lastEnd = thinEnd;
        lastMin = thinMin;
        for (int li = 0; li < beyondSq.length; li++) {
            double d = always[li] || !(minPixels > 0) ? Double.POSITIVE_INFINITY : coreless(li);
            double t = d + radius[li];
            beyondSq[li] = (float) (t * t);
        }
    }

    /** {@return the squared horizontal distance beyond which plants of a list are coreless (+inf: never)} */
    float beyondSq(int list) {
        return beyondSq[list];
    }

    /** The least distance of a component's base beyond which no part of the list has a core. */
    private double coreless(int li) {
        double widest = widen(Double.POSITIVE_INFINITY);
        double px = lastX;
        double py = lastY;
        double halfMin = 0.5 * lastMinPixels;
        double far = 0;
        for (int i = 0; i < half[li].length; i++) {
            if (!(py > 0)) {
                // an orthographic view: the least width is the same everywhere
                if (!(half[li][i] * widest < CUT * halfMin * px)) {
                    return Double.POSITIVE_INFINITY;
                }
                continue;
            }
            far = Math.max(far, reach[li][i] + Math.max(0, (half[li][i] * widest / (CUT * halfMin) - px) / py));
        }
        if (!(py > 0)) {
            return 0;
        }
        double b = far * 1.001 + 1e-3;
        while (b > 0) {
            double a = b * STEP - 0.005;
            a = a < 0.01 ? 0 : a;
            for (int i = 0; i < half[li].length; i++) {
                double r = reach[li][i];
                if (!(half[li][i] * widen(b + r) < CUT * halfMin * (px + Math.max(a - r, 0) * py))) {
                    return b;
                }
            }
            b = a;
        }
        return 0;
    }

    /** The thinning's widening at distance x, as plant_far.glsl's thinWiden (nondecreasing in x). */
    private double widen(double x) {
        if (lastMin >= 1) {
            return 1;
        }
        double keptFar = lastMin;
        if (!(lastEnd > lastStart)) {
            return Math.min(1 / Math.max(keptFar, 0.05), 4);
        }
        double t = Math.min(1, Math.max(0, (x - lastStart) / (lastEnd - lastStart)));
        double kept = 1 - (1 - keptFar) * t * t * (3 - 2 * t);
        return Math.min(1 / Math.max(kept, 0.05), 4);
    }
}
