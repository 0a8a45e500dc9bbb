package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.jecosys.anim.AnimationView;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The showcase meadow's wind looks like wind (scenes/meadow.xml, its default view, 60 Hz). A plant's
 * bend is the mean bend of its components (radians), sampled at 30 Hz over the plants in view all
 * the time:
 * <ul>
 * <li>gusts travel: the bend pattern one second later correlates best with the pattern shifted
 * downwind at the mean wind's speed (within 30%), at least 0.1 better than with the standing one;</li>
 * <li>neighbours move alike but not in lockstep: over plant pairs closer than 1 m the mean
 * correlation of their bends is between 0.5 and 0.9, and at most 1% of the pairs exceed 0.99;</li>
 * <li>no start-up: the first 10 frames, from the first state a viewer can be shown (the state before
 * the first step; with the meadow's prewarm, {@code <animation prewarm>}, the first step's frame, the
 * built state never being published), change the meadow (mean |change of D| per component per frame)
 * no more than 1.1 times the most any 10 frames of the steady state do (from 3 s on), and at least
 * half as much as the steady state's mean: the meadow starts in motion, without a jump (with prewarm
 * 1 s: 0.00211 m against the steady 0.00174, whose largest 10 frames read 0.00210; the wind of the
 * first seconds is gustier than the mean, whatever the prewarm);</li>
 * <li>with a 9 m/s gust at most 5% of plant-frames have a component at (or within 2% of) maxBend,
 * and a plant's bend varies in time by at least 10% of its mean.</li>
 * </ul>
 */
class MeadowWindTest {
    static final double HZ = 60;
    static final int EVERY = 2;
    static SceneDef scene;

    @BeforeAll
    static void load() throws Exception {
        scene = SceneFiles.parse(Path.of("scenes/meadow.xml"));
    }

    /** One run: per-frame bends of the plants always in view, the change per frame, the mean wind. */
    static final class Run {
        final List<Integer> plants = new ArrayList<>();
        float[][] bend;
        /** Per sample, per plant: whether one of its components is within 2% of maxBend. */
        boolean[][] atMax;
        double[] change;
        double windX;
        double windZ;
        World world;
    }

    static Run run(List<FlowDef> flows, double seconds) throws Exception {
        SimulationDef d = scene.simulationDef();
        // a quarter of the meadow's plants (the wind is tested, not the density): keeps the test fast
        List<DistributionDef> quarter = new ArrayList<>();
        for (DistributionDef dist : d.distributions()) {
            quarter.add(dist.toBuilder().count(dist.count() / 4).build());
        }
        SimulationDef def = new SimulationDef(d.terrain(), d.species(), quarter, d.placements(), flows,
                d.field(), d.animation(), d.seed());
        Run r = new Run();
        try (Simulation sim = Simulation.create(def, Path.of("scenes"), 2, Progress.NONE)) {
            World w = sim.world();
            r.world = w;
            ViewCamera cam = ViewCamera.of(scene.camera(), w.terrain().heightfield().height(scene.camera().x(),
                    scene.camera().z()), 16.0 / 9);
            AnimationView s = sim.inspect().state();
            int plants = sim.plantCount();
            int steps = (int) Math.round(seconds * HZ);
            float[] px = new float[sim.componentCount()];
            float[] pz = new float[sim.componentCount()];
            for (int c = 0; c < px.length; c++) {
                px[c] = s.deviationX(c);
                pz[c] = s.deviationZ(c);
            }
            boolean[] always = new boolean[plants];
            java.util.Arrays.fill(always, true);
            r.change = new double[steps + 1];
            r.bend = new float[steps / EVERY][];
            r.atMax = new boolean[steps / EVERY][];
            long winds = 0;
            for (int k = 1; k <= steps; k++) {
                sim.stepFixed(cam);
                double sum = 0;
                int n = 0;
                for (int p = 0; p < plants; p++) {
                    if (!sim.inspect().plantVisible(p)) {
                        always[p] = false;
                        continue;
                    }
                    for (int c = w.firstComponent(p), e = c + w.componentsOf(p); c < e; c++) {
                        float x = s.deviationX(c);
                        float z = s.deviationZ(c);
                        sum += Math.hypot(x - px[c], z - pz[c]);
                        n++;
                        px[c] = x;
                        pz[c] = z;
                    }
                    r.windX += sim.inspect().windX(p);
                    r.windZ += sim.inspect().windZ(p);
                    winds++;
                }
                r.change[k] = sum / n;
                if (k % EVERY == 0) {
                    float[] b = new float[plants];
                    boolean[] f = new boolean[plants];
                    for (int p = 0; p < plants; p++) {
                        int c0 = w.firstComponent(p);
                        float t = 0;
                        for (int c = c0, e = c0 + w.componentsOf(p); c < e; c++) {
                            float bend = s.bend(c);
                            t += bend;
                            f[p] |= bend >= 0.98f * s.kinds().maxBend(s.kind(c));
                        }
                        b[p] = t / w.componentsOf(p);
                    }
                    r.bend[k / EVERY - 1] = b;
                    r.atMax[k / EVERY - 1] = f;
                }
            }
            r.windX /= winds;
            r.windZ /= winds;
            for (int p = 0; p < plants; p++) {
                if (always[p]) {
                    r.plants.add(p);
                }
            }
        }
        return r;
    }

    /** Each plant's bend series from sample {@code from}, made zero-mean and unit-variance. */
    static double[][] standardised(Run r, int from) {
        double[][] z = new double[r.world.plantCount()][];
        int n = r.bend.length - from;
        for (int p : r.plants) {
            double m = 0;
            double m2 = 0;
            for (int i = from; i < r.bend.length; i++) {
                m += r.bend[i][p];
                m2 += r.bend[i][p] * (double) r.bend[i][p];
            }
            m /= n;
            double sd = Math.sqrt(Math.max(1e-24, m2 / n - m * m));
            z[p] = new double[n];
            for (int i = 0; i < n; i++) {
                z[p][i] = (r.bend[i + from][p] - m) / sd;
            }
        }
        return z;
    }

    static long cell(double x, double z) {
        return (long) Math.floor(x) << 32 ^ ((long) Math.floor(z) & 0xffffffffL);
    }

    static Map<Long, List<Integer>> grid(Run r) {
        Map<Long, List<Integer>> g = new HashMap<>();
        for (int p : r.plants) {
            g.computeIfAbsent(cell(r.world.plantX(p), r.world.plantZ(p)), k -> new ArrayList<>()).add(p);
        }
        return g;
    }

    /** The plant in view nearest (x, z) within {@code radius} metres, or -1. */
    static int nearest(Map<Long, List<Integer>> g, World w, double x, double z, double radius) {
        int best = -1;
        double bd = radius;
        for (int dx = -1; dx <= 1; dx++) {
            for (int dz = -1; dz <= 1; dz++) {
                for (int q : g.getOrDefault(cell(x + dx, z + dz), List.of())) {
                    double d = Math.hypot(w.plantX(q) - x, w.plantZ(q) - z);
                    if (d < bd) {
                        bd = d;
                        best = q;
                    }
                }
            }
        }
        return best;
    }

    /**
     * The correlation of the standardised bend at each plant with the bend {@code lag} samples later
     * at the plant nearest the point {@code v lag} downwind (v in m/s; v = 0: the same plant).
     */
    static double travelling(Run r, double[][] z, Map<Long, List<Integer>> g, double v, int lag, double dirX,
                             double dirZ) {
        double seconds = lag * EVERY / HZ;
        double sum = 0;
        long n = 0;
        for (int p : r.plants) {
            int q = nearest(g, r.world, r.world.plantX(p) + v * seconds * dirX, r.world.plantZ(p) + v * seconds * dirZ,
                    0.5);
            if (q < 0) {
                continue;
            }
            for (int i = 0; i + lag < z[p].length; i++) {
                sum += z[p][i] * z[q][i + lag];
                n++;
            }
        }
        return sum / n;
    }

    static Run meadow;

    static synchronized Run meadow() throws Exception {
        if (meadow == null) {
            meadow = run(scene.flows(), 15);
        }
        return meadow;
    }

    @Test
    void gustFrontsCrossTheFieldAtTheMeanWindsSpeed() throws Exception {
        Run r = meadow();
        double[][] z = standardised(r, (int) (HZ / EVERY));
        Map<Long, List<Integer>> g = grid(r);
        double speed = Math.hypot(r.windX, r.windZ);
        int lag = (int) Math.round(HZ / EVERY); // one second
        double best = -2;
        double bestV = 0;
        for (double v = 0; v <= 2.5 * speed; v += 0.25) {
            double c = travelling(r, z, g, v, lag, r.windX / speed, r.windZ / speed);
            if (c > best) {
                best = c;
                bestV = v;
            }
        }
        double standing = travelling(r, z, g, 0, lag, 1, 0);
        assertTrue(Math.abs(bestV - speed) <= 0.3 * speed, "the bend pattern travels at " + bestV + " m/s, the mean "
                + "wind is " + speed + " m/s");
        assertTrue(best >= standing + 0.1, "travelling pattern correlates " + best + ", standing " + standing);
    }

    @Test
    void neighboursMoveAlikeButNotInLockstep() throws Exception {
        Run r = meadow();
        double[][] z = standardised(r, (int) (HZ / EVERY));
        Map<Long, List<Integer>> g = grid(r);
        double sum = 0;
        int pairs = 0;
        int lockstep = 0;
        World w = r.world;
        for (int p : r.plants) {
            for (int dx = -1; dx <= 1; dx++) {
                for (int dz = -1; dz <= 1; dz++) {
                    for (int q : g.getOrDefault(cell(w.plantX(p) + dx, w.plantZ(p) + dz), List.of())) {
                        if (q <= p || Math.hypot(w.plantX(p) - w.plantX(q), w.plantZ(p) - w.plantZ(q)) >= 1) {
                            continue;
                        }
                        double c = 0;
                        for (int i = 0; i < z[p].length; i++) {
                            c += z[p][i] * z[q][i];
                        }
                        c /= z[p].length;
                        sum += c;
                        pairs++;
                        lockstep += c > 0.99 ? 1 : 0;
                    }
                }
            }
        }
        assertTrue(pairs > 500, "pairs closer than 1 m: " + pairs);
        double mean = sum / pairs;
        assertTrue(mean >= 0.5 && mean <= 0.9, "mean correlation of neighbours " + mean);
        assertTrue(lockstep <= 0.01 * pairs, lockstep + " of " + pairs + " pairs move in lockstep");
    }

    @Test
    void theFirstFramesChangeNoMoreThanTheSteadyState() throws Exception {
        Run r = meadow();
        double first = 0;
        assertTrue(scene.simulationDef().animation().prewarm() > 0, "the meadow prewarms");
        for (int k = 2; k <= 11; k++) { // change[1] leads from the built state, never published, to frame 1
            first += r.change[k];
        }
        first /= 10;
        double steady = 0;
        int from = (int) (3 * HZ);
        for (int k = from; k < r.change.length; k++) {
            steady += r.change[k];
        }
        steady /= r.change.length - from;
        double most = 0; // the steady state's largest change over 10 frames: the wind's own range
        for (int k = from; k + 10 <= r.change.length; k++) {
            double w = 0;
            for (int j = 0; j < 10; j++) {
                w += r.change[k + j] / 10;
            }
            most = Math.max(most, w);
        }
        System.out.printf(java.util.Locale.ROOT, "meadow start: first 10 frames %.5f m per frame, steady %.5f (its "
                + "largest 10 frames %.5f)%n", first, steady, most);
        assertTrue(first <= 1.1 * most, "first 10 frames " + first + " m per frame, the steady state's largest 10 "
                + most);
        assertTrue(first >= 0.5 * steady, "the meadow starts in motion: first 10 frames " + first + " m per frame, "
                + "steady " + steady);
    }

    @Test
    void aNineMetreGustBendsTheMeadowWithoutCombingItFlat() throws Exception {
        List<FlowDef> flows = new ArrayList<>();
        for (FlowDef f : scene.flows()) {
            flows.add(f.kind() == FlowKind.GUST ? f.toBuilder().strength(9).build() : f);
        }
        assertEquals(1, flows.stream().filter(f -> f.kind() == FlowKind.GUST).count());
        Run r = run(flows, 8);
        int from = (int) (HZ / EVERY);
        long frames = 0;
        long atMax = 0;
        double relative = 0;
        for (int p : r.plants) {
            double m = 0;
            double m2 = 0;
            for (int i = from; i < r.bend.length; i++) {
                frames++;
                atMax += r.atMax[i][p] ? 1 : 0;
                m += r.bend[i][p];
                m2 += r.bend[i][p] * (double) r.bend[i][p];
            }
            int n = r.bend.length - from;
            m /= n;
            relative += Math.sqrt(Math.max(0, m2 / n - m * m)) / m;
        }
        assertTrue(atMax <= 0.05 * frames, atMax + " of " + frames + " plant-frames at maxBend");
        relative /= r.plants.size();
        assertTrue(relative >= 0.1, "a plant's bend varies by " + relative + " of its mean");
    }
}
