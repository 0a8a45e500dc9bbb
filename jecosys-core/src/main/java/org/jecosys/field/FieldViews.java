package org.jecosys.field;

import org.jecosys.math.Camera;
import org.jecosys.math.Require;
import org.jecosys.math.ViewLod;
import org.joml.FrustumIntersection;
import org.joml.Matrix4f;

/**
 * The views of one {@link QuadtreeForceField} update (paper §3.1.1): per view its frustum, eye
 * (metres) and level-of-detail metric ({@link ViewLod}), and the two questions the tree walk asks of
 * a node's box (its XZ rectangle over the terrain's height range): which views see it, and whether
 * its subtree collapses into it under the LOD distances ("beyond the i-th distance, i levels
 * collapse", for the view that needs the most detail).
 *
 * <p>Threads: the field's update thread. Allocation: at construction only.
 */
final class FieldViews {
    private final FrustumIntersection[] frustum = new FrustumIntersection[QuadtreeForceField.MAX_VIEWS];
    private final float[] eyeX = new float[QuadtreeForceField.MAX_VIEWS];
    private final float[] eyeY = new float[QuadtreeForceField.MAX_VIEWS];
    private final float[] eyeZ = new float[QuadtreeForceField.MAX_VIEWS];
    /** Per view its level-of-detail metric ({@link ViewLod}): scale^2 on squared distances, or a fixed one. */
    private final double[] scale2 = new double[QuadtreeForceField.MAX_VIEWS];
    private final double[] fixed2 = new double[QuadtreeForceField.MAX_VIEWS];
    private final double[] metric = new double[2];
    private final Matrix4f viewProj = new Matrix4f();
    private final double reference;
    /** The squared LOD distances, metres^2, ascending. */
    private final double[] lod2;
    /** The height range of every node's box, metres. */
    private final float minY;
    private final float maxY;
    private int views;

    FieldViews(ForceFieldDef def, float minY, float maxY) {
        this.minY = minY;
        this.maxY = maxY;
        lod2 = new double[def.lodDistances().size()];
        for (int i = 0; i < lod2.length; i++) {
            double d = def.lodDistances().get(i);
            lod2[i] = d * d;
        }
        reference = ViewLod.referenceScale(def.lodFovY());
        for (int v = 0; v < frustum.length; v++) {
            frustum[v] = new FrustumIntersection();
        }
    }

    /** Takes the camera and the first {@code count} of {@code others} (checked by the caller) as the views. */
    void set(Camera camera, Camera[] others, int count) {
        views = 1 + count;
        for (int v = 0; v < views; v++) {
            Camera c = v == 0 ? camera : Require.nonNull("view", others[v - 1]);
            frustum[v].set(c.viewProjection(viewProj), false);
            eyeX[v] = (float) c.x();
            eyeY[v] = (float) c.y();
            eyeZ[v] = (float) c.z();
            ViewLod.metric(c, reference, viewProj, metric);
            scale2[v] = metric[0];
            fixed2[v] = metric[1];
        }
    }

    /**
     * Which views see node n's box: -1 for none; otherwise a mask with bit v set when the box lies
     * wholly inside view v's frustum (so do its descendants'). A box that holds a view's eye is seen.
     */
    int cover(Quadtree t, int n) {
        int inside = 0;
        boolean seen = false;
        for (int v = 0; v < views; v++) {
            int res = frustum[v].intersectAab(t.minX[n], minY, t.minZ[n], t.maxX[n], maxY, t.maxZ[n]);
            if (res == FrustumIntersection.INSIDE) {
                inside |= 1 << v;
                seen = true;
            } else if (res == FrustumIntersection.INTERSECT || holdsEye(t, n, v)) {
                seen = true;
            }
        }
        return seen ? inside : -1;
    }

    private boolean holdsEye(Quadtree t, int n, int v) {
        return eyeX[v] >= t.minX[n] && eyeX[v] <= t.maxX[n] && eyeZ[v] >= t.minZ[n] && eyeZ[v] <= t.maxZ[n];
    }

    /** Whether node n (not a leaf) represents its subtree: it is at most as high as the levels that collapse there. */
    boolean collapses(Quadtree t, int n) {
        return lod2.length > 0 && t.height[n] <= lodLevel(t, n);
    }

    /**
     * Levels that may collapse at node n: how many LOD distances lie below the eye-to-box distance,
     * as projected size measures it ({@link ViewLod}), for the view that needs the most detail.
     */
    private int lodLevel(Quadtree t, int n) {
        double nearest = Double.POSITIVE_INFINITY;
        for (int v = 0; v < views; v++) {
            double dx = Math.max(Math.max(t.minX[n] - eyeX[v], eyeX[v] - t.maxX[n]), 0);
            double dy = Math.max(Math.max(minY - eyeY[v], eyeY[v] - maxY), 0);
            double dz = Math.max(Math.max(t.minZ[n] - eyeZ[v], eyeZ[v] - t.maxZ[n]), 0);
            nearest = Math.min(nearest, ViewLod.equivalent2(dx * dx + dy * dy + dz * dz, scale2[v], fixed2[v]));
        }
        int l = 0;
        while (l < lod2.length && nearest > lod2[l]) {
            l++;
        }
        return l;
    }
}
