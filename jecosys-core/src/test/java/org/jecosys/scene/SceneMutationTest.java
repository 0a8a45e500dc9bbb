package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.jecosys.anim.AnimationView;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.terrain.DistributionDef;
import org.junit.jupiter.api.Test;

/**
 * A seeded mutation fuzz of the loader in every {@code mvn -B verify} (the Jazzer
 * {@link SceneFuzzTest} replays its corpus; this one makes new inputs each build, the same ones for
 * the same seed). Mutants of the shipped scenes: numbers replaced by extremes (0, 1e-100, 4.9e-324,
 * the largest double, NaN, schema bounds...), attributes and lines deleted, duplicated or swapped,
 * ids collided, bytes cut. The only outcomes allowed: a scene, or a {@link SceneLoadException} whose
 * every problem has a line and a column; anything else thrown fails. Every valid mutant small enough
 * (see {@link #MAX_COMPONENTS}) is then built and simulated for 5 steps, which must not throw, and
 * must leave no NaN or infinity in the state or the frame: accepted means runnable.
 */
class SceneMutationTest {
    /** The seed; {@code -Djecosys.fuzz.seed=N} runs other mutants. */
    static final long SEED = Long.getLong("jecosys.fuzz.seed", 20_241_117L);
    /** Mutants per run; {@code -Djecosys.fuzz.mutants=N} runs more. */
    static final int MUTANTS = Integer.getInteger("jecosys.fuzz.mutants", 400);
    /** Valid mutants up to this many components (upper bound, before building) are simulated. */
    static final long MAX_COMPONENTS = 20_000;
    static final long MAX_POSE_BYTES = 16L << 20;
    private static final String[] EXTREMES = {"0", "-0", "1e-100", "4.9e-324", "-1", "1e308", "1.7976931348623157e308",
        "1e12", "-1e12", "NaN", "Infinity", "-Infinity", "1000000", "-1000000", "0.001", "1e-9", "2147483648",
        "-2147483649", "9999999999999999999", "", " ", "abc", "1e", "0x10", "10000", "100000", "1e9", "256", "64",
        "8192", "2049", "1024", "65", "33", "90", "-90", "360", "-360", "179", "1e-5", "0.1"};
    private static final Pattern NUMBER_ATTR = Pattern.compile("([A-Za-z]+)=\"(-?[0-9.][0-9.eE+-]*)\"");
    private static final Pattern ANY_ATTR = Pattern.compile(" ([A-Za-z]+)=\"[^\"]*\"");
    private static final Pattern ID_ATTR = Pattern.compile("id=\"([^\"]*)\"");

    private static List<String> shippedScenes() throws Exception {
        try (Stream<Path> s = Files.list(Path.of("scenes"))) {
            List<String> out = new ArrayList<>();
            for (Path p : s.filter(p -> p.toString().endsWith(".xml")).sorted().toList()) {
                out.add(Files.readString(p, StandardCharsets.UTF_8));
            }
            return out;
        }
    }

    static String mutate(String xml, Random rnd) {
        int r = rnd.nextInt(10);
        int ops = r < 7 ? 1 : r < 9 ? 2 : 3;
        String s = xml;
        for (int k = 0; k < ops; k++) {
            int op = rnd.nextInt(100);
            if (op < 50) {
                s = replaceNumber(s, rnd);
            } else if (op < 60) {
                s = deleteAttribute(s, rnd);
            } else if (op < 70) {
                s = duplicateLine(s, rnd);
            } else if (op < 78) {
                s = deleteLine(s, rnd);
            } else if (op < 85) {
                s = swapLines(s, rnd);
            } else if (op < 92) {
                s = collideIds(s, rnd);
            } else {
                s = cut(s, rnd);
            }
        }
        return s;
    }

    private static String replaceNumber(String s, Random rnd) {
        List<int[]> spans = new ArrayList<>();
        Matcher m = NUMBER_ATTR.matcher(s);
        while (m.find()) {
            spans.add(new int[] {m.start(2), m.end(2)});
        }
        if (spans.isEmpty()) {
            return s;
        }
        int pick = rnd.nextInt(spans.size());
        int[] sp = spans.get(pick);
        m.reset();
        for (int i = 0; i <= pick; i++) {
            m.find();
        }
        AttrSpec bounds = anyRange(SceneSchema.ROOT, m.group(1), rnd);
        String v;
        int how = rnd.nextInt(10);
        if (how < 5 && bounds != null) {
            // the schema's own extremes: valid, so the scene goes on to be simulated
            double lo = bounds.minExclusive ? Math.nextUp(bounds.min) : bounds.min;
            double[] at = {lo, bounds.max, lo, bounds.max, (lo + bounds.max) / 2};
            double x = at[rnd.nextInt(at.length)];
            v = bounds.type == AttrType.INT || bounds.type == AttrType.LONG ? String.valueOf((long) x) : Double.toString(x);
        } else if (how < 7) {
            double old = Double.parseDouble(s.substring(sp[0], sp[1]).isEmpty() ? "0" : safe(s.substring(sp[0], sp[1])));
            v = Double.toString(old * Math.pow(10, rnd.nextInt(13) - 6) * (rnd.nextBoolean() ? 1 : -1));
        } else {
            v = EXTREMES[rnd.nextInt(EXTREMES.length)];
        }
        return s.substring(0, sp[0]) + v + s.substring(sp[1]);
    }

    /** An attribute spec of this name with a finite range, anywhere in the schema, or null. */
    private static AttrSpec anyRange(ElementSpec e, String name, Random rnd) {
        List<AttrSpec> found = new ArrayList<>();
        collect(e, name, found);
        return found.isEmpty() ? null : found.get(rnd.nextInt(found.size()));
    }

    private static void collect(ElementSpec e, String name, List<AttrSpec> found) {
        AttrSpec a = e.attrSpec(name);
        if (a != null && a.hasRange() && Double.isFinite(a.min) && Double.isFinite(a.max)
                && (a.type == AttrType.DOUBLE || a.type == AttrType.ANGLE || a.type == AttrType.INT)) {
            found.add(a);
        }
        for (ElementSpec.Child c : e.children) {
            collect(c.spec, name, found);
        }
    }

    private static String safe(String number) {
        try {
            Double.parseDouble(number);
            return number;
        } catch (NumberFormatException e) {
            return "1";
        }
    }

    private static String deleteAttribute(String s, Random rnd) {
        List<int[]> spans = new ArrayList<>();
        Matcher m = ANY_ATTR.matcher(s);
        while (m.find()) {
            spans.add(new int[] {m.start(), m.end()});
        }
        if (spans.isEmpty()) {
            return s;
        }
        int[] sp = spans.get(rnd.nextInt(spans.size()));
        return s.substring(0, sp[0]) + s.substring(sp[1]);
    }

    private static List<String> lines(String s) {
        return new ArrayList<>(List.of(s.split("\n", -1)));
    }

    private static String duplicateLine(String s, Random rnd) {
        List<String> l = lines(s);
        int i = rnd.nextInt(l.size());
        l.add(i, l.get(i));
        return String.join("\n", l);
    }

    private static String deleteLine(String s, Random rnd) {
        List<String> l = lines(s);
        l.remove(rnd.nextInt(l.size()));
        return String.join("\n", l);
    }

    private static String swapLines(String s, Random rnd) {
        List<String> l = lines(s);
        int i = rnd.nextInt(l.size());
        int j = rnd.nextInt(l.size());
        String t = l.get(i);
        l.set(i, l.get(j));
        l.set(j, t);
        return String.join("\n", l);
    }

    private static String collideIds(String s, Random rnd) {
        List<String> ids = new ArrayList<>();
        Matcher m = ID_ATTR.matcher(s);
        while (m.find()) {
            ids.add(m.group(1));
        }
        if (ids.size() < 2) {
            return s;
        }
        String a = ids.get(rnd.nextInt(ids.size()));
        String b = ids.get(rnd.nextInt(ids.size()));
        return s.replaceFirst("\"" + Pattern.quote(a) + "\"", "\"" + Matcher.quoteReplacement(b) + "\"");
    }

    private static String cut(String s, Random rnd) {
        return s.substring(0, rnd.nextInt(s.length() + 1));
    }

    /** Whether a valid mutant is small enough to build and simulate here. */
    static boolean small(SceneDef d) {
        long components = 0;
        long poses = 0;
        for (var p : d.placements()) {
            components += d.speciesById(p.species()).componentsPerPlant();
        }
        for (DistributionDef dist : d.distributions()) {
            components += SceneBudget.plantsAtMost(d.terrain(), dist) * d.speciesById(dist.species()).componentsPerPlant();
        }
        for (SpeciesDef s : d.species()) {
            poses += SceneBudget.poseBytes(s);
        }
        return components <= MAX_COMPONENTS && poses <= MAX_POSE_BYTES && d.terrain().resolution() <= 1025
                && d.terrain().water().resolution() <= 512 && d.terrain().nutrients().resolution() <= 512;
    }

    @Test
    void mutantsLoadOrFailWithLocatedProblemsAndValidOnesSimulateWithoutNaN() throws Exception {
        List<String> scenes = shippedScenes();
        assertTrue(scenes.size() >= 5, "shipped scenes: " + scenes.size());
        Random rnd = new Random(SEED);
        int mutants = MUTANTS;
        int valid = 0;
        int simulated = 0;
        int refused = 0;
        List<String> failures = new ArrayList<>();
        for (int i = 0; i < mutants && failures.size() < 5; i++) {
            String mutant = mutate(scenes.get(i % scenes.size()), rnd);
            String name = "mutant-" + i + ".xml";
            SceneDef d;
            try {
                d = SceneFiles.parse(mutant.getBytes(StandardCharsets.UTF_8), name, Path.of("scenes"));
            } catch (SceneLoadException e) {
                refused++;
                for (SceneProblem p : e.problems()) {
                    if (p.line() < 1 || p.column() < 1 || p.message().isBlank() || !p.file().equals(name)) {
                        failures.add(name + ": a problem without a location: " + p + "\n" + mutant);
                    }
                }
                continue;
            } catch (Throwable t) {
                failures.add(name + ": the loader threw " + t + "\n" + mutant);
                continue;
            }
            valid++;
            if (!small(d)) {
                continue;
            }
            simulated++;
            String nan = simulate(d);
            if (nan != null) {
                failures.add(name + ": " + nan + "\n" + mutant);
            }
        }
        if (!failures.isEmpty()) {
            fail(failures.size() + " mutant(s) of seed " + SEED + " failed:\n" + String.join("\n\n", failures));
        }
        assertTrue(valid > mutants / 5 && refused > mutants / 5, "valid " + valid + ", refused " + refused);
        assertTrue(simulated > mutants / 10, "simulated " + simulated + " of " + valid + " valid, " + refused + " refused");
    }

    /** Builds and runs 5 steps; the first NaN or infinity found, or what was thrown; null when clean. */
    private static String simulate(SceneDef d) {
        try (Simulation sim = Simulation.create(d.simulationDef(), Path.of("scenes"), 1, Progress.NONE)) {
            double ground = sim.world().terrain().heightfield().height(d.camera().x(), d.camera().z());
            ViewCamera cam = ViewCamera.of(d.camera(), ground, 16.0 / 9);
            for (int s = 0; s < 5; s++) {
                sim.stepFixed(cam);
            }
            AnimationView v = sim.inspect().state();
            Frame f = sim.latestFrame();
            for (int c = 0; c < sim.componentCount(); c++) {
                double[] values = {v.deviationX(c), v.deviationZ(c), v.velocityX(c), v.velocityZ(c), v.bend(c),
                    v.azimuth(c), v.poseCoordinate(c), v.forceX(c), v.forceZ(c), f.poseCoord(c), f.bendAzimuth(c)};
                for (int k = 0; k < values.length; k++) {
                    if (!Double.isFinite(values[k])) {
                        return "component " + c + " value " + k + " is " + values[k] + " after 5 steps";
                    }
                }
            }
            for (int p = 0; p < sim.plantCount(); p++) {
                if (!Float.isFinite(sim.inspect().windX(p)) || !Float.isFinite(sim.inspect().windZ(p))) {
                    return "plant " + p + " wind is " + sim.inspect().windX(p) + ", " + sim.inspect().windZ(p);
                }
            }
            return null;
        } catch (Throwable t) {
            return "accepted but building or stepping threw " + t;
        }
    }
}
