package org.jecosys.render;

import org.jecosys.sim.internal.DecisionWriter;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.IntBuffer;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.DrawDecision;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.jecosys.render.plant.PlantBatches;

/**
 * The lists the renderer builds from a frame's decision ({@link DrawDecision}: culling, level of
 * detail, transition bands), instance packing and counters: pure functions, no GL context.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class PlantBatchesTest {
    private World world;

    @BeforeAll
    void build() {
        world = RenderScenes.build(RenderScenes.load("c1.xml"));
    }

    private static ViewCamera looking(double x, double y, double z, double yaw) {
        ViewCamera c = new ViewCamera();
        c.setPosition(x, y, z);
        c.setOrientation(yaw, 0);
        c.setLens(Math.toRadians(60), 16 / 9.0, 0.1, 500);
        return c;
    }

    /** The batches of a frame decided for {@code cam} with a transition band of {@code band} metres. */
    private void update(PlantBatches b, double band, ViewCamera cam) {
        DrawDecision d = DrawDecision.of(world);
        DecisionWriter.setTransition(d, band);
        b.update(DecisionWriter.decideAll(d, cam, new Frame(world.plantCount(), world.bendGeometry())));
    }

    private static int levelsHolding(PlantBatches b, int s, int plant, boolean[] at) {
        int n = 0;
        for (int l = 0; l < b.levels(s); l++) {
            int li = b.list(s, l);
            at[l] = false;
            for (int i = 0; i < b.count(li); i++) {
                if (b.plant(li, i) == plant) {
                    at[l] = true;
                    n++;
                }
            }
        }
        return n;
    }

    @Test
    void eachVisiblePlantIsInItsDistanceLevelAndInBothLevelsInsideABand() {
        PlantBatches b = new PlantBatches(world);
        ViewCamera cam = looking(0, 40, 60, 0);
        cam.setOrientation(0, -Math.atan2(40, 60));
        update(b, 1.0, cam);
        boolean[] at = new boolean[8];
        int checked = 0;
        for (int p = 0; p < world.plantCount(); p++) {
            int s = world.plantSpecies(p);
            double d = Math.sqrt(Math.pow(world.plantX(p) - cam.x(), 2) + Math.pow(world.plantY(p) - cam.y(), 2)
                    + Math.pow(world.plantZ(p) - cam.z(), 2));
            // Table 3's bands for C1's species: level 0 below 10 m, 1 below 15 m, 2 beyond; a band of 1 m
            // before each end draws the next level too
            int level = d < 10 ? 0 : d < 15 ? 1 : 2;
            boolean inBand = (d > 9 && d < 10) || (d > 14 && d < 15);
            int n = levelsHolding(b, s, p, at);
            if (n == 0) {
                continue;
            }
            checked++;
            assertTrue(at[level], "plant " + p + " at its level");
            assertEquals(inBand ? 2 : 1, n, "plant " + p + " in one list, or two inside a band");
        }
        assertEquals(world.plantCount(), checked, "all of C1 is in view from 72 m");
    }

    @Test
    void nearPlantsAreTrianglesAndFarOnesLines() {
        PlantBatches b = new PlantBatches(world);
        ViewCamera cam = looking(0, 1.7, 14, 0);
        update(b, 0.0, cam);
        assertFalse(b.lines(b.list(0, 0)));
        assertFalse(b.lines(b.list(0, 1)));
        assertTrue(b.lines(b.list(0, 2)));
        for (int s = 0; s < b.speciesCount(); s++) {
            for (int l = 0; l < b.levels(s); l++) {
                int li = b.list(s, l);
                for (int i = 0; i < b.count(li); i++) {
                    int p = b.plant(li, i);
                    double d = Math.sqrt(Math.pow(world.plantX(p) - cam.x(), 2)
                            + Math.pow(world.plantY(p) - cam.y(), 2) + Math.pow(world.plantZ(p) - cam.z(), 2));
                    int expected = d < 10 ? 0 : d < 15 ? 1 : 2;
                    assertEquals(expected, l, "plant " + p + " at " + d + " m");
                }
            }
        }
    }

    @Test
    void plantsOutsideTheFrustumAreCulled() {
        PlantBatches b = new PlantBatches(world);
        update(b, 1.0, looking(0, 1.7, 30, Math.PI)); // 18 m south of the terrain, looking south
        assertEquals(0, b.instances());
        assertEquals(0, b.triangles() + b.lineCount());
        update(b, 1.0, looking(0, 1.7, 30, 0));
        assertTrue(b.instances() > 0);
        // a plant straight behind the camera is never listed, one straight ahead is
        ViewCamera side = looking(world.plantX(0), world.plantY(0) + 1, world.plantZ(0) + 3, 0);
        update(b, 1.0, side);
        boolean[] at = new boolean[8];
        assertTrue(levelsHolding(b, world.plantSpecies(0), 0, at) > 0);
        side.setOrientation(Math.PI, 0);
        update(b, 1.0, side);
        assertEquals(0, levelsHolding(b, world.plantSpecies(0), 0, at));
    }

    @Test
    void countersAreInstancesTimesPrimitivesAndPackingFollowsTheLists() {
        PlantBatches b = new PlantBatches(world);
        update(b, 1.0, looking(0, 1.7, 14, 0));
        long tri = 0;
        long lines = 0;
        int inst = 0;
        for (int li = 0; li < b.listCount(); li++) {
            assertEquals(inst, b.instanceOffset(li));
            inst += b.count(li);
            long n = (long) b.count(li) * b.primitivesPerPlant(li);
            if (b.lines(li)) {
                lines += n;
            } else {
                tri += n;
            }
        }
        assertEquals(tri, b.triangles());
        assertEquals(lines, b.lineCount());
        assertEquals(inst, b.instances());

        IntBuffer records = IntBuffer.allocate(2 * b.maxInstances());
        assertEquals(inst, b.writeInstances(records));
        assertEquals(inst, b.writeInstances(records)); // twice: a second frame must fit too
        assertEquals(2 * inst, records.limit());
        int lo = Integer.MAX_VALUE;
        int hi = 0;
        for (int li = 0; li < b.listCount(); li++) {
            for (int i = 0; i < b.count(li); i++) {
                int p = b.plant(li, i);
                int o = 2 * (b.instanceOffset(li) + i);
                assertEquals(world.firstComponent(p), records.get(o), "first component of the listed plant");
                assertEquals(b.keepOf(li, i), records.get(o + 1));
                lo = Math.min(lo, world.firstComponent(p));
                hi = Math.max(hi, world.firstComponent(p) + world.componentsOf(p));
            }
        }
        assertEquals(lo, b.runs().start(0), "the first range starts at the lowest listed component");
        assertEquals(hi, b.runs().end(b.runs().count() - 1), "the last ends after the highest");
    }

    @Test
    void plantsDrawnWholeComeFirstInEachListThenThoseInABandEachInPlantOrder() {
        PlantBatches b = new PlantBatches(world);
        ViewCamera cam = looking(0, 1.7, 14, 0);
        DrawDecision d = DrawDecision.of(world);
        DecisionWriter.setTransition(d, 2.0);
        Frame f = DecisionWriter.decideAll(d, cam, new Frame(world.plantCount(), world.bendGeometry()));
        b.update(f);
        int banded = 0;
        int whole = 0;
        for (int li = 0; li < b.listCount(); li++) {
            int s = b.speciesOf(li);
            int level = li - b.list(s, 0);
            int[] expectWhole = new int[world.plantCount()];
            int[] expectBanded = new int[world.plantCount()];
            int nw = 0;
            int nb = 0;
            for (int p = 0; p < world.plantCount(); p++) {
                int l = f.drawLevel(p);
                if (world.plantSpecies(p) != s || l < 0 || (l != level && l + 1 != level)) {
                    continue;
                }
                int keep = f.drawKeep(p);
                if (l + 1 == level && keep >>> 16 == 0) {
                    continue;
                }
                int window = l == level ? keep & 0xFFFF : keep >>> 16;
                if (window == PlantBatches.WHOLE) {
                    expectWhole[nw++] = p;
                } else {
                    expectBanded[nb++] = p;
                }
            }
            assertEquals(nw, b.whole(li), "list " + li + ": plants drawn whole");
            assertEquals(nw + nb, b.count(li), "list " + li + ": every plant once");
            for (int i = 0; i < nw; i++) {
                assertEquals(expectWhole[i], b.plant(li, i), "list " + li + " entry " + i);
                assertEquals(PlantBatches.WHOLE, b.keepOf(li, i));
            }
            for (int i = 0; i < nb; i++) {
                assertEquals(expectBanded[i], b.plant(li, nw + i), "list " + li + " entry " + (nw + i));
                assertTrue(b.keepOf(li, nw + i) != PlantBatches.WHOLE);
            }
            whole += nw;
            banded += nb;
        }
        assertTrue(banded > 4 && whole > 4, "both kinds present: " + whole + " whole, " + banded + " banded");
        // a second frame with no band: every plant whole again, the lists refilled from scratch
        DecisionWriter.setTransition(d, 0);
        b.update(DecisionWriter.decideAll(d, cam, new Frame(world.plantCount(), world.bendGeometry())));
        for (int li = 0; li < b.listCount(); li++) {
            assertEquals(b.count(li), b.whole(li), "no band, list " + li);
        }
    }
}
