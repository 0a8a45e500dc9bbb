package org.jecosys.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.CameraWalk;
import org.jecosys.sim.OpenWorld;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.SimulationDef;
import org.jecosys.sim.World;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.world.RollingTerrain;
import org.jecosys.world.TilePlacer;

/**
 * The open world's simulation along a walk (issue 39): the meadow's species, flows, field and
 * animation ({@code meadow.xml}) streamed in 32 m tiles within 64 m of a camera that walks straight at
 * 10 m/s over unbounded rolling hills, 30 frames a second, 2 animation workers and 1 tile worker. Per
 * frame the time of its fixed steps; at checkpoints the heap after a full GC, the tiles, plants and
 * components alive, the tiles built per second and the steps that waited for a tile. Then the same
 * cost per animated component for the meadow itself along its own camera path (2 workers), the figure
 * the walk's is measured against. Beside each step's wall time its CPU time ({@link StepClock}) and, on
 * Linux, what else in the process ran meanwhile ({@link CoreShares}); between the standing steps a fixed
 * kernel on two threads at once ({@link TwoThreadKernel}) and after them one on one thread: the
 * machine's own spread. Nothing is drawn.
 */
final class OpenWorldSection implements Section {
    private static final double SPEED = 10;
    private static final double RATE = 30;
    static final double TILE = 16;
    static final double RADIUS = 64;
    private final Path scenes;

    OpenWorldSection(Path scenes) {
        this.scenes = scenes;
    }

    @Override
    public String name() {
        return "open-world simulation along a walk";
    }

    /** The meadow's mix, about 5.7 plants per m² after the competition, on the meadow's species. */
    static TilePlacer placer(SimulationDef def) {
        List<DistributionDef> d = StreamingSection.meadow();
        int[] species = new int[d.size()];
        for (int k = 0; k < d.size(); k++) {
            species[k] = index(def, d.get(k).species());
        }
        return new TilePlacer(def.seed(), TILE, d, species, RollingTerrain.gentle(def.seed()));
    }

    private static int index(SimulationDef def, String id) {
        for (int s = 0; s < def.species().size(); s++) {
            if (def.species().get(s).id().equals(id)) {
                return s;
            }
        }
        throw new IllegalArgumentException("the meadow has no species " + id);
    }

    @Override
    public void run(Mode mode, Report report) throws Exception {
        double[] checkpoints = switch (mode) {
            case SMOKE -> new double[] {10, 20};
            case QUICK -> new double[] {200, 400, 600};
            case FULL -> new double[] {1000, 2500, 5000};
        };
        SimulationDef def = SceneFiles.parse(scenes.resolve("meadow.xml")).simulationDef();
        double radius = mode == Mode.SMOKE ? 20 : RADIUS;
        TilePlacer placer = placer(def);
        RollingTerrain ground = RollingTerrain.gentle(def.seed());
        Table t = new Table("open-world", String.format(java.util.Locale.ROOT,
                "Open world: the meadow's species streamed along a straight walk at 10 m/s (%.0f m tiles within %.0f m, "
                + "2 animation workers, 1 tile worker, nothing drawn)", TILE, radius),
                List.of("distance m", "heap after GC MB", "tiles alive", "plants alive", "components alive",
                        "tiles built per s", "step ms (median)", "step ms (p99)", "p99 / median",
                        "step CPU p99 / median", "ns per animated component (median)", "waits for a tile"));
        MemoryMXBean memory = ManagementFactory.getMemoryMXBean();
        List<Object> raw = new ArrayList<>();
        double walkNs;
        Map<String, Object> m = new LinkedHashMap<>();
        double[] standing = null;
        double[] floor = null;
        double[] twoThreads = null;
        try (OpenWorld w = OpenWorld.create(def, placer, radius, 2, 1, 4);
             CollectorPauses pauses = new CollectorPauses();
             CoreShares shares = new CoreShares()) {
            StepClock clock = new StepClock("jecosys-world-");
            ViewCamera cam = new ViewCamera();
            cam.setOrientation(Math.PI / 2, Math.toRadians(-8));
            cam.setLens(Math.toRadians(60), 16.0 / 9, 0.1, 1000);
            place(cam, ground, mode == Mode.SMOKE ? -5 : -100);
            // the start is loaded as a game's loading screen would load it
            w.load(cam);
            // a warm-up walk of 100 m in real time (the JIT, the tiles ahead), not measured; 10 m in a smoke run
            long warm = System.nanoTime();
            int warmFrames = mode == Mode.SMOKE ? 15 : 300;
            for (int f = 0; f < warmFrames; f++) {
                place(cam, ground, (f + 1 - warmFrames) * SPEED / RATE);
                warm += (long) (1e9 / RATE);
                StepClock.sleepUntil(warm);
                w.step(1 / RATE, cam);
            }
            double end = checkpoints[checkpoints.length - 1];
            int frames = (int) Math.ceil(end / SPEED * RATE);
            double[] stepMs = new double[frames];
            double[] frameMs = new double[frames];
            double[] cpuMs = new double[frames];
            double[] perComponent = new double[frames];
            int used = 0;
            int next = 0;
            long builtBefore = w.builtTiles();
            long waitsBefore = w.tileWaits();
            int segment = 0;
            double since = 0;
            long frameNanos = (long) (1e9 / RATE);
            // the collector's pauses along the walk, but for the full collections asked for at the checkpoints
            long[] stepStart = new long[frames];
            long[] stepEnd = new long[frames];
            long[] gcFrom = new long[checkpoints.length];
            long[] gcTo = new long[checkpoints.length];
            // what else in the process ran while each step ran (Linux)
            long[][] others = new long[CoreShares.SLOTS][frames];
            long[] before = new long[CoreShares.SLOTS];
            long[] after = new long[CoreShares.SLOTS];
            long walkStart = System.nanoTime();
            long deadline = walkStart;
            for (int f = 0; f < frames; f++) {
                double x = (f + 1) * SPEED / RATE;
                place(cam, ground, x);
                if (f % 300 == 0) {
                    shares.rescan();
                }
                // real time: 30 frames a second, as a game's loop; tiles are built in the time between steps
                deadline = StepClock.pace(deadline + frameNanos);
                shares.read(before);
                long c0 = clock.cpuNanos();
                long t0 = System.nanoTime();
                int n = w.step(1 / RATE, cam);
                long ns = System.nanoTime() - t0;
                long cpu = clock.cpuNanos() - c0;
                shares.read(after);
                if (n > 0) {
                    for (int k = 0; k < CoreShares.SLOTS; k++) {
                        others[k][used] = after[k] - before[k];
                    }
                    stepStart[used] = t0;
                    stepEnd[used] = t0 + ns;
                    stepMs[used] = ns / 1e6 / n;
                    frameMs[used] = ns / 1e6;
                    cpuMs[used] = cpu / 1e6 / n;
                    perComponent[used] = w.animatedComponents() > 0 ? (double) ns / n / w.animatedComponents() : 0;
                    used++;
                }
                if (next < checkpoints.length && x >= checkpoints[next] - 1e-9) {
                    gcFrom[next] = System.nanoTime();
                    System.gc();
                    System.gc();
                    gcTo[next] = System.nanoTime();
                    double heap = memory.getHeapMemoryUsage().getUsed() / (1024.0 * 1024.0);
                    double[] ms = java.util.Arrays.copyOfRange(stepMs, segment, used);
                    double median = Stats.median(ms);
                    double p99 = Stats.percentile(ms, 0.99);
                    double[] cpus = java.util.Arrays.copyOfRange(cpuMs, segment, used);
                    double cpuRatio = Stats.percentile(cpus, 0.99) / Stats.median(cpus);
                    double seconds = (x - since) / SPEED;
                    double builtPerSecond = (w.builtTiles() - builtBefore) / seconds;
                    double nsPer = Stats.median(java.util.Arrays.copyOfRange(perComponent, segment, used));
                    t.row(Math.round(x), heap, w.liveTiles(), w.livePlants(), w.liveComponents(), builtPerSecond,
                            median, p99, p99 / median, cpuRatio, nsPer, w.tileWaits() - waitsBefore);
                    Map<String, Object> row = new LinkedHashMap<>();
                    row.put("distance", x);
                    row.put("heapMB", heap);
                    row.put("tiles", w.liveTiles());
                    row.put("plants", w.livePlants());
                    row.put("components", w.liveComponents());
                    row.put("tilesBuiltPerSecond", builtPerSecond);
                    row.put("stepMedianMs", median);
                    row.put("stepP99Ms", p99);
                    row.put("stepCpuP99OverMedian", cpuRatio);
                    row.put("nsPerAnimatedComponent", nsPer);
                    row.put("waits", w.tileWaits() - waitsBefore);
                    raw.add(row);
                    next++;
                    builtBefore = w.builtTiles();
                    waitsBefore = w.tileWaits();
                    segment = used;
                    since = x;
                }
            }
            walkNs = Stats.median(java.util.Arrays.copyOf(perComponent, used));
            t.note("Each row: the walk's stretch since the previous row (steps, tiles built, waits), and the heap"
                    + " after a full GC, the tiles, plants and components alive at its end. The walk runs in real time"
                    + " (30 frames a second, as a game's loop; tiles are built in the time between steps), after a"
                    + " loading screen and a warm-up walk of 100 m. At most " + w.maxLiveTiles() + " tiles are live"
                    + " per view (those within the radius plus one tile). A wait is a step that found a tile due and"
                    + " not built yet.");
            double[] walkSteps = java.util.Arrays.copyOf(stepMs, used);
            double[] slow = SlowSteps.count(walkSteps, java.util.Arrays.copyOf(cpuMs, used));
            t.note(String.format(java.util.Locale.ROOT, "Of the walk's %d steps, %.0f took longer than 1.5 times the"
                    + " median; in %.0f of them the CPU time (the threads' sum) was within 1.3 times its median: the"
                    + " usual work, run on fewer cores. CPU time over wall time: %.2f in those slow steps, %.2f in all"
                    + " (medians; the animation's two threads side by side give up to 2).", used, slow[0], slow[1],
                    slow[2], slow[3]));
            m.put("slowSteps", slow[0]);
            m.put("slowStepsWithUsualCpu", slow[1]);
            double[] gc = pauses.within(walkStart, System.nanoTime(), gcFrom, gcTo, next);
            boolean[] inPause = SlowSteps.inPause(stepStart, stepEnd, used, pauses);
            int slowInPause = SlowSteps.inPauses(walkSteps, inPause);
            t.note(String.format(java.util.Locale.ROOT, "The collector (%s) paused the walk %.0f times, %.1f ms in all,"
                    + " the longest %.1f ms (the full collections asked for at the rows left out); %d of the slow steps"
                    + " overlapped a pause.", CollectorPauses.names(), gc[0], gc[1], gc[2], slowInPause));
            m.put("collectorPauses", gc[0]);
            m.put("collectorPauseMs", gc[1]);
            m.put("collectorLongestPauseMs", gc[2]);
            m.put("slowStepsInAPause", slowInPause);
            if (CoreShares.available()) {
                CoreShares.Attribution a = CoreShares.attribute(walkSteps, others, inPause, 1_000_000);
                t.note(CoreShares.note(a, used, 1));
                m.put("slowStepsWithCompiler", a.slowWith()[CoreShares.COMPILER]);
                m.put("slowStepsWithCollector", a.slowWith()[CoreShares.COLLECTOR]);
                m.put("slowStepsWithTileWorkers", a.slowWith()[CoreShares.TILES]);
                m.put("slowStepsWithOtherJvmThreads", a.slowWith()[CoreShares.OTHER]);
                m.put("slowStepsWithNone", a.slowNone());
                m.put("slowStepsWithNoneThatWaitedInTheRunQueue", a.slowNoneWaited());
            }
            if (mode != Mode.SMOKE && Affinity.available()) {
                double metres = mode == Mode.FULL ? 1000 : 600;
                double[] pinned = pinnedWalk(w, cam, ground, end, metres, clock);
                t.note(String.format(java.util.Locale.ROOT, "The walk went on for %.0f m with its threads pinned to"
                        + " cores, as a game engine pins its workers (the stepping thread to core 0, the animation"
                        + " pool's thread and the tile worker to core 1): step %.2f ms median, %.2f ms p99 (%.2f"
                        + " times); %.0f steps took longer than 1.5 times the median, %.0f of them with the usual CPU"
                        + " time. Unpinned, this machine's scheduler now and then wakes a thread on a busy core while"
                        + " the other stays idle (docs/performance.md).", metres, pinned[0], pinned[1],
                        pinned[1] / pinned[0], pinned[2], pinned[3]));
                m.put("pinnedStepMedianMs", pinned[0]);
                m.put("pinnedStepP99Ms", pinned[1]);
                m.put("pinnedSlowSteps", pinned[2]);
            }
            if (mode != Mode.SMOKE) {
                // the same world with the camera standing where the walk ended: no tile arrives, the same plants
                // are animated at every step; what its steps spread by is the machine's, not the streaming's
                double[] stand = new double[600];
                double[] standCpu = new double[stand.length];
                double[] pair = new double[stand.length];
                // half a period after each step, in the same seconds, a fixed kernel of the frame's whole
                // step on two threads at once: what this machine gives any step that needs both cores
                double frameStepMs = Stats.median(java.util.Arrays.copyOf(frameMs, used));
                try (TwoThreadKernel kernel = new TwoThreadKernel(frameStepMs)) {
                    long next2 = System.nanoTime();
                    for (int f = 0; f < stand.length; f++) {
                        next2 += frameNanos;
                        kernel.arm(next2 + frameNanos / 2);
                        StepClock.sleepUntil(next2);
                        long c0 = clock.cpuNanos();
                        long t0 = System.nanoTime();
                        int n = Math.max(1, w.step(1 / RATE, cam));
                        stand[f] = (System.nanoTime() - t0) / 1e6 / n;
                        standCpu[f] = (clock.cpuNanos() - c0) / 1e6 / n;
                        pair[f] = kernel.run() / 1e6;
                    }
                }
                twoThreads = new double[] {Stats.median(pair), Stats.percentile(pair, 0.99), frameStepMs};
                standing = new double[] {Stats.median(stand), Stats.percentile(stand, 0.99),
                        Stats.percentile(standCpu, 0.99) / Stats.median(standCpu)};
                // then the machine's own spread for a step of that length, paced the same way
                floor = StepClock.floor(standing[0], RATE, stand.length);
            }
        }
        m.put("walkNsPerAnimatedComponent", walkNs);
        if (standing != null) {
            t.note(String.format(java.util.Locale.ROOT, "The camera then stood still where the walk ended for 20 s in "
                    + "real time (no tile arriving, the same plants animated at every step): step %.2f ms median, "
                    + "%.2f ms p99 (%.2f times; its CPU time %.2f times).", standing[0], standing[1],
                    standing[1] / standing[0], standing[2]));
            t.note(String.format(java.util.Locale.ROOT, "The machine's own spread: a fixed arithmetic kernel of about"
                    + " that step's length, on one thread, paced the same way for 20 s (parked between runs):"
                    + " %.2f ms median, %.2f ms p99 (%.2f times). The step's CPU time (the stepping thread and the"
                    + " animation pool's, summed) leaves out the time a thread waited to run; its ratio is the"
                    + " library's own spread.", floor[0], floor[1], floor[1] / floor[0]));
            m.put("standingStepMedianMs", standing[0]);
            m.put("standingStepP99Ms", standing[1]);
            m.put("standingStepCpuP99OverMedian", standing[2]);
            m.put("floorMedianMs", floor[0]);
            m.put("floorP99Ms", floor[1]);
            t.note(String.format(java.util.Locale.ROOT, "Standing, in the same 20 s, half a period after each"
                    + " step: a fixed kernel of the walk's whole step per frame (%.2f ms) on two threads at once,"
                    + " ending when both are done, as the walk's step needs both cores (the second thread wakes 1"
                    + " ms early and spins, as the animation pool's does before a step): %.2f ms median, %.2f ms"
                    + " p99 (%.2f times); what this machine gives any step that needs both its cores.",
                    twoThreads[2], twoThreads[0], twoThreads[1], twoThreads[1] / twoThreads[0]));
            m.put("twoThreadKernelMedianMs", twoThreads[0]);
            m.put("twoThreadKernelP99Ms", twoThreads[1]);
        }
        if (mode == Mode.SMOKE) {
            t.note("A smoke run walks a few metres within a radius of " + radius + " m and does not step the meadow "
                    + "for reference.");
        } else {
            double[] meadow = meadowSteps(def, mode);
            double meadowNs = meadow[0];
            t.note(String.format(java.util.Locale.ROOT, "The meadow itself (its own camera path, 2 workers, in real "
                    + "time after a warm-up as fast as it goes): %.2f ns per animated component per fixed step "
                    + "(median); the walk's %.2f, a ratio of %.2f. The meadow's step: %.2f ms median, %.2f ms p99 "
                    + "(%.2f times).", meadowNs, walkNs, walkNs / meadowNs, meadow[1], meadow[2], meadow[2] / meadow[1]));
            m.put("meadowNsPerAnimatedComponent", meadowNs);
        }
        raw.add(m);
        report.add(t);
        if (mode != Mode.SMOKE) {
            report.add(frames(def, placer, ground, mode == Mode.QUICK ? 150 : 600, raw));
        }
        report.raw("openWorld", raw);
    }

    /**
     * The open world drawn along the same kind of walk ({@code OpenWorldRenderer}: sky, each tile's
     * ground, the plants), 640x360 with 4 samples, on this machine's GL (thinned at the low quality on a
     * software rasteriser, as the viewer does), one frame after the other as fast as they go: step of
     * 1/30 s, render, glFinish. Allocates (a table).
     */
    private static Table frames(SimulationDef def, TilePlacer placer, RollingTerrain ground, int frames,
                                List<Object> raw) {
        int width = 640;
        int height = 360;
        double[] ms = new double[frames];
        double[] stepMs = new double[frames];
        String renderer;
        int made;
        int live;
        long waits;
        long waits0 = 0;
        try (OpenWorld w = OpenWorld.create(def, placer, RADIUS, 2, 1, 4);
             org.jecosys.render.GlContext gl = org.jecosys.render.GlContext.headless(
                     org.jecosys.render.GlContext.DebugOutput.OFF);
             org.jecosys.render.gl.GlFramebuffer fb = new org.jecosys.render.gl.GlFramebuffer(
                     org.jecosys.render.gl.GlContexts.tracker(gl), width, height, 4)) {
            renderer = gl.describe();
            if (org.jecosys.render.ShadowPath.software(renderer)) {
                org.jecosys.sim.DrawQuality q = org.jecosys.sim.DrawQuality.LOW;
                w.setThinning(q.thinStart(), q.thinEnd(), q.thinMinFraction());
            }
            org.jecosys.render.RenderSettings settings = org.jecosys.render.RenderSettings.standalone();
            ViewCamera cam = new ViewCamera();
            cam.setOrientation(Math.PI / 2, Math.toRadians(-8));
            cam.setLens(Math.toRadians(60), width / (double) height, 0.1, 1000);
            place(cam, ground, 0);
            w.load(cam);
            try (org.jecosys.render.OpenWorldRenderer r = new org.jecosys.render.OpenWorldRenderer(gl, w, settings)) {
                fb.bind();
                for (int k = 0; k < 256 && r.tileRenderers() < w.liveTiles(); k++) {
                    r.render(cam, width, height); // the loading screen makes every tile's renderer
                }
                waits0 = w.tileWaits();
                for (int f = 0; f < 30 + frames; f++) {
                    place(cam, ground, (f + 1) * SPEED / RATE);
                    long t0 = System.nanoTime();
                    w.step(1 / RATE, cam);
                    long t1 = System.nanoTime();
                    fb.bind();
                    r.render(cam, width, height);
                    gl.finish();
                    if (f >= 30) { // the first second warms up
                        ms[f - 30] = (System.nanoTime() - t0) / 1e6;
                        stepMs[f - 30] = (t1 - t0) / 1e6;
                    }
                }
                made = r.renderersMade();
            }
            live = w.liveTiles();
            waits = w.tileWaits() - waits0;
        }
        double median = Stats.median(ms);
        double p99 = Stats.percentile(ms, 0.99);
        double stepMedian = Stats.median(stepMs);
        double stepP99 = Stats.percentile(stepMs, 0.99);
        Table t = new Table("open-world-frames", "Open world drawn: the walk at 10 m/s, 640x360, 4 samples",
                List.of("frames", "frame ms (median)", "frame ms (p99)", "p99 / median", "step ms (median)",
                        "step ms (p99)", "step p99 / median", "tiles alive", "tile renderers made",
                        "waits for a tile"));
        t.row(frames, median, p99, p99 / median, stepMedian, stepP99, stepP99 / stepMedian, live, made, waits);
        t.note("GL renderer: " + renderer + ". A frame: the fixed steps of 1/30 s, the open world's renderer (sky, "
                + "each tile's ground, the plants; at most " + org.jecosys.render.OpenWorldRenderer.NEW_TILES_PER_FRAME
                + " tile renderers made a frame) and glFinish, one after the other; the first second not counted."
                + " The step columns time the frame's fixed steps alone (2 animation workers, 1 tile worker), with"
                + " the frame's drawing between them where the undrawn walk above parks its threads.");
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("frameMedianMs", median);
        m.put("frameP99Ms", p99);
        m.put("stepMedianMs", stepMedian);
        m.put("stepP99Ms", stepP99);
        raw.add(m);
        return t;
    }

    /**
     * The walk continued from {@code from} for {@code metres} in real time with the stepping thread pinned
     * to core 0 and the animation pool's and tile worker's threads to core 1 ({@link Affinity}), unpinned
     * after: {step median ms, p99 ms, slow steps, slow steps with the usual CPU time}.
     */
    private static double[] pinnedWalk(OpenWorld w, ViewCamera cam, RollingTerrain ground, double from,
                                       double metres, StepClock clock) {
        Affinity.pinCaller(0);
        Affinity.pinNamed("jecosys-world-", 1);
        Affinity.pinNamed("jecosys-tiles", 1);
        try {
            int frames = (int) Math.ceil(metres / SPEED * RATE);
            double[] ms = new double[frames];
            double[] cpu = new double[frames];
            int used = 0;
            long deadline = System.nanoTime();
            for (int f = 0; f < frames; f++) {
                place(cam, ground, from + (f + 1) * SPEED / RATE);
                deadline = StepClock.pace(deadline + (long) (1e9 / RATE));
                long c0 = clock.cpuNanos();
                long t0 = System.nanoTime();
                int n = w.step(1 / RATE, cam);
                long ns = System.nanoTime() - t0;
                if (n > 0) {
                    ms[used] = ns / 1e6 / n;
                    cpu[used] = (clock.cpuNanos() - c0) / 1e6 / n;
                    used++;
                }
            }
            double[] steps = java.util.Arrays.copyOf(ms, used);
            double[] slow = SlowSteps.count(steps, java.util.Arrays.copyOf(cpu, used));
            return new double[] {Stats.median(steps), Stats.percentile(steps, 0.99), slow[0], slow[1]};
        } finally {
            Affinity.pinCaller(-1);
            Affinity.pinNamed("jecosys-world-", -1);
            Affinity.pinNamed("jecosys-tiles", -1);
        }
    }

    private static void place(ViewCamera cam, RollingTerrain ground, double x) {
        cam.setPosition(x, ground.height(x, 0) + 1.7, 0);
    }

    /**
     * The meadow's step along its own camera path (2 workers): per animated component (ns, median), and
     * the step's median and 99th percentile (ms).
     */
    private double[] meadowSteps(SimulationDef def, Mode mode) throws Exception {
        SceneDef scene = SceneFiles.parse(scenes.resolve("meadow.xml"));
        World world = World.build(def, scenes, 2, Progress.NONE);
        try (Simulation sim = Simulation.of(world, def, 2)) {
            CameraWalk walk = new CameraWalk(scene.camera(), world.terrain().heightfield(), 16 / 9.0);
            int frames = mode == Mode.SMOKE ? 30 : 900;
            double[] ns = new double[frames];
            double[] ms = new double[frames];
            int used = 0;
            int timed = 0;
            long deadline = System.nanoTime();
            for (int f = 0; f < 2 * frames; f++) {
                ViewCamera cam = walk.at(f / RATE);
                if (f >= frames) { // the timed half in real time, as the walk
                    deadline += (long) (1e9 / RATE);
                    StepClock.sleepUntil(deadline);
                } else {
                    deadline = System.nanoTime();
                }
                long t0 = System.nanoTime();
                int n = sim.step(1 / RATE, cam);
                long dt = System.nanoTime() - t0;
                if (f >= frames && n > 0) {
                    ms[timed++] = dt / 1e6 / n;
                    int animated = sim.latestFrame().componentsAnimated();
                    if (animated > 0) {
                        ns[used++] = (double) dt / n / animated;
                    }
                }
            }
            double[] steps = java.util.Arrays.copyOf(ms, timed);
            return new double[] {Stats.median(java.util.Arrays.copyOf(ns, used)), Stats.median(steps),
                    Stats.percentile(steps, 0.99)};
        }
    }
}
