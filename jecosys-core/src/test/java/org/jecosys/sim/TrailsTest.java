package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.anim.AnimationView;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Trails (issue 26): a walker crossing C1's meadow flattens the grass it passes, which stays down
 * for the recovery time its species sets and then stands up again; the same for any number of
 * workers; with recovery 0, or while nothing is pushed past the threshold, the plants move bit for
 * bit as without trails.
 *
 * <p>The walker is a source flow of 30 m^2/s walking a scripted path along z = 0 at 1.4 m/s, in C1's
 * breeze and gusts. Three runs share the wind: A with the walker and the grass's recovery, B with the
 * walker and no recovery (the elastic spring alone), C with the recovery and no walker. The walker's
 * mark on plant p is {@code E(t) = D_A(t) - D_C(t)} (its first leaf's deviation, metres); its push is
 * E at the step where |E| peaks. (B's push reaches the springs through the field's nodes, which in
 * C1's sparse meadow span metres: it comes later and smaller than the exact push that flattens.)
 */
class TrailsTest {
    static final double RECOVERY = 1.5;
    static final double STEP = 1.0 / 60;
    /** 28 m at 1.4 m/s, then five recovery times and a margin. */
    static final int STEPS = (int) Math.ceil((28 / 1.4 + 5 * RECOVERY + 1) / STEP);

    @TempDir
    Path dir;
    /** The Z of the walker's path: where most grass tufts of C1 stand within 0.5 m of it. */
    private double pathZ = Double.NaN;

    /**
     * C1's fixture with, optionally, the grass's recovery and the walker; the field at its finest
     * everywhere (level-of-detail distances of 40 and 60 m), so the walker's own push reaches the
     * springs through the field wherever it walks, unless {@code fixtureField}.
     */
    SceneDef scene(String name, double recovery, boolean walker) throws Exception {
        return scene(name, recovery, walker, false);
    }

    SceneDef scene(String name, double recovery, boolean walker, boolean fixtureField) throws Exception {
        String text = Files.readString(Path.of("jecosys-core/src/test/resources/org/jecosys/sim/c1-fixture.xml"));
        String field = "<field maxObjectsPerNode=\"4\" maxDepth=\"6\" lodDistances=\"10 15\"/>";
        assertTrue(text.contains(field));
        if (!fixtureField) {
            text = text.replace(field, "<field maxObjectsPerNode=\"4\" maxDepth=\"6\" lodDistances=\"40 60\"/>");
        }
        String grass = "<species id=\"grassA\" name=\"grass tuft A\" maxBend=\"68.8\">";
        assertTrue(text.contains(grass));
        if (recovery > 0) {
            text = text.replace(grass, grass.replace(">", " recovery=\"" + recovery + "\">"));
        }
        if (walker) {
            String wind = "<wind>";
            assertTrue(text.contains(wind));
            String z = String.format(java.util.Locale.ROOT, "%.3f", pathZ());
            text = text.replace(wind, wind + "\n    <source id=\"walker\" strength=\"30\" x=\"-14\" z=\"" + z + "\" "
                    + "influenceRadius=\"1.5\"><path speed=\"1.4\" loop=\"false\"><waypoint x=\"-14\" z=\"" + z + "\"/>"
                    + "<waypoint x=\"14\" z=\"" + z + "\"/></path></source>");
        }
        Path file = dir.resolve(name + ".xml");
        Files.writeString(file, text);
        return SceneFiles.parse(file);
    }

    /** Grass tufts of C1 (the walker does not move them) within 0.5 m of the line z = pathZ, |x| < 11. */
    static int[] nearPath(World world, double z) {
        int grass = world.plants().species().stream().map(m -> m.def().id()).toList().indexOf("grassA");
        return java.util.stream.IntStream.range(0, world.plantCount()).filter(p -> world.plantSpecies(p) == grass
                && Math.abs(world.plantZ(p) - z) <= 0.5 && Math.abs(world.plantX(p)) < 11).toArray();
    }

    /** The path's Z, on a 0.05 m grid over [-8, 8]: the line with the most grass tufts near it. */
    double pathZ() throws Exception {
        if (Double.isNaN(pathZ)) {
            World world = SimFixtures.world();
            int most = -1;
            for (int i = -160; i <= 160; i++) {
                int n = nearPath(world, i * 0.05).length;
                if (n > most) {
                    most = n;
                    pathZ = i * 0.05;
                }
            }
        }
        return pathZ;
    }

    static Simulation simulation(SceneDef def, int workers) throws Exception {
        World world = World.build(def.simulationDef(), Path.of("scenes"), 2, Progress.NONE);
        return Simulation.of(world, def.simulationDef(), workers, SimFixtures.CHUNK);
    }

    /** A camera high over the middle that sees the whole path. */
    static ViewCamera overhead() {
        ViewCamera camera = new ViewCamera();
        camera.setPosition(0, 9, 7);
        camera.setOrientation(0, -0.9);
        camera.setLens(Math.toRadians(100), 1.6, 0.1, 200);
        return camera;
    }

    /**
     * Per step and plant, the first component's deviation (X, Z); one run. {@code mostFlat[0]} receives
     * the largest flattening of any plant at any step.
     */
    static float[][] run(Simulation sim, int[] plants, float[] mostFlat) {
        float[][] d = new float[STEPS][plants.length * 2];
        ViewCamera cam = overhead();
        try (sim) {
            for (int i = 0; i < STEPS; i++) {
                sim.stepFixed(cam);
                AnimationView s = sim.inspect().state();
                for (int j = 0; j < plants.length; j++) {
                    int c = s.firstComponent(plants[j]);
                    d[i][2 * j] = s.deviationX(c);
                    d[i][2 * j + 1] = s.deviationZ(c);
                }
                for (int p = 0; p < s.plantCount(); p++) {
                    mostFlat[0] = Math.max(mostFlat[0], s.flattening(p));
                }
            }
        }
        return d;
    }

    @Test
    void aWalkerLeavesATrailThatStaysForTheRecoveryTimeAndFillsInAfterFive() throws Exception {
        SceneDef a = scene("a", RECOVERY, true);
        SceneDef b = scene("b", 0, true);
        SceneDef c = scene("c", RECOVERY, false);
        World world = World.build(a.simulationDef(), Path.of("scenes"), 2, Progress.NONE);
        int[] near = nearPath(world, pathZ());
        assertTrue(near.length >= 3, "grass tufts within 0.5 m of the path: " + near.length);
        float[] flatA = {0};
        float[] flatC = {0};
        float[][] dA = run(simulation(a, 2), near, flatA);
        float[][] dB = run(simulation(b, 2), near, new float[1]);
        float[][] dC = run(simulation(c, 2), near, flatC);
        assertTrue(flatA[0] > 0.5f, "the walker flattened plants, most by " + flatA[0]);
        assertEquals(0f, flatC[0], "C1's wind alone flattens no plant");
        int r = (int) Math.round(RECOVERY / STEP);
        StringBuilder report = new StringBuilder();
        double worstHeld = Double.POSITIVE_INFINITY;
        double worstBack = 0;
        double elasticMost = 0;
        for (int j = 0; j < near.length; j++) {
            int peak = 0;
            double best = -1;
            for (int i = 0; i < STEPS; i++) {
                double ex = dA[i][2 * j] - dC[i][2 * j];
                double ez = dA[i][2 * j + 1] - dC[i][2 * j + 1];
                if (ex * ex + ez * ez > best) {
                    best = ex * ex + ez * ez;
                    peak = i;
                }
            }
            double px = dA[peak][2 * j] - dC[peak][2 * j];
            double pz = dA[peak][2 * j + 1] - dC[peak][2 * j + 1];
            double push = Math.hypot(px, pz);
            assertTrue(peak + 5 * r < STEPS, "plant " + near[j] + " peaks too late to watch it recover");
            double held = Double.POSITIVE_INFINITY;
            for (int i = peak; i <= peak + r; i++) {
                double along = ((dA[i][2 * j] - dC[i][2 * j]) * px + (dA[i][2 * j + 1] - dC[i][2 * j + 1]) * pz) / push;
                held = Math.min(held, along / push);
            }
            int five = peak + 5 * r;
            double back = Math.hypot(dA[five][2 * j] - dC[five][2 * j], dA[five][2 * j + 1] - dC[five][2 * j + 1]) / push;
            // the elastic spring alone (B, reported): the walker's largest push there through the field's
            // nodes, and what is left five recovery times after it
            double pushB = 0;
            int peakB = 0;
            for (int i = 0; i < STEPS; i++) {
                double e = Math.hypot(dB[i][2 * j] - dC[i][2 * j], dB[i][2 * j + 1] - dC[i][2 * j + 1]);
                if (e > pushB) {
                    pushB = e;
                    peakB = i;
                }
            }
            int later = Math.min(STEPS - 1, peakB + 5 * r);
            double elastic = Math.hypot(dB[later][2 * j] - dC[later][2 * j], dB[later][2 * j + 1] - dC[later][2 * j + 1])
                    / pushB;
            worstHeld = Math.min(worstHeld, held);
            worstBack = Math.max(worstBack, back);
            elasticMost = Math.max(elasticMost, elastic);
            report.append(String.format("%n  plant %d at (%.2f, %.2f): push %.3f m, held >= %.2f over 1 recovery time,"
                            + " %.3f left after 5; without recovery: push %.3f m, %.3f left after 5", near[j],
                    world.plantX(near[j]), world.plantZ(near[j]), push, held, back, pushB, elastic));
        }
        System.out.println("[trails] " + near.length + " tufts within 0.5 m of the walker's path:" + report);
        assertTrue(worstHeld >= 0.5, "bent at least half way toward the push for one recovery time:" + report);
        assertTrue(worstBack <= 0.05, "back within 5% after five recovery times:" + report);
        assertTrue(elasticMost <= 0.05, "without recovery the walker's push springs back too:" + report);
    }

    @Test
    void flatteningAndRecoveryAllocateNothingAfterWarmUp() throws Exception {
        var mx = SimulationAllocationTest.MX;
        mx.setThreadAllocatedMemoryEnabled(true);
        try (Simulation sim = simulation(scene("a", RECOVERY, true), 2)) {
            ViewCamera cam = overhead();
            for (int i = 0; i < 420; i++) { // the walker reaches the first tufts near its path after about 4 s
                sim.stepFixed(cam);
            }
            long self = Thread.currentThread().getId();
            long[] workers = sim.inspect().workerThreadIds();
            SimulationAllocationTest.total(self, workers);
            long[] windows = new long[6];
            int zeroRun = 0;
            int w = 0;
            float flat = 0;
            for (; w < windows.length && zeroRun < 2; w++) {
                long before = SimulationAllocationTest.total(self, workers);
                for (int k = 0; k < 120; k++) {
                    sim.stepFixed(cam);
                }
                windows[w] = SimulationAllocationTest.total(self, workers) - before;
                zeroRun = windows[w] == 0 ? zeroRun + 1 : 0;
                for (int p = 0; p < sim.plantCount(); p++) {
                    flat = Math.max(flat, sim.inspect().state().flattening(p));
                }
            }
            assertTrue(flat > 0, "plants were flattened while measuring");
            assertEquals(2, zeroRun, "two windows of 120 steps allocating 0 bytes; bytes per window: "
                    + java.util.Arrays.toString(java.util.Arrays.copyOf(windows, w)));
        }
    }

    @Test
    void trailsAreTheSameForOneToEightWorkers() throws Exception {
        SceneDef a = scene("a", RECOVERY, true);
        long first = 0;
        for (int w : new int[] {1, 2, 3, 8}) {
            try (Simulation sim = simulation(a, w)) {
                ViewCamera cam = overhead();
                float flat = 0;
                for (int i = 0; i < 900; i++) {
                    sim.stepFixed(cam);
                    for (int p = 0; p < sim.plantCount(); p++) {
                        flat = Math.max(flat, sim.inspect().state().flattening(p));
                    }
                }
                assertTrue(flat > 0.5f, "the walker flattened plants, most by " + flat);
                long h = sim.inspect().stateHash();
                if (w == 1) {
                    first = h;
                } else {
                    assertEquals(String.format("%016x", first), String.format("%016x", h), w + " workers");
                }
            }
        }
    }

    @Test
    void withoutRecoveryOrWithoutAPushTheStatesAreTodays() throws Exception {
        // recovery 0 written out: the golden state of the frozen C1
        SceneDef zero = scene("zero", 0, false, true);
        assertEquals(String.format("%016x", DeterminismTest.GOLDEN), String.format("%016x",
                DeterminismTest.run(simulation(zero, 2), org.jecosys.anim.AnimationMode.CONSTRAINT)));
        // the grass recovers but nothing flattens it: every deviation and velocity bit for bit as without
        SceneDef c = scene("c", RECOVERY, false);
        try (Simulation with = simulation(c, 2); Simulation without = simulation(scene("elastic", 0, false), 2)) {
            ViewCamera cam = overhead();
            for (int i = 0; i < 600; i++) {
                with.stepFixed(cam);
                without.stepFixed(cam);
            }
            AnimationView s = with.inspect().state();
            AnimationView o = without.inspect().state();
            for (int k = 0; k < s.componentCount(); k++) {
                assertEquals(Float.floatToRawIntBits(o.deviationX(k)), Float.floatToRawIntBits(s.deviationX(k)), "D x " + k);
                assertEquals(Float.floatToRawIntBits(o.deviationZ(k)), Float.floatToRawIntBits(s.deviationZ(k)), "D z " + k);
                assertEquals(Float.floatToRawIntBits(o.velocityX(k)), Float.floatToRawIntBits(s.velocityX(k)), "v x " + k);
                assertEquals(Float.floatToRawIntBits(o.poseCoordinate(k)), Float.floatToRawIntBits(s.poseCoordinate(k)),
                        "pose " + k);
            }
        }
    }
}
