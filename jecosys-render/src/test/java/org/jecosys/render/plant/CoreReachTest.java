package org.jecosys.render.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.jecosys.plant.LodMesh;
import org.jecosys.plant.Primitive;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.RenderScenes;
import org.jecosys.render.TestFrames;
import org.jecosys.sim.Frame;
import org.jecosys.sim.DrawDecision;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * {@link CoreReach}'s distances are safe and close: beyond a list's distance every vertex of its mesh is
 * one that plant.vert leaves out of the core's pass (its test run here in single precision, as the
 * shader runs it, on a 5 mm grid out to 300 m beyond), and the distance lies within 10% (plus half a
 * metre) of the farthest grid point where some vertex keeps its core. Flower species never lose their
 * core; the meadow's grasses do, at their far level, within the view's first 40 m (80 m where the
 * thinning widens them up to 4 times). For a perspective view with and without the thinning's
 * widening, and an orthographic one.
 */
class CoreReachTest {
    private static final float MIN_PIXELS = 1.75f;
    /** A pixel's size per metre at 540 rows and a 60 degree view. */
    private static final float PIXEL_Y = (float) (2 * Math.tan(Math.toRadians(30)) / 540);

    @Test
    void beyondAListsDistanceTheShaderLeavesOutEveryVertex() {
        World world = RenderScenes.build(RenderScenes.load("meadow.xml"));
        List<SpeciesModel> models = world.plants().species();
        PlantBatches batches = new PlantBatches(world);
        CoreReach reach = new CoreReach(models, batches);
        float[][] cases = {{0, PIXEL_Y, 4, 16, 0.15f}, {0, PIXEL_Y, 0, 1, 1}, {0.004f, 0, 0, 1, 1}};
        List<String> far = new ArrayList<>();
        for (float[] c : cases) {
            reach.update(MIN_PIXELS, c[0], c[1], c[2], c[3], c[4]);
            for (int s = 0; s < models.size(); s++) {
                SpeciesModel m = models.get(s);
                boolean flowers = PlantMeshes.hasFlowerParts(m);
                double radius = DrawDecision.boundingRadius(m);
                for (int l = 0; l < m.levels(); l++) {
                    int li = batches.list(s, l);
                    double beyond = Math.sqrt(reach.beyondSq(li));
                    if (flowers || m.mesh(l).primitive() == Primitive.LINES) {
                        assertEquals(Double.POSITIVE_INFINITY, beyond, m.def().id() + " level " + l + " keeps a core");
                        continue;
                    }
                    float[][] parts = parts(m, m.mesh(l));
                    double from = beyond - radius;
                    double kept = lastKept(parts, c, c[1] > 0 ? from + 300 : 1000);
                    String what = m.def().id() + " level " + l + " case " + java.util.Arrays.toString(c);
                    assertTrue(Double.isInfinite(from) || kept < from, what + ": a core at " + kept + " m, beyond "
                            + from + " m");
                    if (c[1] > 0) {
                        assertTrue(from <= Math.max(kept, 0) * 1.1 + 0.5, what + ": " + from + " m, the last core at " + kept + " m");
                    }
                    if (c[1] > 0 && l == m.levels() - 1) {
                        far.add(m.def().id() + " " + String.format(java.util.Locale.ROOT, "%.1f", from));
                        assertTrue(from < (c[4] < 1 ? 80 : 40), what + ": coreless only beyond " + from + " m");
                    }
                }
            }
        }
        System.out.println("[look] coreless beyond (m, far level; thinning from 4 m, then none): " + far);
        assertEquals(6, far.size(), "the meadow's three grasses lose their core far away");
    }

    /**
     * {@link PlantBatches#setCoreless}: the same plants in every list as without it, the whole plants
     * beyond the list's distance first (in plant order), then the other whole plants (in plant order),
     * then those in a band; off again, the lists are as before.
     */
    @Test
    void theBatchesListTheCorelessWholePlantsFirst() {
        World world = RenderScenes.build(RenderScenes.load("meadow.xml"));
        ViewCamera cam = new ViewCamera();
        cam.setPosition(0, world.terrain().heightfield().height(0, 0) + 1.7, 0);
        cam.setOrientation(0, -0.2);
        cam.setLens(Math.toRadians(60), 16 / 9.0, 0.05, 500);
        Frame frame = TestFrames.rest(world, cam);
        PlantBatches plain = new PlantBatches(world);
        plain.update(frame);
        PlantBatches split = new PlantBatches(world);
        CoreReach reach = new CoreReach(world.plants().species(), split);
        reach.update(MIN_PIXELS, 0, PIXEL_Y, 0, 1, 1);
        split.setCoreless(reach, (float) cam.x(), (float) cam.z());
        split.update(frame);
        long coreless = 0;
        for (int li = 0; li < split.listCount(); li++) {
            assertEquals(plain.count(li), split.count(li), "list " + li);
            assertEquals(plain.whole(li), split.whole(li), "list " + li + " whole");
            java.util.List<Integer> none = new ArrayList<>();
            java.util.List<Integer> core = new ArrayList<>();
            for (int i = 0; i < plain.whole(li); i++) {
                int p = plain.plant(li, i);
                float dx = world.plantX(p) - (float) cam.x();
                float dz = world.plantZ(p) - (float) cam.z();
                (dx * dx + dz * dz >= reach.beyondSq(li) ? none : core).add(p);
            }
            assertEquals(none.size(), split.coreless(li), "list " + li + " coreless");
            none.addAll(core);
            for (int i = 0; i < split.count(li); i++) {
                int want = i < none.size() ? none.get(i) : plain.plant(li, i);
                assertEquals(want, split.plant(li, i), "list " + li + " entry " + i);
                assertEquals(i < none.size() ? PlantBatches.WHOLE : plain.keepOf(li, i), split.keepOf(li, i), "its window");
            }
            coreless += split.coreless(li);
        }
        assertTrue(coreless > 1000, "coreless plants listed apart: " + coreless);
        split.setCoreless(null, 0, 0);
        split.update(frame);
        for (int li = 0; li < split.listCount(); li++) {
            assertEquals(0, split.coreless(li));
            for (int i = 0; i < split.count(li); i++) {
                assertEquals(plain.plant(li, i), split.plant(li, i), "off again: list " + li + " entry " + i);
            }
        }
    }

    /** Per distinct blade or stem part of the mesh: its widest half width and reach, as uploaded. */
    private static float[][] parts(SpeciesModel m, LodMesh mesh) {
        Set<Integer> slots = new LinkedHashSet<>();
        for (int v = 0; v < mesh.vertexCount(); v++) {
            slots.add(mesh.vertexSlot(v));
        }
        float[][] p = new float[slots.size()][];
        int i = 0;
        for (int slot : slots) {
            p[i++] = new float[] {m.slotWidestHalfWidth(slot), PlantMeshes.reach(m.slotPoseTable(slot, 0))};
        }
        return p;
    }

    /** The farthest grid distance (5 mm steps from 0) at which some part keeps a core; -1 if none. */
    private static double lastKept(float[][] parts, float[] c, double to) {
        double last = -1;
        for (int k = 0; k * 0.005 <= to; k++) {
            float d = (float) (k * 0.005);
            for (float[] part : parts) {
                if (!leftOut(part[0], part[1], d, c)) {
                    last = d;
                }
            }
        }
        return last;
    }

    /** plant.vert's test, in single precision. */
    private static boolean leftOut(float half, float shapeReach, float d, float[] c) {
        float reach = 1.5f * shapeReach;
        float least = 0.5f * MIN_PIXELS * (c[0] + Math.max(d - reach, 0f) * c[1]);
        return half * widen(d + reach, c) < 0.996f * least;
    }

    private static float widen(float d, float[] c) {
        if (c[4] >= 1f) {
            return 1f;
        }
        float t = Math.min(1f, Math.max(0f, (d - c[2]) / (c[3] - c[2])));
        float kept = 1f - (1f - c[4]) * t * t * (3f - 2f * t);
        return Math.min(1f / Math.max(kept, 0.05f), 4f);
    }
}
