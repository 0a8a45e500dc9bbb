package org.jecosys.field;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jecosys.math.Rng;
import org.jecosys.math.ViewCamera;
import org.jecosys.wind.AbstractWindSource;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindField;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;

/**
 * Inside an effective node the wind varies smoothly, from the node's gradient (fitted to its
 * neighbours' winds, no further flow evaluation), plus a per-plant flutter for the eddies a
 * turbulent gust declares; the flows are still evaluated once per effective node holding plants.
 */
class FieldInterpolationTest {
    static final double SIZE = 100;

    /** A wind linear in space, counting its evaluations: u = (2 + 0.05 x, -1 + 0.03 x - 0.04 z). */
    static final class Sheared extends AbstractWindSource {
        long evaluations;

        Sheared() {
            super("sheared");
        }

        @Override
        protected void flow(double x, double z, double time, Vector2d dest) {
            evaluations++;
            dest.set(2 + 0.05 * x, -1 + 0.03 * x - 0.04 * z);
        }
    }

    static QuadtreeForceField field(WindField wind, int n, long seed) {
        Rng rng = new Rng(seed);
        float[] xs = new float[n];
        float[] zs = new float[n];
        for (int i = 0; i < n; i++) {
            xs[i] = (float) rng.nextDouble(0, SIZE);
            zs[i] = (float) rng.nextDouble(0, SIZE);
        }
        return QuadtreeForceField.build(ForceFieldDef.builder().maxDepth(10).lodDistances(15.0, 40.0).build(), 0, 0,
                SIZE, SIZE, 0, 1,
                wind, xs, zs);
    }

    static ViewCamera camera() {
        ViewCamera camera = new ViewCamera();
        camera.setPosition(10, 2, 10);
        camera.setOrientation(Math.PI * 0.75, -0.1);
        return camera;
    }

    @Test
    void aLinearWindIsExactAtEveryPlantWithOneEvaluationPerEffectiveNode() {
        Sheared flow = new Sheared();
        WindField wind = new WindField();
        wind.add(flow);
        QuadtreeForceField f = field(wind, 20_000, 1);
        f.update(camera());
        assertEquals(0, wind.eddySpeed(), 0);
        FieldDebugView view = f.debugView();
        int holding = 0;
        for (int node = 0; node < view.nodeCount(); node++) {
            holding += view.effective(node) && f.tree().plantsIn(node) > 0 ? 1 : 0;
        }
        assertEquals(holding, f.counters().flowEvaluations(), "one evaluation per effective node holding plants");
        assertEquals(f.counters().flowEvaluations(), flow.evaluations, "and none for the gradients");
        Vector2d got = new Vector2d();
        Vector2d want = new Vector2d();
        double error = 0;
        double nodeError = 0;
        int visible = 0;
        int varied = 0;
        for (int p = 0; p < f.plantCount(); p++) {
            int e = f.effectiveNode(p);
            if (e < 0) {
                continue;
            }
            visible++;
            f.wind(p, got);
            flow.velocity(f.tree().plantX(p), f.tree().plantZ(p), 0, want);
            error += got.distance(want);
            nodeError += want.distance(view.windX(e), view.windZ(e));
            varied += got.distance(view.windX(e), view.windZ(e)) > 1e-3 ? 1 : 0;
        }
        assertTrue(visible > 1000, "visible " + visible);
        assertTrue(error < 0.05 * nodeError, "mean error " + error / visible + " m/s, one value per node "
                + nodeError / visible);
        assertTrue(varied > visible / 2, "plants of one node differ: " + varied + " of " + visible);
    }

    @Test
    void aTurbulentGustMakesNeighboursFlutterAndAUniformWindDoesNot() {
        WindField calm = WindField.of(List.of(FlowDef.uniform("u", 4, 0.5)));
        QuadtreeForceField uniform = field(calm, 5000, 2);
        uniform.update(camera());
        Vector2d v = new Vector2d();
        for (int p = 0; p < uniform.plantCount(); p++) {
            if (uniform.isVisible(p)) {
                uniform.wind(p, v);
                assertEquals(4 * Math.cos(0.5), v.x, 1e-5, "no gradient, no flutter");
            }
        }
        // gusts and eddies 100 km wide: uniform over the field, so only the flutter tells plants apart
        FlowDef gust = FlowDef.builder("g", FlowKind.GUST).strength(4).turbulence(0.5).noiseScale(100_000).build();
        WindField a = WindField.of(List.of(gust));
        WindField b = WindField.of(List.of(gust));
        assertEquals(2, a.eddySpeed(), 1e-12);
        QuadtreeForceField fa = field(a, 5000, 3);
        QuadtreeForceField fb = field(b, 5000, 3);
        int n = fa.plantCount();
        float[] ax = new float[n];
        float[] az = new float[n];
        float[] bx = new float[n];
        float[] bz = new float[n];
        float[] before = new float[n];
        boolean[] vis = new boolean[n];
        int differ = 0;
        double jump = 0;
        for (int step = 0; step < 30; step++) {
            a.advance(1.0 / 60);
            b.advance(1.0 / 60);
            fa.update(camera());
            fb.update(camera());
            fa.gather(0, n, ax, az, vis);
            fb.gather(0, n, bx, bz, vis);
            for (int p = 0; p < n; p++) {
                assertEquals(ax[p], bx[p], 0, "seeded: the same at every run");
                assertTrue(Float.isFinite(ax[p]) && Float.isFinite(az[p]));
                if (vis[p] && step > 0) {
                    jump = Math.max(jump, Math.abs(ax[p] - before[p]));
                }
                before[p] = ax[p];
            }
        }
        int pairs = 0;
        int[] firstOf = new int[fa.debugView().nodeCount()];
        java.util.Arrays.fill(firstOf, -1);
        for (int p = 0; p < n; p++) {
            int e = fa.effectiveNode(p);
            if (!vis[p] || e < 0) {
                continue;
            }
            int q = firstOf[e];
            if (q < 0) {
                firstOf[e] = p;
                continue;
            }
            pairs++;
            differ += Math.abs(ax[p] - ax[q]) > 0.05 ? 1 : 0;
        }
        assertTrue(pairs > 100 && differ > pairs / 2, "plants of one node flutter apart: " + differ + " of " + pairs);
        assertTrue(jump > 0 && jump < 0.5, "and smoothly in time: at most " + jump + " m/s per 1/60 s");
    }
}
