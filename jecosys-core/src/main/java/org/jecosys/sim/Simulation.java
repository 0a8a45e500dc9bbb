package org.jecosys.sim;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.ConcurrentLinkedQueue;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.anim.AnimationState;
import org.jecosys.anim.AnimationView;
import org.jecosys.anim.SpringKinds;
import org.jecosys.field.FieldBounds;
import org.jecosys.field.FieldCounters;
import org.jecosys.field.ForceField;
import org.jecosys.field.ForceFieldFactory;
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
    private final ForceField field;
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

    private Simulation(World world, SimulationDef def, int threads, int chunkComponents, ForceFieldFactory fields) {
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
        field = Require.nonNull("the force field factory's result",
                fields.create(new FieldBounds(hf.minX(), hf.minZ(), hf.maxX(), hf.maxZ(), hf.minHeight(),
                        hf.maxHeight() + plantHeight), def.field(), wind, xs.clone(), zs.clone()));
        if (field.plantCount() != plants) {
            throw new IllegalArgumentException("the force field must hold the world's " + plants + " plants, it holds "
                    + field.plantCount());
        }
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
     * @param def      terrain, species, distributions, flows, field and animation settings
     * @param baseDir  folder that relative image paths resolve against
     * @param progress receives the long generation steps
     * @return the simulation, at rest, time 0; the caller closes it
     * @throws IOException when an image of the def cannot be read
     */
    public static Simulation create(SimulationDef def, Path baseDir, Progress progress) throws IOException {
        return create(def, baseDir, progress, 0);
    }

    /**
     * Like {@link #create(SimulationDef, Path, Progress)} with {@code threads} animation workers, in
     * [0, 256]; 0 keeps the def's setting (whose 0 means the available processors).
     *
     * @param def      terrain, species, distributions, flows, field and animation settings
     * @param baseDir  folder that relative image paths resolve against
     * @param progress receives the long generation steps
     * @param threads  animation workers, in [0, 256]; 0 keeps the def's setting
     * @return the simulation, at rest, time 0; the caller closes it
     * @throws IOException when an image of the def cannot be read
     */
    public static Simulation create(SimulationDef def, Path baseDir, Progress progress, int threads)
            throws IOException {
        Require.nonNull("def", def);
        int t = workers(def, threads);
        World world = World.build(def, Require.nonNull("baseDir", baseDir), t, Require.nonNull("progress", progress));
        return new Simulation(world, def, t, CHUNK_COMPONENTS, ForceFieldFactory.QUADTREE);
    }

    /**
     * A simulation of an already built world (which must come from {@code def}), with the paper's
     * quadtree force field. Allocates; any thread.
     *
     * @param world   the world, built from {@code def} (e.g. {@link World#build})
     * @param def     what the world was built from: flows, field and animation settings
     * @param threads animation workers in [0, 256]; 0 keeps the def's setting
     * @return the simulation, at rest, time 0; the caller closes it
     */
    public static Simulation of(World world, SimulationDef def, int threads) {
        return of(world, def, threads, ForceFieldFactory.QUADTREE);
    }

    /**
     * A simulation of an already built world (which must come from {@code def}) whose force field
     * is built by {@code fields} instead of the paper's quadtree (paper §3, §5.1; see
     * {@link ForceFieldFactory} for the contract). The field gets the terrain's box (the tallest
     * plant included), {@code def.field()}, this simulation's {@link #windField()} and the plant
     * positions in the world's plant order. Build time; allocates; any thread.
     *
     * @param world   the world, built from {@code def} (e.g. {@link World#build})
     * @param def     what the world was built from: flows, field and animation settings
     * @param threads animation workers in [0, 256]; 0 keeps the def's setting (whose 0 means the
     *                available processors)
     * @param fields  builds the force field, called once on this thread
     * @return the simulation, at rest, time 0
     * @throws IllegalArgumentException on null arguments, a bad thread count, or a field that does
     *                                  not hold exactly the world's plants
     */
    public static Simulation of(World world, SimulationDef def, int threads, ForceFieldFactory fields) {
        Require.nonNull("world", world);
        Require.nonNull("def", def);
        Require.nonNull("fields", fields);
        return new Simulation(world, def, workers(def, threads), CHUNK_COMPONENTS, fields);
    }

    /** Like {@link #of} with another chunk size (components), for tests of the chunking itself. */
    static Simulation of(World world, SimulationDef def, int threads, int chunkComponents) {
        Require.range("chunkComponents", chunkComponents, 1, Integer.MAX_VALUE);
        return new Simulation(world, def, workers(def, threads), chunkComponents, ForceFieldFactory.QUADTREE);
    }

    private static int workers(SimulationDef def, int threads) {
        Require.range("threads", threads, 0, 256);
        int t = threads != 0 ? threads : def.animation().threads();
        return t != 0 ? t : Runtime.getRuntime().availableProcessors();
    }

    /**
     * Adds {@code dt} seconds of real time and runs the fixed steps it completes, at most
     * {@code maxSubSteps}; publishes a frame after each. Any finite {@code dt} is fine: after a long
     * pause (a breakpoint, a suspended game, a slow level load) the simulation runs
     * {@code maxSubSteps} steps, drops the rest of the backlog and counts it in
     * {@link #droppedSteps()} (the meadow slows down rather than spiral or jump). Stepping thread.
     * No allocation after warm-up.
     *
     * @param dt     elapsed real time, seconds, finite and &gt;= 0
     * @param camera the viewer, for visibility and level of detail (read, not kept)
     * @return fixed steps run, in [0, maxSubSteps]
     * @throws IllegalArgumentException when {@code dt} is negative, NaN or infinite, or the camera is null
     * @throws IllegalStateException    when the simulation is closed and a step is due
     */
    public int step(double dt, Camera camera) {
        Require.nonNegative("dt", dt);
        Require.nonNull("camera", camera);
        accumulator += dt;
        int n = 0;
        while (accumulator >= fixedStep && n < maxSubSteps) {
            stepFixed(camera);
            accumulator -= fixedStep;
            n++;
        }
        if (accumulator >= fixedStep) {
            long drop = (long) (accumulator / fixedStep); // saturates at Long.MAX_VALUE for absurd pauses
            droppedSteps = droppedSteps > Long.MAX_VALUE - drop ? Long.MAX_VALUE : droppedSteps + drop;
            accumulator -= drop * fixedStep;
            if (!(accumulator < fixedStep)) {
                accumulator = 0; // a pause so long that the remainder lost all precision: drop it too
            }
        }
        return n;
    }

    /**
     * Runs exactly one fixed step (ignoring the accumulator) and publishes its frame. Stepping thread.
     *
     * @param camera the viewer, for visibility and level of detail (read, not kept)
     * @throws IllegalStateException when the simulation is closed
     */
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
     *
     * @return the frame; read it until the next call
     */
    public Frame latestFrame() {
        return exchange.latest();
    }

    /**
     * Queues a new flow built from {@code def}. Any thread; allocates.
     *
     * @param def the flow; its id must not be in use when the command runs
     * @return its handle, for {@link #removeFlow}, {@link #setFlowEnabled} and {@link #moveAgent}
     */
    public WindSource addFlow(FlowDef def) {
        return addFlow(WindSource.of(def));
    }

    /**
     * Queues a flow, a built-in one or a game's own implementation (paper §3.2; see
     * {@link WindSource} and {@link org.jecosys.wind.AbstractWindSource}): from the next fixed step
     * on, the force field sums it with the other flows at every effective node, applies its enabled
     * switch and activation, and advances it with the clock, exactly like the scene's flows. After
     * this call the flow belongs to the stepping thread: switch it with {@link #setFlowEnabled}, move
     * it with {@link #moveAgent}, remove it with {@link #removeFlow}. Any thread; allocates a command.
     *
     * @param source the flow; its id must not be in use when the command runs (else the step that runs
     *               it throws IllegalArgumentException)
     * @return {@code source}, the handle
     */
    public WindSource addFlow(WindSource source) {
        Require.nonNull("source", source);
        commands.add(() -> wind.add(source));
        return source;
    }

    /**
     * Queues the removal of a flow or agent. Any thread; allocates a command.
     *
     * @param source the handle {@link #addFlow} or {@link #attachAgent} returned (a flow not held is ignored)
     */
    public void removeFlow(WindSource source) {
        Require.nonNull("source", source);
        commands.add(() -> wind.remove(source));
    }

    /**
     * Queues an agent: a flow (FIXED motion) the game moves with {@link #moveAgent}. Any thread;
     * allocates.
     *
     * @param def the agent's flow, e.g. a SOURCE around the player
     * @return its handle
     * @throws IllegalArgumentException when the motion is not FIXED
     */
    public WindSource attachAgent(FlowDef def) {
        Require.nonNull("def", def);
        if (def.motion().kind() != org.jecosys.wind.MotionDef.Kind.FIXED) {
            throw new IllegalArgumentException("an agent's motion must be FIXED (the game moves it), got "
                    + def.motion().kind());
        }
        return addFlow(def);
    }

    /**
     * Queues moving a flow's centre to (x, z). Any thread; allocates a command.
     *
     * @param agent the flow's handle: a built-in flow, or a user flow with a movable centre (an
     *              {@link org.jecosys.wind.AbstractWindSource}; the interface's default
     *              {@link WindSource#setCentre} throws, in the step that runs the command)
     * @param x     new centre X, metres (finite)
     * @param z     new centre Z, metres (finite)
     */
    public void moveAgent(WindSource agent, double x, double z) {
        Require.nonNull("agent", agent);
        Require.finite("x", x);
        Require.finite("z", z);
        commands.add(() -> agent.setCentre(x, z));
    }

    /**
     * Queues a blast: a short radial pulse at (x, z) metres of peak strength {@code strength} m^2/s
     * lasting {@code duration} s, removed once over ({@link WindField#blast}). Any thread; allocates.
     *
     * @param id       unique flow id while the blast lasts
     * @param x        centre X, metres (finite)
     * @param z        centre Z, metres (finite)
     * @param strength peak strength, m^2/s, &gt; 0
     * @param duration seconds, &gt; 0
     */
    public void blast(String id, double x, double z, double strength, double duration) {
        Require.nonNull("id", id);
        Require.finite("x", x);
        Require.finite("z", z);
        Require.positive("strength", strength);
        Require.positive("duration", duration);
        commands.add(() -> wind.blast(id, x, z, strength, duration));
    }

    /**
     * Queues switching a flow on or off. Any thread; allocates a command.
     *
     * @param source  the flow's handle
     * @param enabled whether it acts
     */
    public void setFlowEnabled(WindSource source, boolean enabled) {
        Require.nonNull("source", source);
        commands.add(() -> source.setEnabled(enabled));
    }

    /**
     * Queues a change of animation mode (paper Table 7). Any thread; allocates a command.
     *
     * @param mode static, random or constraint
     */
    public void setMode(AnimationMode mode) {
        Require.nonNull("mode", mode);
        commands.add(() -> this.mode = mode);
    }

    /**
     * Queues switching the force field on or off (see the class comment). Any thread; allocates a command.
     *
     * @param enabled whether the field evaluates flows and culls plants
     */
    public void setFieldEnabled(boolean enabled) {
        commands.add(() -> fieldEnabled = enabled);
    }

    /**
     * Queues a scale of every species' level-of-detail distances, in [0.01, 100] (2 keeps detail
     * twice as far). Any thread; allocates a command.
     *
     * @param scale factor on every level-of-detail distance, in [0.01, 100]
     */
    public void setLodScale(double scale) {
        Require.range("scale", scale, 0.01, 100);
        commands.add(() -> state.setLodScale(scale));
    }

    /** {@return the animation mode of the last step} Stepping thread. */
    public AnimationMode mode() {
        return mode;
    }

    /** {@return whether the force field was on in the last step} Stepping thread. */
    public boolean fieldEnabled() {
        return fieldEnabled;
    }

    /** {@return the static world} Any thread. */
    public World world() {
        return world;
    }

    /** {@return the def this simulation was built from} Any thread. */
    public SimulationDef def() {
        return def;
    }

    /** {@return the number of plants} Any thread. */
    public int plantCount() {
        return world.plantCount();
    }

    /** {@return the number of components} Any thread. */
    public int componentCount() {
        return world.componentCount();
    }

    /**
     * {@return the number of threads that animate: the pool's threads and the stepping thread, which
     * helps} Any thread.
     */
    public int workers() {
        return pool.workers();
    }

    /** {@return the number of fixed chunks of plants} Any thread. */
    public int chunks() {
        return chunkAnimator.chunks();
    }

    /** {@return the fixed step, seconds} Any thread. */
    public double fixedStep() {
        return fixedStep;
    }

    /** {@return the number of fixed steps run so far} Stepping thread. */
    public long steps() {
        return steps;
    }

    /** {@return the simulation time, seconds (fixed steps x fixed step)} Stepping thread. */
    public double time() {
        return time;
    }

    /** {@return the number of fixed steps dropped by the sub-step cap so far} Stepping thread. */
    public long droppedSteps() {
        return droppedSteps;
    }

    /**
     * A read-only view of the animated state (deviations, velocities, outputs, levels), for reading
     * between steps. Stepping thread; the view allocates nothing.
     *
     * @return the live view (not a copy: it changes with every step)
     */
    public AnimationView state() {
        return state;
    }

    /**
     * The force field: the paper's quadtree ({@code org.jecosys.field.QuadtreeForceField}) unless
     * the simulation was built with another {@link ForceFieldFactory}. Its debug view and counters
     * reflect the update for the next step. Stepping thread; read it, do not add or move plants.
     *
     * @return the field
     */
    public ForceField forceField() {
        return field;
    }

    /** {@return the counters of the field's last update} Stepping thread. */
    public FieldCounters fieldCounters() {
        return field.counters();
    }

    /** {@return the wind flows} Stepping thread (add flows through {@link #addFlow} from other threads). */
    public WindField windField() {
        return wind;
    }

    /**
     * {@return the wind X (m/s) at plant p's node that the last step used} Stepping thread.
     *
     * @param p world plant index, in [0, plantCount())
     */
    public float windX(int p) {
        return windX[1 - current][p];
    }

    /**
     * {@return the wind Z (m/s) at plant p's node that the last step used} Stepping thread.
     *
     * @param p world plant index, in [0, plantCount())
     */
    public float windZ(int p) {
        return windZ[1 - current][p];
    }

    /**
     * {@return whether plant p was visible in the last step} Stepping thread.
     *
     * @param p world plant index, in [0, plantCount())
     */
    public boolean plantVisible(int p) {
        return visible[1 - current][p];
    }

    /** {@return the {@link AnimationState#stateHash()} of the current state} Stepping thread, between steps. */
    public long stateHash() {
        return state.stateHash();
    }

    /** {@return the ids of the pool's worker threads, {@link #workers()} - 1 of them} Allocates; any thread. */
    public long[] workerThreadIds() {
        return pool.threadIds();
    }

    /**
     * Bytes allocated so far by every worker thread and by the last stepping thread
     * ({@code com.sun.management.ThreadMXBean#getThreadAllocatedBytes}); -1 when the JVM cannot tell.
     * Any thread; allocates nothing itself.
     *
     * @return bytes, or -1
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
