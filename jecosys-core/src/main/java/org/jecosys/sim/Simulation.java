package org.jecosys.sim;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.ConcurrentLinkedQueue;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.anim.AnimationState;
import org.jecosys.anim.SpringKinds;
import org.jecosys.field.FieldCounters;
import org.jecosys.field.QuadtreeForceField;
import org.jecosys.math.Progress;
import org.jecosys.math.Require;
import org.jecosys.math.Rng;
import org.jecosys.math.Camera;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.WindField;
import org.jecosys.wind.WindSource;

/**
 * A running meadow for embedding in a game or tool (paper §5.1): the wind flows, the LOD quadtree
 * force field (§3), the dynamic-constraint animation of every component (§4.2) on worker threads,
 * and the published frames the renderer reads. See the package documentation for a game loop.
 *
 * <h2>Stepping</h2>
 * {@link #step(double, Camera)} adds real time to an accumulator and runs as many fixed steps
 * ({@link AnimationDef#fixedStep()}) as it holds, at most {@link AnimationDef#maxSubSteps()}; the
 * backlog beyond that is dropped (the meadow slows down rather than spiral). One fixed step:
 * <ol>
 * <li>the queued commands (flows, agents, mode, field, LOD) are applied;</li>
 * <li>the workers animate fixed chunks of plants ({@code ChunkAnimator}) from the force field's result
 * for the end of this step, writing the back frame;</li>
 * <li>at the same time the stepping thread advances the wind clock and updates the force field for
 * the end of the <em>next</em> step (visibility and LOD from the camera given now), so the field and
 * the animation run concurrently (§5.1) without either waiting for the other's data, then helps with
 * the chunks left. Visibility thus follows the camera one fixed step late. With N workers, N - 1
 * pool threads and the stepping thread animate; with 1, the stepping thread does everything;</li>
 * <li>the frame is published (triple buffering, {@link FrameExchange}).</li>
 * </ol>
 * With the field off ({@link #setFieldEnabled}) no flow is evaluated and no culling is done: every
 * plant is visible and feels no wind (paper Table 6's "Force field disabled").
 *
 * <h2>Determinism</h2>
 * Chunks are fixed by the world (about {@value #CHUNK_COMPONENTS} components each), random mode uses
 * one random stream per chunk, and nothing sums floating-point values across chunks, so the state
 * (see {@link #stateHash()}) is bit-identical for any number of workers.
 *
 * <h2>Threads</h2>
 * <ul>
 * <li>{@link #step}, {@link #stepFixed}, {@link #stateHash}, {@link #state}, {@link #forceField},
 * {@link #windX}/{@link #windZ} and the other inspection methods: one <em>stepping thread</em> at a
 * time (the game loop), never concurrently with a step.</li>
 * <li>{@link #latestFrame()}: one reader thread (the renderer), concurrently with steps; it never
 * blocks and never sees a frame being written.</li>
 * <li>Commands ({@link #addFlow}, {@link #removeFlow}, {@link #attachAgent}, {@link #moveAgent},
 * {@link #setFlowEnabled}, {@link #setMode}, {@link #setFieldEnabled}, {@link #setLodScale}): any
 * thread; queued and applied at the start of the next fixed step. They allocate a small command;
 * steps allocate nothing after warm-up, on the stepping thread and on every worker.</li>
 * <li>{@link #close()}: stops the workers; call it once no step runs. Idempotent.</li>
 * </ul>
 */
public final class Simulation implements AutoCloseable {
    /** Target components per fixed chunk of plants. */
    public static final int CHUNK_COMPONENTS = 8192;

    private final World world;
    private final SimulationDef def;
    private final WindField wind;
    private final QuadtreeForceField field;
    private final SpringKinds kinds;
    private final AnimationState state;
    private final FrameExchange exchange;
    private final WorkerPool pool;
    private final ChunkAnimator chunkAnimator;
    private final float[][] windX = new float[2][];
    private final float[][] windZ = new float[2][];
    private final boolean[][] visible = new boolean[2][];
    private final double[][] eye = new double[2][3];
    private final ConcurrentLinkedQueue<Runnable> commands = new ConcurrentLinkedQueue<>();
    private final double fixedStep;
    private final int maxSubSteps;
    private final int subIntervals;

    private AnimationMode mode;
    private boolean fieldEnabled;
    private double accumulator;
    private boolean primed;
    private int current;
    private long steps;
    private double time;
    private long droppedSteps;
    private volatile long steppingThread = -1;
    private boolean closed;
    boolean stampFrames;

    private Simulation(World world, SimulationDef def, int threads, int chunkComponents) {
        this.world = world;
        this.def = def;
        AnimationDef ad = def.animation();
        fixedStep = ad.fixedStep();
        maxSubSteps = ad.maxSubSteps();
        subIntervals = ad.subIntervals();
        mode = ad.mode();
        fieldEnabled = def.field().enabled();
        wind = WindField.of(def.flows());
        Heightfield hf = world.terrain().heightfield();
        int plants = world.plantCount();
        float[] xs = new float[plants];
        float[] zs = new float[plants];
        float[] ys = new float[plants];
        for (int p = 0; p < plants; p++) {
            xs[p] = world.plantX(p);
            ys[p] = world.plantY(p);
            zs[p] = world.plantZ(p);
        }
        double plantHeight = 0;
        for (SpeciesDef s : def.species()) {
            double h = 0;
            for (var c : s.components()) {
                h += c.length();
            }
            plantHeight = Math.max(plantHeight, h);
        }
        field = QuadtreeForceField.build(def.field(), hf.minX(), hf.minZ(), hf.maxX(), hf.maxZ(), hf.minHeight(),
                hf.maxHeight() + plantHeight, wind, xs, zs);
        kinds = SpringKinds.of(world.plants().species());
        int comps = world.componentCount();
        int[] first = new int[plants + 1];
        for (int p = 0; p < plants; p++) {
            first[p] = world.firstComponent(p);
        }
        first[plants] = comps;
        state = AnimationStates.of(world, kinds, first, xs, ys, zs);
        for (int b = 0; b < 2; b++) {
            windX[b] = new float[plants];
            windZ[b] = new float[plants];
            visible[b] = new boolean[plants];
        }
        exchange = new FrameExchange(plants, comps);
        for (int i = 0; i < 3; i++) {
            Frame f = exchange.frame(i);
            state.copyOutputs(0, comps, f.poseCoord, f.bendAzimuth);
        }
        chunkAnimator = new ChunkAnimator(state, first, plants, chunkComponents, windX, windZ, visible, eye,
                ad.seed());
        pool = new WorkerPool("jecosys-anim", threads, chunkAnimator.chunks(), chunkAnimator);
    }

    /**
     * Builds the world of {@code def} (terrain, species, distribution) and a simulation of it, with
     * the def's worker count (0: the available processors). Build time; allocates; any thread.
     *
     * @param baseDir  folder that relative image paths resolve against
     * @param progress receives the long generation steps
     * @throws IOException when an image of the def cannot be read
     */
    public static Simulation create(SimulationDef def, Path baseDir, Progress progress) throws IOException {
        return create(def, baseDir, progress, 0);
    }

    /**
     * Like {@link #create(SimulationDef, Path, Progress)} with {@code threads} animation workers, in
     * [0, 256]; 0 keeps the def's setting (whose 0 means the available processors).
     */
    public static Simulation create(SimulationDef def, Path baseDir, Progress progress, int threads)
            throws IOException {
        Require.nonNull("def", def);
        int t = workers(def, threads);
        World world = World.build(def, Require.nonNull("baseDir", baseDir), t, Require.nonNull("progress", progress));
        return new Simulation(world, def, t, CHUNK_COMPONENTS);
    }

    /** A simulation of an already built world (which must come from {@code def}). Allocates; any thread. */
    public static Simulation of(World world, SimulationDef def, int threads) {
        Require.nonNull("world", world);
        Require.nonNull("def", def);
        return new Simulation(world, def, workers(def, threads), CHUNK_COMPONENTS);
    }

    /** Like {@link #of} with another chunk size (components), for tests of the chunking itself. */
    static Simulation of(World world, SimulationDef def, int threads, int chunkComponents) {
        Require.range("chunkComponents", chunkComponents, 1, Integer.MAX_VALUE);
        return new Simulation(world, def, workers(def, threads), chunkComponents);
    }

    private static int workers(SimulationDef def, int threads) {
        Require.range("threads", threads, 0, 256);
        int t = threads != 0 ? threads : def.animation().threads();
        return t != 0 ? t : Runtime.getRuntime().availableProcessors();
    }

    /**
     * Adds {@code dt} seconds of real time and runs the fixed steps it completes, at most
     * {@code maxSubSteps}; publishes a frame after each. Stepping thread. No allocation after warm-up.
     *
     * @param dt     elapsed time, seconds, in [0, 10]
     * @param camera the viewer, for visibility and level of detail (read, not kept)
     * @return fixed steps run
     */
    public int step(double dt, Camera camera) {
        Require.range("dt", dt, 0, 10);
        Require.nonNull("camera", camera);
        accumulator += dt;
        int n = 0;
        while (accumulator >= fixedStep && n < maxSubSteps) {
            stepFixed(camera);
            accumulator -= fixedStep;
            n++;
        }
        if (accumulator >= fixedStep) {
            long drop = (long) (accumulator / fixedStep);
            droppedSteps += drop;
            accumulator -= drop * fixedStep;
        }
        return n;
    }

    /** Runs exactly one fixed step (ignoring the accumulator) and publishes its frame. Stepping thread. */
    public void stepFixed(Camera camera) {
        Require.nonNull("camera", camera);
        if (closed) {
            throw new IllegalStateException("the simulation is closed");
        }
        steppingThread = Thread.currentThread().getId();
        drainCommands();
        kinds.prepare(fixedStep, subIntervals);
        if (!primed) {
            updateField(camera, current);
            primed = true;
        }
        Frame f = exchange.back();
        chunkAnimator.prepare(mode, current, f, exchange.backIndex(), exchange.lastPublished(), steps, stampFrames);
        long t0 = System.nanoTime();
        pool.start();
        updateField(camera, 1 - current);
        long fieldNanos = System.nanoTime() - t0;
        pool.await();
        long animNanos = System.nanoTime() - t0;
        current = 1 - current;
        steps++;
        time += fixedStep;
        f.number = steps;
        f.time = time;
        f.componentsAnimated = chunkAnimator.animated();
        f.fieldNanos = fieldNanos;
        f.animationNanos = animNanos;
        exchange.publish();
    }

    /** Advances the wind one fixed step and writes the field's result for its end into buffer b. */
    private void updateField(Camera camera, int b) {
        wind.advance(fixedStep);
        eye[b][0] = camera.x();
        eye[b][1] = camera.y();
        eye[b][2] = camera.z();
        int n = world.plantCount();
        if (fieldEnabled) {
            field.update(camera);
            field.gather(0, n, windX[b], windZ[b], visible[b]);
        } else {
            java.util.Arrays.fill(windX[b], 0f);
            java.util.Arrays.fill(windZ[b], 0f);
            java.util.Arrays.fill(visible[b], true);
        }
    }

    private void drainCommands() {
        for (Runnable r = commands.poll(); r != null; r = commands.poll()) {
            r.run();
        }
    }

    /**
     * The newest published frame (complete; unchanged until this reader calls again). Before the
     * first step: the rest state, number 0. One reader thread. No allocation.
     */
    public Frame latestFrame() {
        return exchange.latest();
    }

    /** Queues a new flow built from {@code def}; returns its handle (use it for {@link #removeFlow}). Any thread; allocates. */
    public WindSource addFlow(FlowDef def) {
        WindSource s = WindSource.of(def);
        commands.add(() -> wind.add(s));
        return s;
    }

    /** Queues the removal of a flow or agent. Any thread; allocates a command. */
    public void removeFlow(WindSource source) {
        Require.nonNull("source", source);
        commands.add(() -> wind.remove(source));
    }

    /**
     * Queues an agent: a flow (FIXED motion) the game moves with {@link #moveAgent}. Any thread;
     * allocates.
     */
    public WindSource attachAgent(FlowDef def) {
        Require.nonNull("def", def);
        if (def.motion().kind() != org.jecosys.wind.MotionDef.Kind.FIXED) {
            throw new IllegalArgumentException("an agent's motion must be FIXED (the game moves it), got "
                    + def.motion().kind());
        }
        return addFlow(def);
    }

    /** Queues moving a flow's centre to (x, z), metres. Any thread; allocates a command. */
    public void moveAgent(WindSource agent, double x, double z) {
        Require.nonNull("agent", agent);
        Require.finite("x", x);
        Require.finite("z", z);
        commands.add(() -> agent.setCentre(x, z));
    }

    /**
     * Queues a blast: a short radial pulse at (x, z) metres of peak strength {@code strength} m^2/s
     * lasting {@code duration} s, removed once over ({@link WindField#blast}). Any thread; allocates.
     */
    public void blast(String id, double x, double z, double strength, double duration) {
        Require.nonNull("id", id);
        Require.finite("x", x);
        Require.finite("z", z);
        Require.positive("strength", strength);
        Require.positive("duration", duration);
        commands.add(() -> wind.blast(id, x, z, strength, duration));
    }

    /** Queues switching a flow on or off. Any thread; allocates a command. */
    public void setFlowEnabled(WindSource source, boolean enabled) {
        Require.nonNull("source", source);
        commands.add(() -> source.setEnabled(enabled));
    }

    /** Queues a change of animation mode (paper Table 7). Any thread; allocates a command. */
    public void setMode(AnimationMode mode) {
        Require.nonNull("mode", mode);
        commands.add(() -> this.mode = mode);
    }

    /** Queues switching the force field on or off (see the class comment). Any thread; allocates a command. */
    public void setFieldEnabled(boolean enabled) {
        commands.add(() -> fieldEnabled = enabled);
    }

    /**
     * Queues a scale of every species' level-of-detail distances, in [0.01, 100] (2 keeps detail
     * twice as far). Any thread; allocates a command.
     */
    public void setLodScale(double scale) {
        Require.range("scale", scale, 0.01, 100);
        commands.add(() -> state.setLodScale(scale));
    }

    /** The animation mode of the last step (stepping thread). */
    public AnimationMode mode() {
        return mode;
    }

    /** Whether the force field was on in the last step (stepping thread). */
    public boolean fieldEnabled() {
        return fieldEnabled;
    }

    /** The static world. Any thread. */
    public World world() {
        return world;
    }

    /** The def this simulation was built from. Any thread. */
    public SimulationDef def() {
        return def;
    }

    /** Number of plants. Any thread. */
    public int plantCount() {
        return world.plantCount();
    }

    /** Number of components. Any thread. */
    public int componentCount() {
        return world.componentCount();
    }

    /** Threads that animate: the pool's threads and the stepping thread, which helps. Any thread. */
    public int workers() {
        return pool.workers();
    }

    /** Fixed chunks of plants. Any thread. */
    public int chunks() {
        return chunkAnimator.chunks();
    }

    /** The fixed step, seconds. Any thread. */
    public double fixedStep() {
        return fixedStep;
    }

    /** Fixed steps run so far. Stepping thread. */
    public long steps() {
        return steps;
    }

    /** Simulation time, seconds (fixed steps x fixed step). Stepping thread. */
    public double time() {
        return time;
    }

    /** Fixed steps dropped by the sub-step cap so far. Stepping thread. */
    public long droppedSteps() {
        return droppedSteps;
    }

    /** The animated state, for reading between steps (do not modify). Stepping thread. */
    public AnimationState state() {
        return state;
    }

    /** The force field (its debug view and counters reflect the update for the next step). Stepping thread. */
    public QuadtreeForceField forceField() {
        return field;
    }

    /** Counters of the field's last update. Stepping thread. */
    public FieldCounters fieldCounters() {
        return field.counters();
    }

    /** The wind flows. Stepping thread (add flows through {@link #addFlow} from other threads). */
    public WindField windField() {
        return wind;
    }

    /** Wind X (m/s) at plant p's node that the last step used. Stepping thread. */
    public float windX(int p) {
        return windX[1 - current][p];
    }

    /** Wind Z (m/s) at plant p's node that the last step used. Stepping thread. */
    public float windZ(int p) {
        return windZ[1 - current][p];
    }

    /** Whether plant p was visible in the last step. Stepping thread. */
    public boolean plantVisible(int p) {
        return visible[1 - current][p];
    }

    /** {@link AnimationState#stateHash()} of the current state. Stepping thread, between steps. */
    public long stateHash() {
        return state.stateHash();
    }

    /** Ids of the pool's worker threads, {@link #workers()} - 1 of them (allocates). Any thread. */
    public long[] workerThreadIds() {
        return pool.threadIds();
    }

    /**
     * Bytes allocated so far by every worker thread and by the last stepping thread
     * ({@code com.sun.management.ThreadMXBean#getThreadAllocatedBytes}); -1 when the JVM cannot tell.
     * Any thread; allocates nothing itself.
     */
    public long allocatedBytes() {
        return pool.allocatedBytes(steppingThread);
    }

    /** Stops the workers. Idempotent; call it when no step runs. */
    @Override
    public void close() {
        closed = true;
        pool.close();
    }
}
