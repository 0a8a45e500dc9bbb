package org.jecosys.render;

import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.sim.internal.FrameWriter;
import org.jecosys.sim.internal.DecisionWriter;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.lang.management.ManagementFactory;
import java.nio.FloatBuffer;
import java.util.List;
import java.util.SplittableRandom;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.scene.SceneDef;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.DrawDecision;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.joml.Vector3f;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.plant.ComponentLooks;
import org.jecosys.render.plant.PlantBatches;
import org.jecosys.render.plant.PlantRenderer;

/**
 * The per-frame component pass, which runs on the GPU ({@code plant_resolve.glsl}) on one of the two
 * {@link ResolvePath}s, each tested by a subclass: every record the renderer reads back is checked
 * against an independent derivation from the world, the pose tables and the frame (C1, whose flowers
 * carry a head and petals on the tip of their stalk); drawing allocates nothing on the render thread.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
abstract class ComponentRecordsTest {
    private static final int F = PlantRenderer.RECORD_FLOATS;
    GlContext gl;
    private GlFramebuffer fb;
    PlantRenderer renderer;
    private DrawDecision decision;
    World world;
    private List<SpeciesModel> models;
    private int[][][] poseTexel;
    private PlantBatches batches;
    Frame frame;
    FloatBuffer rec;
    ViewCamera cam;

    /** {@return the path under test} */
    abstract ResolvePath path();

    @BeforeAll
    void build() {
        world = RenderScenes.build(leavesUpTheStalk(RenderScenes.load("c1.xml")));
        models = world.plants().species();
        poseTexel = new int[models.size()][][];
        PlantRenderer.poseTexelLayout(models, poseTexel); // the pose buffer's layout as the renderer uploads it
        // a frame with every component bent somewhere, some pose coordinates outside the table on purpose
        frame = new Frame(world.plantCount(), world.bendGeometry());
        SplittableRandom rnd = new SplittableRandom(7);
        for (int c = 0; c < world.componentCount(); c++) {
            float coord = (float) rnd.nextDouble(-1, 17); // C1's tables have 16 poses
            FrameWriter.set(frame, c, coord, (float) rnd.nextDouble(-Math.PI, Math.PI));
        }
        cam = new ViewCamera();
        cam.setPosition(0, 6, 16);
        cam.setOrientation(0, -Math.atan2(6, 16));
        cam.setLens(Math.toRadians(60), 16 / 9.0, 0.1, 500);
        gl = GlContext.headless(DebugOutput.ON);
        fb = new GlFramebuffer(gl.tracker(), 320, 180);
        fb.bind();
        assumeTrue(path().supported(gl.capabilities()), path() + " needs a newer GL than " + gl.describe());
        renderer = new PlantRenderer(gl, world, path());
        renderer.setWholePlantsBelow(0); // the dithered band draws on this single-sampled target too
        assertEquals(path(), renderer.path());
        decision = DrawDecision.of(world);
        DecisionWriter.decideAll(decision, cam, frame);
        draw();
        batches = renderer.batches();
        rec = org.lwjgl.system.MemoryUtil.memAllocFloat(F * batches.components());
        renderer.readRecords(rec);
    }

    /**
     * C1 with flower C's two leaves carried half-way up its stalk ({@code attachAt} 0.5: point 4 of 8)
     * instead of standing on the ground, so children sit on a parent's tip (petals, heads) and on a point
     * on the way up.
     */
    static SceneDef leavesUpTheStalk(SceneDef c1) {
        List<SpeciesDef> species = new java.util.ArrayList<>();
        for (SpeciesDef s : c1.species()) {
            List<ComponentDef> cs = new java.util.ArrayList<>();
            for (ComponentDef c : s.components()) {
                cs.add(s.id().equals("flowerC") && c.id().equals("leaf")
                        ? c.toBuilder().attachTo("stalk").attachAt(0.5).build() : c);
            }
            species.add(new SpeciesDef(s.id(), s.name(), s.poses(), s.maxBend(), cs, s.lods(), s.variation(), s.trail()));
        }
        return new SceneDef(c1.version(), c1.name(), c1.seed(), c1.terrain(), species, c1.distributions(),
                c1.placements(), c1.flows(), c1.field(), c1.camera(), c1.animation(), c1.render(), c1.world());
    }

    /** The light of these pictures: the sun high and to the side, haze from 25 m to 160 m. */
    private final Lighting light = new Lighting();

    {
        light.setSunDirection(0.3f, 0.9f, 0.3f);
        light.setSky(0.6f, 0.7f, 0.9f);
        light.setFog(25f, 160f);
    }

    void draw() {
        draw(renderer);
    }

    void draw(PlantRenderer r) {
        r.setLighting(light);
        r.draw(frame, cam, 180);
    }

    @AfterAll
    void close() {
        org.lwjgl.system.MemoryUtil.memFree((java.nio.Buffer) rec);
        if (renderer != null) {
            renderer.close();
        }
        if (gl != null) {
            fb.close();
            gl.debug().check("the component records test");
            gl.close();
        }
    }

    /** Record index of slot {@code slot} of the {@code i}-th plant of list {@code li}. */
    private int record(int li, int i, int slot) {
        int s = world.plantSpecies(batches.plant(li, i));
        return F * (batches.componentOffset(li) + i * models.get(s).slotCount() + slot);
    }

    @Test
    void oneRecordPerSlotOfEveryListedPlantInListOrder() {
        int components = 0;
        for (int li = 0; li < batches.listCount(); li++) {
            assertEquals(components, batches.componentOffset(li), "list " + li);
            for (int i = 0; i < batches.count(li); i++) {
                components += models.get(world.plantSpecies(batches.plant(li, i))).slotCount();
            }
        }
        assertTrue(batches.instances() > 20, "the view holds a good part of C1");
        assertEquals(batches.components(), components);
        assertEquals(F * components, rec.limit());
        long states = 0;
        int drawnComponents = 0;
        for (int p = 0; p < world.plantCount(); p++) {
            drawnComponents += frame.drawLevel(p) >= 0 ? world.componentsOf(p) : 0;
        }
        for (int i = 0; i < batches.runs().count(); i++) {
            assertTrue(batches.runs().end(i) > batches.runs().start(i));
            assertTrue(i == 0 || batches.runs().start(i) - batches.runs().end(i - 1) > PlantBatches.GAP, "ranges merged");
            states += batches.runs().end(i) - batches.runs().start(i);
        }
        assertTrue(states >= drawnComponents, "every drawn component's state is uploaded");
        assertTrue(states <= drawnComponents + (long) PlantBatches.GAP * batches.runs().count(), "and little else");
        assertEquals(8L * batches.instances() + Frame.RENDER_STATE_BYTES * states, renderer.uploadedBytes(),
                "8 bytes per drawn plant and level, 8 per component of the uploaded ranges");
    }

    @Test
    void poseTexelAndWeightGiveBackTheClampedPoseCoordinate() {
        forEachRecord((li, i, slot, r) -> {
            int p = batches.plant(li, i);
            SpeciesModel m = models.get(world.plantSpecies(p));
            int v = world.plantVariant(p);
            PoseTable pt = m.slotPoseTable(slot, v);
            int first = poseTexel[world.plantSpecies(p)][m.slotComponent(slot)][m.slotVariant(slot, v)];
            int stride = 3 * pt.points();
            float texel = rec.get(r + 4);
            assertEquals(Math.rint(texel), texel, "a whole texel");
            int k = ((int) texel - first) / stride;
            assertEquals(first + k * stride, (int) texel, "texel of point 0 of a pose");
            assertTrue(k >= 0 && k <= pt.poses() - 2, "pose k and k + 1 exist: k = " + k);
            float w = rec.get(r + 5);
            assertTrue(w >= 0 && w <= 1, "weight " + w);
            float coord = frame.poseCoord(world.firstComponent(p) + slot);
            float clamped = Math.max(0, Math.min(pt.poses() - 1, coord));
            assertEquals(clamped, k + w, 1e-5, "k + w for coordinate " + coord);
        });
    }

    @Test
    void azimuthIsCarriedAsItsCosineAndSine() {
        forEachRecord((li, i, slot, r) -> {
            int c = world.firstComponent(batches.plant(li, i)) + slot;
            float cos = rec.get(r + 3);
            float sin = rec.get(r + 6);
            assertEquals(1, cos * cos + sin * sin, 1e-6);
            assertEquals(0, Math.IEEEremainder(Math.atan2(sin, cos) - frame.bendAzimuth(c), 2 * Math.PI), 1e-5);
        });
    }

    @Test
    void rootsStandOnTheirPlantAndChildrenOnTheirParentsAnimatedTip() {
        int children = 0;
        int midway = 0;
        Vector3f a = new Vector3f();
        Vector3f b = new Vector3f();
        for (int li = 0; li < batches.listCount(); li++) {
            for (int i = 0; i < batches.count(li); i++) {
                int p = batches.plant(li, i);
                SpeciesModel m = models.get(world.plantSpecies(p));
                double rest = world.plantRestAzimuth(p);
                for (int slot = 0; slot < m.slotCount(); slot++) {
                    int r = record(li, i, slot);
                    int parent = m.slotParent(slot);
                    double ex;
                    double ey;
                    double ez;
                    if (parent < 0) {
                        // the plant's base plus its ground offset turned by the plant's rest azimuth
                        double ox = m.slotBaseX(slot);
                        double oz = m.slotBaseZ(slot);
                        ex = world.plantX(p) + ox * Math.cos(rest) - oz * Math.sin(rest);
                        ey = world.plantY(p);
                        ez = world.plantZ(p) + ox * Math.sin(rest) + oz * Math.cos(rest);
                    } else {
                        // the parent's record: its base, plus its last point at (k, w) turned by its azimuth
                        children++;
                        midway += m.slotAttachPoint(slot) < m.slotPoseTable(parent, 0).points() - 1 ? 1 : 0;
                        int q = record(li, i, parent);
                        PoseTable pt = m.slotPoseTable(parent, world.plantVariant(p));
                        int first = poseTexel[world.plantSpecies(p)][m.slotComponent(parent)]
                                [m.slotVariant(parent, world.plantVariant(p))];
                        int k = ((int) rec.get(q + 4) - first) / (3 * pt.points());
                        float w = rec.get(q + 5);
                        int at = m.slotAttachPoint(slot);
                        pt.position(k, at, a).lerp(pt.position(k + 1, at, b), w);
                        float c = rec.get(q + 3);
                        float sn = rec.get(q + 6);
                        ex = rec.get(q) + a.x * c - a.z * sn;
                        ey = rec.get(q + 1) + a.y;
                        ez = rec.get(q + 2) + a.x * sn + a.z * c;
                    }
                    String where = "plant " + p + " slot " + slot;
                    assertEquals(ex, rec.get(r), 2e-5, where + " x");
                    assertEquals(ey, rec.get(r + 1), 2e-5, where + " y");
                    assertEquals(ez, rec.get(r + 2), 2e-5, where + " z");
                }
            }
        }
        assertTrue(children > 50, "C1's flowers put heads and petals on their stalks: " + children);
        assertTrue(midway > 10, "flower C's leaves sit half-way up its stalks: " + midway);
    }

    @Test
    void theDitherWindowsOfALevelsPlantTileTheThresholdsWithoutOverlap() {
        // at every distance, level l keeps [lo_l, hi_l) with hi_0 = 255, lo_last = 0 and lo_l = hi_(l+1):
        // every fragment of a plant inside a band is drawn by exactly one of the two levels
        for (int s = 0; s < batches.speciesCount(); s++) {
            int levels = batches.levels(s);
            double far = decision.edge(s, levels - 2) + 2;
            for (double d = 0; d <= far; d += 0.01) {
                int prevLo = -1;
                for (int l = 0; l < levels; l++) {
                    int keep = decision.keep(s, l, d);
                    int lo = keep / 256;
                    int hi = keep % 256;
                    String at = "species " + s + " level " + l + " at " + d + " m";
                    assertTrue(lo <= hi, at + ": [" + lo + ", " + hi + ")");
                    assertEquals(l == 0 ? 255 : prevLo, hi, at);
                    prevLo = lo;
                }
                assertEquals(0, prevLo, "the last level keeps from 0");
            }
        }
        // and the records carry the window of the plant's own distance (the whole number; the fraction
        // is 0.99 x the component's bend, for the wind's sheen)
        forEachRecord((li, i, slot, r) -> {
            assertEquals(batches.keepOf(li, i), Math.floor(rec.get(r + 7)));
            double bend = rec.get(r + 7) - Math.floor(rec.get(r + 7));
            assertTrue(bend >= 0 && bend <= 0.99 + 1e-3, "bend fraction " + bend);
        });
    }

    @Test
    void drawingAllocatesNothingOnTheRenderThread() {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long self = Thread.currentThread().getId();
        int zeroWindows = 0;
        for (int window = 0; window < 40 && zeroWindows < 2; window++) {
            long before = mx.getThreadAllocatedBytes(self);
            for (int k = 0; k < 20; k++) {
                draw();
            }
            long bytes = mx.getThreadAllocatedBytes(self) - before;
            zeroWindows = bytes == 0 ? zeroWindows + 1 : 0;
        }
        assertEquals(2, zeroWindows, "two consecutive windows of 20 frames with no allocation after warm-up");
        FloatBuffer again = org.lwjgl.system.MemoryUtil.memAllocFloat(rec.capacity());
        try {
            renderer.readRecords(again);
            assertEquals(rec, again, "the same records every frame");
        } finally {
            org.lwjgl.system.MemoryUtil.memFree((java.nio.Buffer) again);
        }
    }

    @Test
    void theColourVariationIsSeededPerPlantAndOffWhenUnset() {
        // unset: no hue turn, brightness 1, no dryness; a line level's texel 2 is what its vertices share
        forEachRecord((li, i, slot, r) -> {
            if (batches.lines(li)) {
                return;
            }
            assertEquals(1f, rec.get(r + 8), 0f);
            assertEquals(0f, rec.get(r + 9), 0f);
            assertEquals(1f, rec.get(r + 10), 0f);
            assertEquals(0f, rec.get(r + 11), 0f);
        });
        try {
            applyLook(10f, 0.15f, 5f, 1f, 42);
            double[] sum = new double[4];
            double[] sq = new double[4];
            int[] n = new int[1];
            java.util.Set<Float> dryness = new java.util.HashSet<>();
            forEachRecord((li, i, slot, r) -> {
                if (batches.lines(li)) {
                    return;
                }
                float c = rec.get(r + 8);
                float sn = rec.get(r + 9);
                assertEquals(1.0, c * c + sn * sn, 1e-5, "a hue turn is a rotation");
                double hue = Math.toDegrees(Math.atan2(sn, c));
                float value = rec.get(r + 10);
                float dry = rec.get(r + 11);
                assertTrue(value >= 0.3f && value <= 1.8f, "brightness " + value);
                assertTrue(dry >= 0f && dry <= 1f, "dryness " + dry);
                dryness.add(dry);
                sum[0] += hue;
                sq[0] += hue * hue;
                sum[1] += value;
                sq[1] += value * value;
                n[0]++;
            });
            double hueSd = Math.sqrt(sq[0] / n[0] - Math.pow(sum[0] / n[0], 2));
            double valueSd = Math.sqrt(sq[1] / n[0] - Math.pow(sum[1] / n[0], 2));
            // plant spread s.d. 1 plus a component spread of 0.35 (hue) or 0.3 (brightness); the near
            // levels hold a few dozen plants, so the sample s.d. is within about a third of it
            double hueWant = 10 * Math.sqrt(1 + 0.35 * 0.35);
            double valueWant = 0.15 * Math.sqrt(1 + 0.3 * 0.3);
            assertEquals(hueWant, hueSd, hueWant / 3, "hue s.d., degrees, over " + n[0] + " components");
            assertEquals(valueWant, valueSd, valueWant / 3, "brightness s.d., over " + n[0] + " components");
            assertTrue(dryness.size() > 20, "the patches vary over the scene: " + dryness.size() + " values");
            FloatBuffer first = org.lwjgl.system.MemoryUtil.memAllocFloat(rec.capacity());
            try {
                renderer.readRecords(first);
                renderer.setPatches(5f, 1f, 43);
                draw();
                renderer.readRecords(rec);
                assertNotEquals(first, rec, "another seed, another variation");
                renderer.setPatches(5f, 1f, 42);
                draw();
                renderer.readRecords(rec);
                assertEquals(first, rec, "the same seed, the same variation");
            } finally {
                org.lwjgl.system.MemoryUtil.memFree((java.nio.Buffer) first);
            }
        } finally {
            applyLook(0f, 0f, 20f, 0f, 0);
        }
    }

    @Test
    void theResolvePassReadsTheLooksBakedOnTheCpuComponentByComponent() {
        try {
            applyLook(12f, 0.2f, 4f, 0.8f, 7);
            // the same function, by an independent path: the public patch noise at each root's base
            RenderSettings patches = RenderSettings.standalone();
            patches.setPatches(4f, 0.8f, 7);
            int[] checked = new int[1];
            forEachRecord((li, i, slot, r) -> {
                if (batches.lines(li)) {
                    return;
                }
                int p = batches.plant(li, i);
                int first = world.firstComponent(p);
                int ph = ComponentLooks.hash(first * 0x9e3779b9 ^ 7);
                int ch = ComponentLooks.hash(ph ^ (slot + 1) * 0x85ebca6b);
                double hue = Math.toRadians(12) * (ComponentLooks.spread(ph, 0) + 0.35 * ComponentLooks.spread(ch, 0));
                assertEquals(Math.cos(hue), rec.get(r + 8), 1e-5, "cos of the hue turn");
                assertEquals(Math.sin(hue), rec.get(r + 9), 1e-5, "sin of the hue turn");
                double value = 1 + 0.2 * (ComponentLooks.spread(ph, 10) + 0.3 * ComponentLooks.spread(ch, 10));
                assertEquals(Math.max(0.3, Math.min(1.8, value)), rec.get(r + 10), 1e-4, "brightness");
                SpeciesModel m = models.get(world.plantSpecies(p));
                if (m.slotParent(slot) < 0) {
                    double rest = world.plantRestAzimuth(p);
                    double x = world.plantX(p) + m.slotBaseX(slot) * Math.cos(rest) - m.slotBaseZ(slot) * Math.sin(rest);
                    double z = world.plantZ(p) + m.slotBaseX(slot) * Math.sin(rest) + m.slotBaseZ(slot) * Math.cos(rest);
                    assertEquals(0.8 * patches.patchLevel((float) x, (float) z), rec.get(r + 11), 2e-3,
                            "dryness of the patch under component " + (first + slot));
                    checked[0]++;
                }
            });
            assertTrue(checked[0] > 50, "root components checked: " + checked[0]);
        } finally {
            applyLook(0f, 0f, 20f, 0f, 0);
        }
    }

    @Test
    void everyListedPlantIsDrawnOnceAtEachOfItsLevelsInTwoDrawsAtMostPerList() {
        double transition = decision.transition();
        try {
            // a wide band: plants in it are listed at two levels, and go through the dithered draws
            DecisionWriter.setTransition(decision, 3.0);
            DecisionWriter.decideAll(decision, cam, frame);
            draw();
            long listed = 0;
            int calls = 0;
            int banded = 0;
            for (int li = 0; li < batches.listCount(); li++) {
                int whole = batches.whole(li);
                int inBand = batches.count(li) - whole;
                listed += batches.count(li);
                calls += (whole > 0 ? 1 : 0) + (inBand > 0 ? 1 : 0);
                banded += inBand;
            }
            assertTrue(banded > 4, "plants in a band: " + banded);
            assertEquals(batches.instances(), listed);
            assertEquals(listed, renderer.instancesDrawn(), "every listed plant drawn once per list");
            assertEquals(calls, renderer.drawCalls(), "one draw for the whole plants, one for those in a band");
        } finally {
            DecisionWriter.setTransition(decision, transition);
            DecisionWriter.decideAll(decision, cam, frame);
            draw();
            renderer.readRecords(rec);
        }
    }

    @Test
    void aLineLevelsRecordCarriesItsLitColourItsWideningOneOverItsDistanceAndThePixelThere() {
        double[] thinning = {decision.thinStart(), decision.thinEnd(), decision.thinMinFraction()};
        try {
            checkFarRecords(); // no thinning: no widening
            // thinning from 5 m, down to half the plants at 20 m: the kept far blades are widened by 1 / kept
            DecisionWriter.setThinning(decision, 5, 20, 0.5);
            DecisionWriter.decideAll(decision, cam, frame);
            draw();
            renderer.readRecords(rec);
            checkFarRecords();
        } finally {
            DecisionWriter.setThinning(decision, thinning[0], thinning[1], thinning[2]);
            DecisionWriter.decideAll(decision, cam, frame);
            draw();
            renderer.readRecords(rec);
        }
    }

    private void checkFarRecords() {
        // the resolve pass's pixel scale, as PlantRenderer.drawNear sets it for a 180-pixel viewport
        double px = cam.viewHeightAtEye() / 180;
        double py = cam.viewHeightPerMetre() / 180;
        int[] checked = new int[2];
        forEachRecord((li, i, slot, r) -> {
            if (!batches.lines(li)) {
                return;
            }
            String at = "list " + li + " plant " + batches.plant(li, i) + " slot " + slot;
            int a = (int) rec.get(r + 8);
            int b = (int) rec.get(r + 9);
            assertEquals(a, rec.get(r + 8), 0f, at + ": a whole number");
            assertEquals(b, rec.get(r + 9), 0f, at + ": a whole number");
            assertTrue(a >= 0 && a < 1 << 24 && b >= 0 && b < 1 << 24, at + ": 24 bits");
            float red = (a & 4095) / 4095f;
            float green = (a >> 12) / 4095f;
            float blue = (b & 4095) / 4095f;
            assertTrue(red + green + blue > 0.02f, at + ": lit, not black: " + red + ", " + green + ", " + blue);
            double d = Math.sqrt(Math.pow(cam.x() - rec.get(r), 2) + Math.pow(cam.y() - rec.get(r + 1), 2)
                    + Math.pow(cam.z() - rec.get(r + 2), 2));
            double kept = decision.thinKept(d);
            double widen = decision.thinMinFraction() >= 1 ? 1 : Math.min(1 / Math.max(kept, 0.05), 4);
            assertEquals(widen, 1 + 3 * (b >> 12) / 4095.0, 1e-3, at + ": widening at " + d + " m");
            checked[1] += widen > 1.05 ? 1 : 0;
            assertEquals(1 / d, rec.get(r + 10), 1e-5 / d, at + ": 1 / the distance of the component's base");
            assertEquals(px + d * py, rec.get(r + 11), 1e-5 * (px + d * py), at + ": a pixel's height there");
            checked[0]++;
        });
        assertTrue(checked[0] > 100, "line-level components checked: " + checked[0]);
        assertTrue(decision.thinMinFraction() >= 1 || checked[1] > 50, "widened components: " + checked[1]);
    }

    /** Sets every species' hue and brightness spread and the patches, draws, and reads the records back. */
    private void applyLook(float hueDeg, float value, float patchScale, float patchStrength, int seed) {
        for (int s = 0; s < models.size(); s++) {
            renderer.setVariation(s, hueDeg, value, 0f);
        }
        renderer.setPatches(patchScale, patchStrength, seed);
        draw();
        renderer.readRecords(rec);
    }

    private interface RecordCheck {
        void check(int list, int i, int slot, int at);
    }

    private void forEachRecord(RecordCheck check) {
        for (int li = 0; li < batches.listCount(); li++) {
            for (int i = 0; i < batches.count(li); i++) {
                int slots = models.get(world.plantSpecies(batches.plant(li, i))).slotCount();
                for (int slot = 0; slot < slots; slot++) {
                    check.check(li, i, slot, record(li, i, slot));
                }
            }
        }
    }
}
