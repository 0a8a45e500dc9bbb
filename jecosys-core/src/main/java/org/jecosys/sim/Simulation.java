package org.jecosys.sim;

import java.io.IOException;
import java.nio.file.Path;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.anim.SpringKinds;
import org.jecosys.field.ForceFieldFactory;
import org.jecosys.math.Progress;
import org.jecosys.math.Require;
import org.jecosys.math.Camera;
import org.jecosys.terrain.ImageSource;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.WindField;
import org.jecosys.wind.WindSource;

/**
 * A running meadow for embedding in a game or tool (paper §5.1): the wind flows, the LOD quadtree
 * force field (§3), the dynamic-constraint animation of every component (§4.2) on worker threads,
 * and the published frames the renderer reads. See the package documentation for a game loop.
 *
 * <p>How a step runs, how the meadow starts in the wind, why the state is the same for any number
 * of workers, and which thread may call what: the package documentation ("How a simulation steps",
 * "Start", "Determinism", "Threads"); each method says its thread too.
 */
public final class Simulation implements AutoCloseable {
    /** Target components per fixed chunk of plants. */
    public static final int CHUNK_COMPONENTS = 8192;
    /**
     * Most commands waiting for the next step; a command method called past it throws
     * IllegalStateException and queues nothing.
     */
    public static final int MAX_PENDING_COMMANDS = 16_384;
    /**
     * Most flows a simulation holds at once: the scene's, agents, blasts and a game's own flows
     * together, queued ones included (the scene format allows 256).
     */
    public static final int MAX_FLOWS = 1024;
    /** Most views a step follows: its camera and {@code MAX_VIEWS - 1} registered with {@link #addView}. */
    public static final int MAX_VIEWS = org.jecosys.field.QuadtreeForceField.MAX_VIEWS;

    private final World world;
    private final SimulationDef def;
    /** The running parts and the fixed-step loop (package tests set its {@code stampFrames}). */
    final StepLoop loop;
    private final DetailCommands detail;
    private final Inspection inspection;

    /** The simulation's parts; {@code kinds}: its species' kinds prepared (copied: a tile's) or null (built). */
    Simulation(World world, SimulationDef def, int workers, int chunks, ForceFieldFactory fields, SpringKinds kinds) {
        this.world = world;
        this.def = def;
        loop = new StepLoop(world, def, workers, chunks, fields, kinds);
        detail = new DetailCommands(world, loop.commands, loop.state, loop.draw);
        inspection = new Inspection(loop);
    }

    /**
     * Builds the world of {@code def} (terrain, species, distribution) and a simulation of it with
     * {@code workers} animation workers, in [0, 256]; 0 keeps the def's setting
     * ({@link AnimationDef#workers()}, whose 0 means the available processors). Build time; allocates;
     * any thread.
     *
     * @param def      terrain, species, distributions, flows, field and animation settings
     * @param baseDir  folder that relative image paths resolve against; images must lie in its tree
     *                 ({@link ImageSource#folder})
     * @param workers  animation workers, in [0, 256]; 0 keeps the def's setting
     * @param progress receives the long generation steps
     * @return the simulation at time 0, in the wind of t = 0 (the package documentation's "Start"); the caller closes it
     * @throws IOException when an image of the def cannot be read
     */
    public static Simulation create(SimulationDef def, Path baseDir, int workers, Progress progress)
            throws IOException {
        return create(def, ImageSource.folder(Require.nonNull("baseDir", baseDir)), workers, progress);
    }

    /**
     * Like {@link #create(SimulationDef, Path, int, Progress)} with the images the def names read
     * from {@code images} (e.g. {@code org.jecosys.scene.Scene#images()}: the bytes checked when the
     * scene was read, or a game's assets).
     *
     * @param def      terrain, species, distributions, flows, field and animation settings
     * @param images   where the heightmap and resource images come from
     * @param workers  animation workers, in [0, 256]; 0 keeps the def's setting
     * @param progress receives the long generation steps
     * @return the simulation at time 0, in the wind of t = 0 (the package documentation's "Start"); the caller closes it
     * @throws IOException when an image of the def cannot be read or decoded
     */
    public static Simulation create(SimulationDef def, ImageSource images, int workers, Progress progress)
            throws IOException {
        int w = workerCount(Require.nonNull("def", def), workers);
        World world = World.build(def, Require.nonNull("images", images), w, Require.nonNull("progress", progress));
        return new Simulation(world, def, w, CHUNK_COMPONENTS, ForceFieldFactory.QUADTREE, null);
    }

    /**
     * A simulation of an already built world (which must come from {@code def}), with the paper's
     * quadtree force field. Allocates; any thread.
     *
     * @param world   the world, built from {@code def} (e.g. {@link World#build})
     * @param def     what the world was built from: flows, field and animation settings
     * @param workers animation workers in [0, 256]; 0 keeps the def's setting
     * @return the simulation at time 0, in the wind of t = 0 (the package documentation's "Start"); the caller closes it
     */
    public static Simulation of(World world, SimulationDef def, int workers) {
        return of(world, def, workers, ForceFieldFactory.QUADTREE);
    }

    /**
     * A simulation of an already built world (which must come from {@code def}) whose force field
     * is built by {@code fields} instead of the paper's quadtree (paper §3, §5.1; see
     * {@link ForceFieldFactory} for the contract). The field gets the terrain's box (the tallest
     * plant included), {@code def.field()}, this simulation's wind field ({@link Inspection#windField()}) and the plant
     * positions in the world's plant order. Build time; allocates; any thread.
     *
     * @param world   the world, built from {@code def} (e.g. {@link World#build})
     * @param def     what the world was built from: flows, field and animation settings
     * @param workers animation workers in [0, 256]; 0 keeps the def's setting (whose 0 means the
     *                available processors)
     * @param fields  builds the force field, called once on this thread
     * @return the simulation at time 0, in the wind of t = 0 (the package documentation's "Start")
     * @throws IllegalArgumentException on null arguments, a bad worker count, or a field that does
     *                                  not hold exactly the world's plants
     */
    public static Simulation of(World world, SimulationDef def, int workers, ForceFieldFactory fields) {
        Require.nonNull("world", world);
        Require.nonNull("def", def);
        Require.nonNull("fields", fields);
        return new Simulation(world, def, workerCount(def, workers), CHUNK_COMPONENTS, fields, null);
    }

    /** Like {@link #of} with another chunk size (components), for tests of the chunking itself. */
    static Simulation of(World world, SimulationDef def, int workers, int chunkComponents) {
        Require.range("chunkComponents", chunkComponents, 1, Integer.MAX_VALUE);
        return new Simulation(world, def, workerCount(def, workers), chunkComponents, ForceFieldFactory.QUADTREE, null);
    }

    private static int workerCount(SimulationDef def, int workers) {
        Require.range("workers", workers, 0, 256);
        int w = workers != 0 ? workers : def.animation().workers();
        return w != 0 ? w : Runtime.getRuntime().availableProcessors();
    }

    /**
     * Adds {@code dt} seconds of real time and runs the fixed steps it completes, at most
     * {@code maxSubSteps}; publishes a frame after each. Any finite {@code dt} is fine: after a long
     * pause (a breakpoint, a suspended game, a slow level load) the simulation runs
     * {@code maxSubSteps} steps, drops the rest of the backlog and counts it in
     * {@link Inspection#droppedSteps()} (the meadow slows down rather than spiral or jump). Stepping thread.
     * No allocation after warm-up.
     *
     * <p>When a game's own code throws during a step (its {@link Camera}, an
     * {@link org.jecosys.wind.AbstractWindSource} it added), the exception reaches the caller as it
     * is, after the workers finished the fixed step's chunks: that step's frame is not published, the
     * plants keep its motion, and the next call steps normally.
     *
     * <p>The first call to this method or {@link #stepFixed} first runs the def's prewarm
     * ({@link org.jecosys.anim.AnimationDef#prewarm()}, 0 by default) with its camera: that many fixed
     * steps, not counted in the return value nor against maxSubSteps, so the first frame is already in
     * motion (the meadow's 1 s, 60 steps of 2.7 ms each on two cores, adds about 0.2 s to its first step).
     *
     * @param dt     elapsed real time, seconds, finite and &gt;= 0
     * @param camera the viewer, for visibility and level of detail (read, not kept)
     * @return fixed steps run, in [0, maxSubSteps]
     * @throws IllegalArgumentException when {@code dt} is negative, NaN or infinite, the camera is
     *                                  null, or the eye or view-projection matrix of the camera or of
     *                                  a registered view is not finite (checked each fixed step,
     *                                  before anything moves)
     * @throws IllegalStateException    when the simulation is closed (a step that {@link #close()}
     *                                  interrupts from another thread returns after the fixed step it
     *                                  runs, and the next call throws)
     */
    public int step(double dt, Camera camera) {
        Require.nonNegative("dt", dt);
        Require.nonNull("camera", camera);
        return loop.step(dt, camera);
    }

    /**
     * Runs exactly one fixed step (ignoring the accumulator) and publishes its frame; the first call runs
     * the prewarm first, as {@link #step} does. Stepping thread.
     *
     * @param camera the viewer, for visibility and level of detail (read, not kept)
     * @throws IllegalStateException when the simulation is closed
     */
    public void stepFixed(Camera camera) {
        Require.nonNull("camera", camera);
        loop.stepFixed(camera);
    }

    /**
     * Registers a further view the steps animate for, besides the camera given to each step: a second
     * player's camera, a minimap, a shadow map's light. Plants any registered view sees are animated
     * (the force field and the animation follow the union of the views, paper §3.1.1), each at the
     * finest level of detail any view asks, levels picked by projected size
     * ({@link org.jecosys.math.ViewLod}). The step reads the camera object each fixed step (one
     * step late, as it reads the step's camera), so keep it current on the stepping thread. Drawing
     * works for any camera whether registered or not (a renderer decides for a camera the step did not
     * follow); registering only keeps what it sees animated. Any thread; allocates a small array.
     *
     * @param view the camera, kept by reference until {@link #removeView}
     * @throws IllegalArgumentException when it is null or already registered, or its eye or
     *                                  view-projection matrix is not finite (NaN or infinite)
     * @throws IllegalStateException    when {@link #MAX_VIEWS} - 1 views are registered, or the simulation
     *                                  is closed
     */
    public void addView(Camera view) {
        Require.nonNull("view", view);
        loop.addView(view);
    }

    /**
     * Stops animating for a view registered with {@link #addView}. Any thread; allocates a small array.
     *
     * @param view the camera
     * @return whether it was registered
     * @throws IllegalStateException when the simulation is closed
     */
    public boolean removeView(Camera view) {
        return loop.removeView(view);
    }

    /**
     * The newest published frame (complete; unchanged until this reader calls again). Before the
     * first step: the rest state, number 0. One reader thread: the first thread that calls it (the
     * renderer, or the game loop); once that thread has ended another may take over. Other threads
     * read with {@link #copyLatestFrame(Frame)}. No allocation.
     *
     * @return the frame; read it until the next call
     * @throws IllegalStateException when called from a second thread while the reader thread lives
     */
    public Frame latestFrame() {
        return loop.exchange.latest();
    }

    /**
     * Copies the newest published frame into the caller's {@code dest}: for any number of reader
     * threads besides the one of {@link #latestFrame()} (tools, recorders, a second view). The copy is
     * complete, never torn, and frame numbers a thread copies never go back; it never blocks the
     * step. Any thread; no allocation (copies every component: about 1 ms per million components).
     *
     * @param dest a frame of {@link #plantCount()} plants and {@link #componentCount()} components
     *             ({@code new Frame(sim.plantCount(), sim.bendGeometry())}), owned by the caller
     * @return {@code dest}
     * @throws IllegalArgumentException when {@code dest} is null or of other sizes
     */
    public Frame copyLatestFrame(Frame dest) {
        return loop.exchange.copyLatest(dest);
    }

    /**
     * Queues a new flow built from {@code def}. Any thread; allocates.
     *
     * @param def the flow (its values are checked by {@link FlowDef}: the scene schema's ranges); its
     *            id must not be held or queued
     * @return its handle, for {@link #removeFlow}, {@link #setFlowEnabled} and {@link #moveAgent}
     * @throws IllegalArgumentException when {@code def} is null or its id is already in use
     * @throws IllegalStateException    when {@link #MAX_FLOWS} flows or {@link #MAX_PENDING_COMMANDS}
     *                                  commands are already there
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
     * @param source the flow; its id must not be held or queued (checked by this call)
     * @return {@code source}, the handle
     * @throws IllegalArgumentException when {@code source} is null, its id is null or empty, or a flow
     *                                  with its id is already held or queued
     * @throws IllegalStateException    when {@link #MAX_FLOWS} flows or {@link #MAX_PENDING_COMMANDS}
     *                                  commands are already there
     */
    public WindSource addFlow(WindSource source) {
        return loop.commands.addFlow(source);
    }

    /**
     * Queues the removal of a flow or agent. Any thread; allocates a command.
     *
     * @param source the handle {@link #addFlow} or {@link #attachAgent} returned (a flow not held is
     *               ignored); its id is free again when this call returns
     * @throws IllegalStateException when {@link #MAX_PENDING_COMMANDS} commands are already queued
     */
    public void removeFlow(WindSource source) {
        loop.commands.removeFlow(source);
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
        return loop.commands.attachAgent(def);
    }

    /**
     * Moves a flow's centre to (x, z) at the start of the next fixed step, after that step's queued
     * commands. Moves of one flow between two steps coalesce: the latest wins. A flow that is not in
     * the simulation (never added, or removed) is not moved. Any thread; allocates nothing after the
     * flow's first move (a game may call it every frame), and does not count against
     * {@link #MAX_PENDING_COMMANDS}.
     *
     * @param agent the flow's handle: a built-in flow, or a user flow with a movable centre (an
     *              {@link org.jecosys.wind.AbstractWindSource}; the interface's default
     *              {@link WindSource#setCentre} throws, in the step that runs the command)
     * @param x     new centre X, metres, |x| &lt;= {@link org.jecosys.math.Waypoint#MAX_COORDINATE}
     * @param z     new centre Z, metres, |z| &lt;= {@link org.jecosys.math.Waypoint#MAX_COORDINATE}
     * @throws IllegalArgumentException when the agent is null or a coordinate is out of range
     * @throws IllegalStateException    when the simulation is closed
     */
    public void moveAgent(WindSource agent, double x, double z) {
        loop.commands.moveAgent(agent, x, z);
    }

    /**
     * Queues a blast: a short radial pulse at (x, z) metres of peak strength {@code strength} m^2/s
     * lasting {@code duration} s, removed once over ({@link WindField#blast}). Any thread; allocates.
     *
     * @param id       unique flow id while the blast lasts (free again once it is over)
     * @param x        centre X, metres, |x| &lt;= {@link org.jecosys.math.Waypoint#MAX_COORDINATE}
     * @param z        centre Z, metres, |z| &lt;= {@link org.jecosys.math.Waypoint#MAX_COORDINATE}
     * @param strength peak strength, m^2/s, in (0, {@link FlowDef#MAX_STRENGTH}]
     * @param duration seconds, finite, in (0, {@link org.jecosys.wind.ActivationDef#MAX_TIME}]
     * @throws IllegalArgumentException when a value is out of range (NaN and infinities included) or a
     *                                  flow with this id is held or queued
     * @throws IllegalStateException    when {@link #MAX_FLOWS} flows or {@link #MAX_PENDING_COMMANDS}
     *                                  commands are already there
     */
    public void blast(String id, double x, double z, double strength, double duration) {
        loop.commands.blast(id, x, z, strength, duration);
    }

    /**
     * Queues switching a flow on or off. Any thread; allocates a command.
     *
     * @param source  the flow's handle
     * @param enabled whether it acts
     * @throws IllegalStateException when {@link #MAX_PENDING_COMMANDS} commands are already queued
     */
    public void setFlowEnabled(WindSource source, boolean enabled) {
        loop.commands.setFlowEnabled(source, enabled);
    }

    /**
     * Queues a change of animation mode (paper Table 7). Any thread; allocates a command.
     *
     * @param mode static, random or constraint
     * @throws IllegalStateException when {@link #MAX_PENDING_COMMANDS} commands are already queued
     */
    public void setMode(AnimationMode mode) {
        Require.nonNull("mode", mode);
        loop.setMode(mode);
    }

    /**
     * Queues switching the force field on or off (see the package documentation, "How a simulation
     * steps"). Any thread; allocates a command.
     *
     * @param enabled whether the field evaluates flows and culls plants
     * @throws IllegalStateException when {@link #MAX_PENDING_COMMANDS} commands are already queued
     */
    public void setFieldEnabled(boolean enabled) {
        loop.setFieldEnabled(enabled);
    }

    /**
     * Sets the width of the band before each level of detail's end over which a plant is drawn at
     * both levels, dithered (the scene's {@code <render lodTransition>}); see {@link DrawDecision}.
     * Any thread; applied at the next fixed step; allocates a command.
     *
     * @param metres band width, in [0, 10]
     * @throws IllegalArgumentException when out of range
     */
    public void setLodTransition(double metres) {
        detail.setLodTransition(metres);
    }

    /**
     * Sets the distance thinning of the drawing (the scene's {@code <field thinStart thinEnd
     * thinMinFraction>}, which a simulation starts with): beyond {@code start} metres fewer plants are
     * drawn, the kept share falling smoothly to {@code minFraction} at {@code end}; the same plants stay
     * and a plant leaving fades out (see {@link DrawDecision}). For slow GPUs (llvmpipe); the animation
     * is unchanged. Any thread; applied at the next fixed step; allocates a command.
     *
     * @param start       where thinning starts, metres, in [0, 1e6]
     * @param end         where the kept share reaches {@code minFraction}, metres, in [start, 1e6]
     * @param minFraction share of plants kept at and beyond {@code end}, in [0, 1]; 1 turns thinning off
     * @throws IllegalArgumentException when out of range
     * @throws IllegalStateException    when {@link #MAX_PENDING_COMMANDS} commands are already queued
     */
    public void setThinning(double start, double end, double minFraction) {
        detail.setThinning(start, end, minFraction);
    }

    /**
     * Replaces the level-of-detail distances of one species, for the animation and the drawing alike
     * (one set of bands). Any thread; applied at the next fixed step. Allocates a copy.
     *
     * @param species      species index, in [0, species count)
     * @param maxDistances ascending distances where each level but the last ends, metres, &gt; 0,
     *                     one fewer than the species' levels
     * @throws IllegalArgumentException when the species or the distances are out of range
     */
    public void setLodDistances(int species, double[] maxDistances) {
        detail.setLodDistances(species, maxDistances);
    }

    /**
     * The frame's visibility and level decision, read only: its bands, transition and bounding radii.
     * Any thread (values set by the stepping thread).
     *
     * @return the decision the workers apply
     */
    public DrawDecision drawDecision() {
        return loop.draw;
    }

    /**
     * Queues a scale of every species' level-of-detail distances, in [0.01, 100] (2 keeps detail
     * twice as far). Any thread; allocates a command.
     *
     * @param scale factor on every level-of-detail distance, in [0.01, 100]
     * @throws IllegalStateException when {@link #MAX_PENDING_COMMANDS} commands are already queued
     */
    public void setLodScale(double scale) {
        detail.setLodScale(scale);
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
     * The read-only inspection of this simulation: its clock and counters, mode, animated state,
     * force field, wind per plant, state hash and workers (for tools, tests and debug views). Any
     * thread (each of its methods says which thread may call it); no allocation: always the same
     * object.
     *
     * @return the inspection, live
     */
    public Inspection inspect() {
        return inspection;
    }

    /**
     * {@return the bend geometry of the components (immutable): what maps the deviations a frame holds
     * to pose coordinates and azimuths}, for {@link Frame#Frame(int, org.jecosys.anim.BendGeometry)}.
     * Any thread; no allocation.
     */
    public org.jecosys.anim.BendGeometry bendGeometry() {
        return loop.state.geometry();
    }

    /**
     * Closes the simulation: from now on every step and every command call throws
     * {@code IllegalStateException("the simulation is closed")}; then waits for a step running on
     * another thread to finish the fixed step it is in (that step returns normally), at most
     * {@value #CLOSE_WAIT_MILLIS} ms (a step stuck in a game's own flow or camera completes alone
     * when that code returns), and stops the workers. Safe from any thread at any time, also from the
     * stepping thread and during a step; idempotent. Commands still queued are dropped. Allocates
     * nothing unless it has to wait.
     */
    @Override
    public void close() {
        loop.close();
    }

    /** How long {@link #close()} waits for a running step to reach its end, milliseconds. */
    static final long CLOSE_WAIT_MILLIS = 1000;

    /** The message of every call refused after {@link #close()}. */
    static final String CLOSED = "the simulation is closed";
}
