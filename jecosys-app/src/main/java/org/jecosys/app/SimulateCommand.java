package org.jecosys.app;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.anim.AnimationView;
import org.jecosys.bench.Json;
import org.jecosys.field.FieldCounters;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.field.ForceField;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.OutputFiles;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.CameraWalk;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.SimulationDef;
import org.jecosys.sim.World;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code jecosys simulate SCENE}: runs the simulation headless and reports speed and a state hash. */
@Command(name = "simulate", mixinStandardHelpOptions = true,
        description = {"Run the simulation headless (no rendering) and print components, plants, steps, median ms "
                + "per step, component updates per second, allocated bytes per step and a state hash."})
final class SimulateCommand implements Callable<Integer> {
    /** on or off. */
    enum OnOff { on, off }

    @Spec
    CommandSpec spec;
    @Mixin
    Verbose verbose;
    @Mixin
    SceneImages images;
    @Parameters(index = "0", paramLabel = "SCENE", description = "Scene file.")
    String scene;
    @Option(names = "--steps", paramLabel = "N", defaultValue = "600", description = "Fixed steps to run, "
            + "1 to 10000000 (default ${DEFAULT-VALUE}).")
    int steps;
    @Option(names = "--dt", paramLabel = "S", description = "Step length in seconds, 1e-5 to 1 (default: the "
            + "scene's fixedStep).")
    Double dt;
    @Option(names = "--threads", paramLabel = "T", description = "Animation workers, 1 to 256 (default: the "
            + "scene's setting, else the available processors).")
    Integer threads;
    @Option(names = "--mode", paramLabel = "MODE", converter = ModeConverter.class, description = "static, random or constraint (default: the "
            + "scene's).")
    AnimationMode mode;
    @Option(names = "--field", paramLabel = "on|off", description = "Force field on or off (default: the scene's).")
    OnOff field;
    @Option(names = "--json", paramLabel = "FILE", description = "Also write the results and field counters as JSON (a regular "
            + "file, replaced atomically; never a link, device or pipe, never the scene).")
    Path json;
    @Option(names = "--dump", paramLabel = "FILE.csv", description = "Write the final state, one row per component (a regular file, "
            + "replaced atomically; never a link, device or pipe, never the scene or the --json file).")
    Path dump;

    @Override
    public Integer call() {
        if (steps < 1 || steps > 10_000_000) {
            throw new ParameterException(spec.commandLine(), "--steps must be in [1, 10000000], got " + steps);
        }
        if (dt != null && !(dt >= 1e-5 && dt <= 1)) {
            throw new ParameterException(spec.commandLine(), "--dt must be in [1e-5, 1] seconds, got " + dt);
        }
        if (threads != null && (threads < 1 || threads > 256)) {
            throw new ParameterException(spec.commandLine(), "--threads must be in [1, 256], got " + threads);
        }
        OutputPlan plan = new OutputPlan(spec.commandLine()).file("--json", json).file("--dump", dump);
        Path file = SceneArgs.resolve(scene);
        plan.input(file, "the scene file this run reads").check();
        Scene loaded = SceneArgs.load(file, images.of(file, plan), spec.commandLine().getErr());
        if (loaded == null) {
            return ExitCodes.BAD_INPUT;
        }
        plan.checkImages();
        plan.createFolders();
        SceneDef def = loaded.def();
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        SimulationDef sd = overridden(def);
        if (def.isOpenWorld()) {
            if (dump != null) {
                throw new ParameterException(spec.commandLine(), "--dump needs a scene of one square: " + file
                        + " is an open world (<world>), whose plants exist only around the camera");
            }
            return OpenWorldRun.run(file, def, sd, steps, threads == null ? 2 : threads, json, out, err);
        }
        Progress progress = new ConsoleProgress(err, ConsoleProgress.stderrIsTerminal());
        Run run;
        try (Simulation sim = Simulation.create(sd, loaded.images(), threads == null ? 0 : threads, progress)) {
            BuildReport.print(sim.world(), err, err); // stdout stays the results only, for scripts
            CameraWalk walk = new CameraWalk(def.camera(), sim.world().terrain().heightfield(),
                    (double) def.render().width() / def.render().height());
            run = run(sim, walk);
            out.printf(Locale.ROOT, "scene                 %s%n", file);
            out.printf(Locale.ROOT, "components            %d%n", sim.componentCount());
            out.printf(Locale.ROOT, "plants                %d%n", sim.plantCount());
            out.printf(Locale.ROOT, "steps                 %d (dt %s s, mode %s, field %s, %d workers)%n", steps,
                    sd.animation().fixedStep(), sd.animation().mode().xmlName(), sd.field().enabled() ? "on" : "off",
                    sim.inspect().workers());
            out.printf(Locale.ROOT, "median ms per step    %.4f%n", run.medianMs);
            out.printf(Locale.ROOT, "component updates/s   %.4g%n", run.updatesPerSecond);
            out.printf(Locale.ROOT, "allocated bytes/step  %.1f%n", run.allocatedPerStep);
            out.printf(Locale.ROOT, "state hash            %016x%n", run.hash);
            out.flush();
            OutputFiles files = new OutputFiles();
            if (json != null) {
                String text = json(file, sim, sd, run);
                files.write(json, o -> o.write(text.getBytes(StandardCharsets.UTF_8)));
            }
            if (dump != null) {
                files.write(dump, o -> dump(sim, o));
            }
        } catch (IOException e) {
            return fail(err, e);
        }
        return ExitCodes.OK;
    }

    private int fail(PrintWriter err, IOException e) {
        err.println("jecosys simulate: " + e.getMessage());
        if (verbose.verbose) {
            e.printStackTrace(err);
        }
        err.flush();
        return ExitCodes.FAILURE;
    }

    private SimulationDef overridden(SceneDef def) {
        SimulationDef sd = def.simulationDef();
        AnimationDef a = sd.animation();
        AnimationDef anim = new AnimationDef(mode != null ? mode : a.mode(), dt != null ? dt : a.fixedStep(),
                a.maxSubSteps(), a.subIntervals(), threads != null ? threads : a.workers(), a.seed(),
                a.prewarm());
        ForceFieldDef f = sd.field();
        ForceFieldDef fd = field == null ? f
                : f.withEnabled(field == OnOff.on);
        return new SimulationDef(sd.terrain(), sd.species(), sd.distributions(), sd.placements(), sd.flows(), fd,
                anim, sd.seed());
    }

    /** What a run measured. */
    record Run(double medianMs, double updatesPerSecond, double allocatedPerStep, long hash, long updates) {
    }

    private Run run(Simulation sim, CameraWalk walk) {
        int cap = 1 << 20;
        int every = (steps + cap - 1) / cap;
        long[] samples = new long[(steps + every - 1) / every];
        int n = 0;
        long totalNanos = 0;
        long updates = 0;
        long alloc0 = 0;
        int warm = Math.max(1, steps / 2); // allocation is measured over the second half (after warm-up)
        // the first call links the native allocation counter, which allocates: keep it out of the window
        sim.inspect().allocatedBytes();
        for (int i = 0; i < steps; i++) {
            if (i == warm) {
                alloc0 = sim.inspect().allocatedBytes();
            }
            ViewCamera cam = walk.at(sim.inspect().time());
            long t0 = System.nanoTime();
            sim.stepFixed(cam);
            long t = System.nanoTime() - t0;
            totalNanos += t;
            updates += sim.latestFrame().componentsAnimated();
            if (i % every == 0) {
                samples[n++] = t;
            }
        }
        long alloc1 = sim.inspect().allocatedBytes();
        double allocPerStep = steps > 1 && alloc0 >= 0 ? (double) (alloc1 - alloc0) / (steps - warm) : 0;
        Arrays.sort(samples, 0, n);
        double median = n % 2 == 1 ? samples[n / 2] : (samples[n / 2 - 1] + samples[n / 2]) / 2.0;
        return new Run(median / 1e6, totalNanos > 0 ? updates / (totalNanos / 1e9) : 0, allocPerStep,
                sim.inspect().stateHash(), updates);
    }

    private String json(Path file, Simulation sim, SimulationDef sd, Run run) {
        FieldCounters fc = sim.inspect().fieldCounters();
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("scene", file.toString());
        m.put("components", sim.componentCount());
        m.put("plants", sim.plantCount());
        m.put("steps", steps);
        m.put("dt", sd.animation().fixedStep());
        m.put("threads", sim.inspect().workers());
        m.put("mode", sd.animation().mode().xmlName());
        m.put("field", sd.field().enabled());
        m.put("medianMsPerStep", run.medianMs);
        m.put("componentUpdatesPerSecond", run.updatesPerSecond);
        m.put("allocatedBytesPerStep", run.allocatedPerStep);
        m.put("stateHash", String.format(Locale.ROOT, "%016x", run.hash));
        Map<String, Object> c = new LinkedHashMap<>();
        c.put("nodes", fc.nodes());
        c.put("leaves", fc.leaves());
        c.put("visibleNodes", fc.visibleNodes());
        c.put("visibleLeaves", fc.visibleLeaves());
        c.put("effectiveNodes", fc.effectiveNodes());
        c.put("flowEvaluations", fc.flowEvaluations());
        m.put("fieldCounters", c);
        return Json.write(m);
    }

    /** The CSV header of --dump. */
    static final String DUMP_HEADER = "plant,component,species,x,z,windX,windZ,forceX,forceZ,devX,devZ,velX,velZ,"
            + "bend,azimuth,node,nodeDepth";

    /**
     * Streams the final state as CSV, one row per component: memory stays one row whatever the
     * scene's size (the prairie's dump is over 500 MB).
     */
    static void dump(Simulation sim, OutputStream o) throws IOException {
        World w = sim.world();
        AnimationView s = sim.inspect().state();
        ForceField f = sim.inspect().forceField();
        Writer out = new BufferedWriter(new OutputStreamWriter(o, StandardCharsets.UTF_8), 1 << 16);
        out.write(DUMP_HEADER);
        out.write('\n');
        StringBuilder sb = new StringBuilder(256);
        char[] row = new char[256];
        for (int p = 0; p < w.plantCount(); p++) {
            String species = w.plants().species().get(w.plantSpecies(p)).def().id();
            int node = sim.inspect().fieldEnabled() ? f.effectiveNode(p) : -1;
            if (node < 0) {
                node = f.leafNode(p);
            }
            int depth = f.debugView().depth(node);
            for (int c = w.firstComponent(p), e = c + w.componentsOf(p); c < e; c++) {
                sb.append(p).append(',').append(c).append(',').append(species).append(',')
                        .append(w.plantX(p)).append(',').append(w.plantZ(p)).append(',')
                        .append(sim.inspect().windX(p)).append(',').append(sim.inspect().windZ(p)).append(',')
                        .append((float) s.forceX(c)).append(',').append((float) s.forceZ(c)).append(',')
                        .append(s.deviationX(c)).append(',').append(s.deviationZ(c)).append(',')
                        .append(s.velocityX(c)).append(',').append(s.velocityZ(c)).append(',')
                        .append(s.bend(c)).append(',').append(s.azimuth(c)).append(',')
                        .append(node).append(',').append(depth).append('\n');
                int n = sb.length();
                if (n > row.length) {
                    row = new char[2 * n];
                }
                sb.getChars(0, n, row, 0); // Writer.append(CharSequence) would make a String per row
                out.write(row, 0, n);
                sb.setLength(0);
            }
        }
        out.flush();
    }
}
