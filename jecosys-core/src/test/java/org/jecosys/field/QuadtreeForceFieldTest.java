package org.jecosys.field;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jecosys.math.Rng;
import org.jecosys.math.ViewCamera;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindField;
import org.joml.Matrix4f;
import org.joml.Vector2d;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

class QuadtreeForceFieldTest {
    static final double SIZE = 200;

    static QuadtreeForceField randomField(ForceFieldDef def, WindField wind, int n, long seed) {
        Rng rng = new Rng(seed);
        float[] xs = new float[n];
        float[] zs = new float[n];
        for (int i = 0; i < n; i++) {
            xs[i] = (float) rng.nextDouble(0, SIZE);
            zs[i] = (float) rng.nextDouble(0, SIZE);
        }
        return QuadtreeForceField.build(def, 0, 0, SIZE, SIZE, 0, 1, wind, xs, zs);
    }

    static WindField someWind() {
        return WindField.of(List.of(FlowDef.uniform("u", 3, 0.4), FlowDef.point("v", FlowKind.VORTEX, 80, 120, 30),
                FlowDef.point("s", FlowKind.SOURCE, 150, 40, 20)));
    }

    /** A box is certainly outside when all 8 corners lie beyond the same clip plane. */
    static boolean fullyOutside(Matrix4f vp, float x0, float y0, float z0, float x1, float y1, float z1) {
        int[] outside = new int[6];
        Vector4f v = new Vector4f();
        for (int c = 0; c < 8; c++) {
            vp.transform(v.set((c & 1) == 0 ? x0 : x1, (c & 2) == 0 ? y0 : y1, (c & 4) == 0 ? z0 : z1, 1));
            if (v.x < -v.w) outside[0]++;
            if (v.x > v.w) outside[1]++;
            if (v.y < -v.w) outside[2]++;
            if (v.y > v.w) outside[3]++;
            if (v.z < -v.w) outside[4]++;
            if (v.z > v.w) outside[5]++;
        }
        for (int o : outside) {
            if (o == 8) {
                return true;
            }
        }
        return false;
    }

    @Test
    void nodesFullyOutsideAreNeverVisibleAndTheCameraNodeAlwaysIs() {
        QuadtreeForceField f = randomField(ForceFieldDef.defaults(), someWind(), 20_000, 5);
        FieldDebugView dbg = f.debugView();
        Quadtree t = f.tree();
        Rng rng = new Rng(99);
        ViewCamera cam = new ViewCamera();
        cam.setLens(Math.toRadians(60), 16.0 / 9, 0.1, 120);
        Matrix4f vp = new Matrix4f();
        int hidden = 0;
        for (int k = 0; k < 40; k++) {
            double ex = rng.nextDouble(0, SIZE);
            double ez = rng.nextDouble(0, SIZE);
            cam.setPosition(ex, rng.nextDouble(1.5, 30), ez);
            cam.setOrientation(rng.nextDouble(-Math.PI, Math.PI), rng.nextDouble(-1.2, 1.2));
            f.update(cam);
            cam.viewProjection(vp);
            for (int n = 0; n < dbg.nodeCount(); n++) {
                boolean holdsEye = ex >= dbg.minX(n) && ex <= dbg.maxX(n) && ez >= dbg.minZ(n) && ez <= dbg.maxZ(n);
                if (holdsEye) {
                    assertTrue(dbg.visible(n), "the node holding the camera is visible");
                } else if (fullyOutside(vp, dbg.minX(n), 0, dbg.minZ(n), dbg.maxX(n), 1, dbg.maxZ(n))) {
                    assertFalse(dbg.visible(n), "node " + n + " fully outside the frustum");
                    hidden++;
                }
                if (dbg.visible(n) && t.parent(n) >= 0) {
                    assertTrue(dbg.visible(t.parent(n)), "a visible node's parent is visible");
                }
            }
        }
        assertTrue(hidden > 1000, "culling happened: " + hidden);
    }

    @Test
    void withoutLodDistancesEffectiveNodesAreTheVisibleLeaves() {
        ForceFieldDef def = ForceFieldDef.builder().maxDepth(10).lodDistances().build();
        QuadtreeForceField f = randomField(def, someWind(), 30_000, 8);
        ViewCamera cam = new ViewCamera();
        cam.setPosition(100, 2, 190);
        cam.setOrientation(0.2, -0.1);
        f.update(cam);
        FieldCounters c = f.counters();
        FieldDebugView dbg = f.debugView();
        int visibleLeaves = 0;
        int nonEmpty = 0;
        for (int n = 0; n < dbg.nodeCount(); n++) {
            if (dbg.visible(n) && dbg.isLeaf(n)) {
                visibleLeaves++;
                assertTrue(dbg.effective(n));
                assertEquals(0, dbg.lodLevel(n));
                if (f.tree().plantsIn(n) > 0) {
                    nonEmpty++;
                }
            } else if (dbg.visible(n)) {
                assertFalse(dbg.effective(n));
            }
        }
        assertEquals(visibleLeaves, c.visibleLeaves());
        assertEquals(visibleLeaves, c.effectiveNodes());
        assertEquals(nonEmpty, c.flowEvaluations());
        assertTrue(visibleLeaves > 0 && visibleLeaves < c.leaves(), c.toString());
        assertEquals(f.tree().nodeCount(), c.nodes());
    }

    /** A full tree: a 64 x 64 grid, one plant per leaf at depth 6, seen whole from above. */
    static QuadtreeForceField gridField(List<Double> lod, WindField wind) {
        int g = 64;
        float[] xs = new float[g * g];
        float[] zs = new float[g * g];
        for (int i = 0; i < g * g; i++) {
            xs[i] = (i % g) + 0.5f;
            zs[i] = (i / g) + 0.5f;
        }
        return QuadtreeForceField.build(ForceFieldDef.builder().maxObjectsPerNode(1).maxDepth(6).lodDistances(lod)
                .build(), 0, 0, g, g, 0, 0, wind, xs, zs);
    }

    static ViewCamera above() {
        ViewCamera camera = new ViewCamera();
        camera.setPosition(32, 200, 32);
        camera.setOrientation(0, -Math.PI / 2);
        camera.setLens(1.2, 1, 1, 1000);
        return camera;
    }

    @Test
    void eachCollapsedSubtreeOfHeightHSavesFourToTheHMinusOneEvaluations() {
        WindField wind = someWind();
        QuadtreeForceField full = gridField(List.of(), wind);
        full.update(above());
        assertEquals(4096, full.counters().visibleLeaves());
        assertEquals(4096, full.counters().flowEvaluations());
        for (int h = 1; h <= 3; h++) {
            Double[] d = new Double[h];
            for (int i = 0; i < h; i++) {
                d[i] = 1.0 + i;
            }
            QuadtreeForceField lod = gridField(List.of(d), wind);
            lod.update(above());
            FieldCounters c = lod.counters();
            int subtrees = 4096 >> (2 * h);
            assertEquals(subtrees, c.effectiveNodes());
            assertEquals(subtrees, c.flowEvaluations());
            assertEquals(4096, c.visibleLeaves());
            int saved = full.counters().flowEvaluations() - c.flowEvaluations();
            assertEquals(subtrees * ((1 << (2 * h)) - 1), saved, "4^h - 1 per subtree, h=" + h);
            FieldDebugView dbg = lod.debugView();
            for (int n = 0; n < dbg.nodeCount(); n++) {
                if (dbg.effective(n)) {
                    assertEquals(h, dbg.lodLevel(n));
                    assertEquals(6 - h, dbg.depth(n));
                }
            }
        }
    }

    @Test
    void countersMatchTheCollapsedSubtreesForAViewerInsideTheScene() {
        ForceFieldDef def = ForceFieldDef.builder().maxObjectsPerNode(4).maxDepth(10).lodDistances(10.0, 25.0, 50.0)
                .build();
        QuadtreeForceField f = randomField(def, someWind(), 50_000, 21);
        ViewCamera camera = new ViewCamera();
        camera.setPosition(60, 1.7, 150);
        camera.setOrientation(0.5, 0);
        camera.setLens(1.0, 1.6, 0.1, 400);
        f.update(camera);
        FieldCounters c = f.counters();
        FieldDebugView dbg = f.debugView();
        int[] leavesPerRep = new int[dbg.nodeCount()];
        int visibleLeaves = 0;
        for (int n = 0; n < dbg.nodeCount(); n++) {
            if (dbg.visible(n) && dbg.isLeaf(n)) {
                leavesPerRep[dbg.representative(n)]++;
                visibleLeaves++;
                assertTrue(dbg.lodLevel(n) <= 3);
            }
        }
        int saved = 0;
        int effective = 0;
        for (int n = 0; n < dbg.nodeCount(); n++) {
            if (leavesPerRep[n] > 0) {
                effective++;
                saved += leavesPerRep[n] - 1;
                assertTrue(dbg.effective(n));
            }
        }
        assertEquals(visibleLeaves, c.visibleLeaves());
        assertEquals(effective, c.effectiveNodes());
        assertEquals(visibleLeaves - c.effectiveNodes(), saved);
        assertTrue(saved > 0, c.toString());
    }

    @Test
    void plantsGetTheWindOfTheirEffectiveNodeAtItsCentreOfGravityRefinedByItsGradient() {
        WindField wind = someWind();
        wind.advance(0.5);
        ForceFieldDef def = ForceFieldDef.builder().maxObjectsPerNode(6).maxDepth(10).lodDistances(20.0, 60.0).build();
        QuadtreeForceField f = randomField(def, wind, 20_000, 2);
        ViewCamera camera = new ViewCamera();
        camera.setPosition(20, 3, 20);
        camera.setOrientation(Math.PI * 0.75, -0.05);
        f.update(camera);
        Vector2d got = new Vector2d();
        Vector2d want = new Vector2d();
        Quadtree t = f.tree();
        int visible = 0;
        float[] wx = new float[f.plantCount()];
        float[] wz = new float[f.plantCount()];
        boolean[] vis = new boolean[f.plantCount()];
        f.gather(0, f.plantCount(), wx, wz, vis);
        double plantError = 0;
        double nodeError = 0;
        for (int p = 0; p < f.plantCount(); p++) {
            int e = f.effectiveNode(p);
            assertEquals(e >= 0, f.isVisible(p));
            assertEquals(vis[p], f.isVisible(p));
            if (e < 0) {
                assertEquals(0, f.wind(p, got).length(), 0);
                continue;
            }
            visible++;
            for (int a = f.leafNode(p); a != e; a = t.parent(a)) {
                assertTrue(a >= 0, "the effective node is an ancestor of the leaf");
            }
            f.wind(p, got);
            assertEquals((float) got.x, wx[p], "gather gives the plant's wind bit for bit");
            assertEquals((float) got.y, wz[p]);
            wind.velocity(t.centroidX(e), t.centroidZ(e), want);
            assertEquals(want.x, f.debugView().windX(e), 1e-5, "the node's wind is the flows' at its centroid");
            assertEquals(want.y, f.debugView().windZ(e), 1e-5);
            wind.velocity(t.plantX(p), t.plantZ(p), want);
            plantError += Math.hypot(want.x - got.x, want.y - got.y);
            nodeError += Math.hypot(want.x - f.debugView().windX(e), want.y - f.debugView().windZ(e));
            assertEquals((float) got.x, wx[p], 0);
            assertEquals((float) got.y, wz[p], 0);
            assertEquals(t.depth(f.leafNode(p)), f.depth(p));
        }
        assertTrue(visible > 100 && visible < f.plantCount(), "visible " + visible);
        // 0.58 before the gradient was weighed by how well it predicts the neighbours (leave-one-out); 0.72 since:
        // nodes whose neighbours cannot check a straight-line fit give it up, to be no worse than their own wind
        assertTrue(plantError < 0.75 * nodeError, "inside a node the gradient brings a plant's wind closer to the "
                + "flow's at the plant: mean error " + plantError / visible + " vs " + nodeError / visible);
    }

    @Test
    void invisiblePlantsKeepTheirLastWind() {
        QuadtreeForceField f = randomField(ForceFieldDef.defaults(), someWind(), 5000, 4);
        ViewCamera cam = new ViewCamera();
        cam.setPosition(100, 2, 100);
        cam.setOrientation(0, 0);
        int n = f.plantCount();
        float[] wx = new float[n];
        float[] wz = new float[n];
        boolean[] vis = new boolean[n];
        f.update(cam);
        f.gather(0, n, wx, wz, vis);
        float[] before = wx.clone();
        cam.setOrientation(Math.PI, 0);
        f.update(cam);
        java.util.Arrays.fill(wx, 0, n, Float.NaN);
        System.arraycopy(before, 0, wx, 0, n);
        f.gather(0, n, wx, wz, vis);
        int kept = 0;
        for (int p = 0; p < n; p++) {
            if (!vis[p]) {
                assertEquals(before[p], wx[p], 0);
                kept++;
            }
        }
        assertTrue(kept > 0);
    }

    @Test
    void aDisabledFieldEvaluatesNothingAndGivesZeroWind() {
        ForceFieldDef def = ForceFieldDef.builder().enabled(false).lodDistances(15.0).build();
        QuadtreeForceField f = randomField(def, someWind(), 5000, 4);
        ViewCamera camera = new ViewCamera();
        camera.setPosition(100, 2, 100);
        f.update(camera);
        assertEquals(0, f.counters().flowEvaluations());
        assertTrue(f.counters().effectiveNodes() > 0);
        Vector2d v = new Vector2d();
        for (int p = 0; p < f.plantCount(); p++) {
            assertEquals(0, f.wind(p, v).length(), 0);
        }
    }

    @Test
    void plantsAddedAndMovedAfterUpdatesAreServed() {
        QuadtreeForceField f = randomField(ForceFieldDef.defaults(), someWind(), 100, 4);
        ViewCamera cam = new ViewCamera();
        cam.setPosition(100, 2, 100);
        cam.setOrientation(0, -0.2);
        f.update(cam);
        Rng rng = new Rng(3);
        for (int i = 0; i < 20_000; i++) {
            f.addPlant(rng.nextDouble(0, SIZE), rng.nextDouble(0, SIZE));
        }
        f.movePlant(0, 100, 95);
        assertFalse(f.isVisible(f.plantCount() - 1), "not visible before the next update");
        assertEquals(-1, f.debugView().representative(f.debugView().nodeCount() - 1));
        f.update(cam);
        QuadtreeTest.checkInvariants(f.tree());
        assertTrue(f.isVisible(0));
        assertTrue(f.counters().nodes() > 1000);
    }

    @Test
    void reusingTheEdgeNeighboursWhileTheCutStaysChangesNoWindBitForBit() {
        WindField wind = someWind();
        wind.add(org.jecosys.wind.FlowDef.builder("g", org.jecosys.wind.FlowKind.GUST).strength(4).direction(0.5)
                .build());
        QuadtreeForceField reuse = randomField(ForceFieldDef.defaults(), wind, 20_000, 11);
        QuadtreeForceField fresh = randomField(ForceFieldDef.defaults(), wind, 20_000, 11);
        int plants = reuse.plantCount();
        float[][] w = new float[4][plants + 1];
        boolean[][] vis = new boolean[2][plants + 1];
        ViewCamera cam = new ViewCamera();
        cam.setLens(Math.toRadians(60), 16.0 / 9, 0.1, 300);
        for (int k = 0; k < 120; k++) {
            // still stretches (the same cut) and moves (a new cut), the wind blowing on
            int stretch = k / 10;
            cam.setPosition(40 + 7 * stretch + (k % 10 < 5 ? 0 : 0.01 * k), 2, 150 - 5 * stretch);
            cam.setOrientation(0.2 * stretch, -0.15);
            if (k == 60) {
                reuse.addPlant(100, 100);
                fresh.addPlant(100, 100);
                plants++;
            }
            wind.advance(1 / 60.0);
            reuse.update(cam);
            fresh.forgetNeighbours();
            fresh.update(cam);
            reuse.gather(0, plants, w[0], w[1], vis[0]);
            fresh.gather(0, plants, w[2], w[3], vis[1]);
            assertArrayEquals(w[2], w[0], "wind X, step " + k);
            assertArrayEquals(w[3], w[1], "wind Z, step " + k);
            assertArrayEquals(vis[1], vis[0], "visible, step " + k);
        }
        long reused = reuse.neighbourReuses();
        assertTrue(reused > 40 && reused < 120, "updates that reused the neighbours of the one before: " + reused);
        assertEquals(0, fresh.neighbourReuses());
    }
}
