package org.jecosys.sim;

import org.jecosys.math.Camera;
import org.jecosys.math.Progress;
import org.jecosys.math.Require;
import org.jecosys.plant.ComponentFactories;
import org.jecosys.plant.GravityBend;
import org.jecosys.plant.PlantModel;
import org.jecosys.world.TilePlacer;
import org.jecosys.wind.FlowDef;
import org.jecosys.world.TileStreamer;

/**
 * A world without an edge: plants exist only in square tiles within a radius of the views, and each
 * live tile is a small {@link Simulation} of its own plants (paper §3–§4 unchanged inside it: its own
 * LOD quadtree force field over the tile, so the field is tiled as the views move, the same per-node
 * force and LOD; the dynamic-constraint spring per component). A tile is built on a tile worker
 * ({@link TileStreamer}) once it comes within the radius plus one tile of a view: placed by the
 * {@link TilePlacer} (a pure function of the seed and the tile's coordinates, seam-free across borders),
 * its ground sampled from the placer's height function, its plants settled at the equilibrium of the
 * wind. It becomes live at the first step at least {@link #TILE_LATENCY} steps after its start at which
 * it lies within the radius of a view, so what is live at each step depends only on the views' path,
 * not on the number of workers or the machine's load (a step waits for a tile due and not yet built;
 * {@link #tileWaits()} counts them); its clock then joins the others' ({@link
 * org.jecosys.wind.WindField#startAt}). A tile farther than the radius plus one tile from every view
 * is closed and let go; its trails and flattening go with it, and a tile that comes back starts at its
 * equilibrium again. Memory is bounded by the tiles within that distance: {@link #maxLiveTiles()}.
 *
 * <p>Steps: each fixed step first brings the tiles up to date with the views, then steps every live
 * tile's simulation, the tiles shared among the animation workers (a tile's result does not depend on
 * which worker ran it, so the state of every tile is bit-identical for any number of workers). A tile
 * whose box no view's frustum meets, now and at the last step, only advances its clock and flows
 * ({@link #idleTiles()}): its plants were sampled unseen at the last step, so they rest as unseen
 * plants do and start at the wind's equilibrium when seen. The step's tiles and the workers that step
 * them are kept in {@code TileSteps}.
 *
 * <p>Threads: one stepping thread calls {@link #step}, {@link #stepFixed}, {@link #addView},
 * {@link #removeView}, {@link #tile(int)} and the counters; {@link #close} any thread. A step
 * allocates nothing while no tile arrives or leaves (a view standing still or moving within its
 * tiles); a tile arriving costs its bookkeeping on the stepping thread (its build runs on a tile
 * worker).
 */
public final class OpenWorld implements AutoCloseable {
    /** Steps from a tile's start to its being live: 8 fixed steps (a quarter of a second at 30 Hz). */
    public static final int TILE_LATENCY = 8;
    /**
     * The build window, nanoseconds: a tile worker starts a phase of a tile's build (its placement, its
     * world, its simulation) only within this long after a step ended, and never while a step runs,
     * so that building takes the frame's idle time rather than the step's cores (the per-frame budget).
     */
    public static final long BUILD_WINDOW_NANOS = 12_000_000L;

    private final SimulationDef def;
    private final PlantModel model;
    private final TilePlacer placer;
    private final TileStreamer<WorldTile> tiles;
    /** The live tiles of a step and the animation workers that step them. */
    private final TileSteps tileSteps;
    private final double fixedStep;
    private final int maxSubSteps;
    private final Object lock = new Object();
    private Camera[] views = new Camera[0];
    private int idleTiles;
    private double accumulator;
    private double time;
    private long steps;
    private long droppedSteps;
    private long animated;
    private volatile boolean closed;
    /** The thinning set with {@link #setThinning} (start, end, kept share), or null for the def's. */
    private double[] thinning;
    /** The flows added at run time. */
    private final WorldFlows flows = new WorldFlows();
    /** Builds the tiles on the tile workers, in the frame's idle time. */
    private final TileBuilds builds;

    /**
     * Makes an open world. Pre-computes the species (paper §4.1) once for all tiles; starts the
     * animation workers and the tile workers. Build time; allocates; any thread.
     *
     * @param def         the species, flows, field and animation settings and the seed; its terrain,
     *                    distributions and placements are not used (the placer places the plants)
     * @param placer      places each tile's plants on its ground; its species indices are {@code def}'s
     * @param radius      reach of a view, metres: tiles whose square comes this close are live, in
     *                    (0, 64 tile sizes]
     * @param workers     animation workers, in [1, 256]
     * @param tileWorkers threads that build tiles, in [1, 64]
     * @param budget      most tiles started per step, in [1, 1024]
     * @return the open world at time 0, with no tile yet (the first steps start them)
     * @throws IllegalArgumentException when an argument is null or out of range
     */
    public static OpenWorld create(SimulationDef def, TilePlacer placer, double radius, int workers,
                                   int tileWorkers, int budget) {
        return create(def, placer, radius, workers, tileWorkers, budget, org.jecosys.plant.PlantTextures.NONE);
    }

    /**
     * As {@link #create(SimulationDef, TilePlacer, double, int, int, int)}, the components' images
     * ({@link org.jecosys.plant.PlantTextures#load}) shared by every tile. Build time; allocates.
     *
     * @param def         the species, flows, field and animation (its terrain and distributions are not used)
     * @param placer      the tiles' placement
     * @param radius      how far around the views tiles are alive, metres
     * @param workers     animation workers, in [1, 256]
     * @param tileWorkers threads that build tiles, in [1, 64]
     * @param budget      most tiles started per step, in [1, 1024]
     * @param textures the prepared images the species name, {@link org.jecosys.plant.PlantTextures#NONE} for none
     * @return the open world at time 0, with no tile yet
     * @throws IllegalArgumentException when an argument is null or out of range
     */
    public static OpenWorld create(SimulationDef def, TilePlacer placer, double radius, int workers,
                                   int tileWorkers, int budget, org.jecosys.plant.PlantTextures textures) {
        Require.nonNull("def", def);
        Require.nonNull("placer", placer);
        PlantModel model = PlantModel.build(def.species(), def.seed(), GravityBend.EARTH_GRAVITY, Progress.NONE,
                ComponentFactories.NONE).withTextures(Require.nonNull("textures", textures));
        return new OpenWorld(def, model, placer, radius, workers, tileWorkers, budget);
    }

    private OpenWorld(SimulationDef def, PlantModel model, TilePlacer placer, double radius, int workers,
                      int tileWorkers, int budget) {
        this.def = def;
        this.model = model;
        this.placer = placer;
        Require.range("workers", workers, 1, 256);
        this.fixedStep = def.animation().fixedStep();
        double tallest = WorldTile.tallest(def.species());
        this.maxSubSteps = def.animation().maxSubSteps();
        builds = new TileBuilds(def, model, placer, () -> closed);
        tiles = new TileStreamer<>(placer.tileSize(), builds, radius, placer.tileSize(), tileWorkers, budget,
                TILE_LATENCY);
        tileSteps = new TileSteps(tiles.maxLiveTiles() * Simulation.MAX_VIEWS, workers, tallest);
    }

    /**
     * Adds {@code dt} seconds and runs the fixed steps it completes, at most the def's
     * {@code maxSubSteps} (the rest of a long pause is dropped and counted). Stepping thread.
     *
     * @param dt     elapsed time, seconds, finite and &gt;= 0
     * @param camera the viewer: its tiles are kept live and its frustum animated
     * @return fixed steps run
     * @throws IllegalArgumentException when {@code dt} is negative or not finite, or the camera null
     * @throws IllegalStateException    when the world is closed
     */
    public int step(double dt, Camera camera) {
        Require.nonNegative("dt", dt);
        Require.nonNull("camera", camera);
        accumulator += dt;
        int n = 0;
        try {
            while (accumulator >= fixedStep && n < maxSubSteps) {
                // another fixed step follows at once: the animation workers spin for it instead of sleeping
                stepFixed(camera, accumulator - fixedStep >= fixedStep && n + 1 < maxSubSteps);
                accumulator -= fixedStep;
                n++;
            }
        } finally {
            builds.burstEnded(); // a step that threw ends the burst too
        }
        if (accumulator >= fixedStep) {
            long drop = (long) (accumulator / fixedStep);
            droppedSteps += drop;
            accumulator = Math.max(0, accumulator - drop * fixedStep);
        }
        return n;
    }

    /**
     * Runs one fixed step: the tiles brought up to date with the camera and the registered views (at
     * most the budget started, those due taken in, those out of reach let go), then every live tile
     * stepped. Stepping thread.
     *
     * @param camera the viewer
     * @throws IllegalStateException when the world is closed, or building a tile failed
     */
    public void stepFixed(Camera camera) {
        stepFixed(camera, false);
    }

    private void stepFixed(Camera camera, boolean followed) {
        Require.nonNull("camera", camera);
        synchronized (lock) {
            checkOpen();
            if (flows.count() > 0) {
                flows.expire(time, tileSteps.tiles, tileSteps.started(tiles));
            }
            int viewCount = tileSteps.viewsAt(camera, views);
            tiles.update(tileSteps.viewX, tileSteps.viewZ, viewCount); // a wait for a tile opens the builds' gate
            int idle = tileSteps.gather(tiles, camera, views, time, flows, thinning);
            animated = tileSteps.run(camera, builds, followed);
            idleTiles = idle;
            steps++;
            time += fixedStep;
        }
    }

    /**
     * Adds a flow to the whole world from the next step on: every live tile and every tile that starts
     * later holds its own instance of it (so a flow is given as a def, not as a game's own
     * {@link org.jecosys.wind.WindSource} object). Its activation window is in the world's time. Stepping thread;
     * allocates.
     *
     * @param def the flow, its id not held by the scene's flows nor by another added one
     * @throws IllegalArgumentException when {@code def} is null or its id is taken
     * @throws IllegalStateException    when {@link Simulation#MAX_FLOWS} flows are there, or the world is closed
     */
    public void addFlow(FlowDef def) {
        synchronized (lock) {
            checkOpen();
            flows.add(def, Double.POSITIVE_INFINITY, tileSteps.tiles, tileSteps.started(tiles), this.def);
        }
    }

    /**
     * Removes a flow added with {@link #addFlow} or {@link #blast} from every tile. Stepping thread.
     *
     * @param id the flow's id
     * @return whether such a flow was there
     */
    public boolean removeFlow(String id) {
        synchronized (lock) {
            checkOpen();
            int k = flows.indexOf(id);
            if (k < 0) {
                return false;
            }
            flows.remove(k, tileSteps.tiles, tileSteps.started(tiles));
            return true;
        }
    }

    /**
     * Moves an added flow's centre (an agent: a player, a vehicle) to (x, z) at the next step, in every
     * tile, and in the tiles that start later. Call it every frame: the latest move before a step wins.
     * Stepping thread; allocates nothing after the agent's first move in each tile.
     *
     * @param id an id given to {@link #addFlow}
     * @param x  centre X, metres, |x| &lt;= {@link org.jecosys.math.Waypoint#MAX_COORDINATE}
     * @param z  centre Z, metres, |z| &lt;= {@link org.jecosys.math.Waypoint#MAX_COORDINATE}
     * @throws IllegalArgumentException when no added flow has this id, or a coordinate is out of range
     */
    public void moveAgent(String id, double x, double z) {
        synchronized (lock) {
            checkOpen();
            int k = flows.indexOf(id);
            if (k < 0) {
                throw new IllegalArgumentException("no flow '" + id + "' was added to the open world");
            }
            flows.move(k, x, z, tileSteps.tiles, tileSteps.started(tiles));
        }
    }

    /**
     * A blast at (x, z) from the next step: a short radial pulse of peak {@code strength} m^2/s over
     * {@code duration} s, in every tile (a tile that starts while it lasts gets it too), dropped once
     * over. Stepping thread; allocates.
     *
     * @param id       a free flow id
     * @param x        centre X, metres
     * @param z        centre Z, metres
     * @param strength peak strength, m^2/s, &gt; 0
     * @param duration seconds, &gt; 0
     * @throws IllegalArgumentException when a value is out of range or the id is taken
     */
    public void blast(String id, double x, double z, double strength, double duration) {
        synchronized (lock) {
            checkOpen();
            FlowDef d = WorldFlows.blast(id, x, z, strength, duration, time);
            flows.add(d, time + duration, tileSteps.tiles, tileSteps.started(tiles), this.def);
        }
    }

    /**
     * Sets the distance thinning of the drawing in every tile, now and for the tiles that start later
     * ({@link Simulation#setThinning}: for slow GPUs such as llvmpipe, e.g. {@link DrawQuality#LOW}'s 4 m,
     * 16 m and 0.15). Stepping thread; allocates a command per tile.
     *
     * @throws IllegalArgumentException when a value is out of range
     *
     * @param start       where thinning starts, metres, in [0, 1e6]
     * @param end         where the kept share reaches {@code minFraction}, metres, in [start, 1e6]
     * @param minFraction share of plants kept at and beyond {@code end}, in [0, 1]; 1 turns thinning off
     */
    public void setThinning(double start, double end, double minFraction) {
        synchronized (lock) {
            checkOpen();
            Require.range("start", start, 0, 1e6);
            Require.range("end", end, start, 1e6);
            Require.range("minFraction", minFraction, 0, 1);
            double[] t = {start, end, minFraction};
            for (int k = 0; k < tiles.liveTiles(); k++) {
                tiles.live(k).simulation.setThinning(start, end, minFraction); // checks the values
            }
            thinning = t;
        }
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException("the open world is closed");
        }
    }

    /**
     * Follows another view (split screen, a second player, a minimap): its tiles are kept live too,
     * and the plants it sees are animated. Stepping thread; allocates.
     *
     * @param view the view, read at every step
     * @throws IllegalArgumentException when it is null or registered already
     * @throws IllegalStateException    when {@link Simulation#MAX_VIEWS} - 1 views are registered
     */
    public void addView(Camera view) {
        Require.nonNull("view", view);
        synchronized (lock) {
            views = ViewLists.with(views, view, Simulation.MAX_VIEWS - 1, "an open world");
        }
    }

    /**
     * Stops following a view. Stepping thread; allocates.
     *
     * @param view a registered view
     * @return whether it was registered
     */
    public boolean removeView(Camera view) {
        synchronized (lock) {
            Camera[] v = views;
            views = ViewLists.without(v, view);
            return views != v;
        }
    }

    /** {@return the live tiles} Stepping thread. */
    public int liveTiles() {
        return tiles.liveTiles();
    }

    /**
     * {@return live tile k, in ascending order of (i, j)} Stepping thread; no allocation.
     *
     * @param k in [0, {@link #liveTiles()})
     */
    public WorldTile tile(int k) {
        return tiles.live(k);
    }

    /** {@return the plants of the live tiles} */
    public long livePlants() {
        return tiles.livePlants();
    }

    /** {@return the components of the live tiles} Stepping thread; no allocation. */
    public long liveComponents() {
        long c = 0;
        for (int k = 0; k < tiles.liveTiles(); k++) {
            c += tiles.live(k).world.componentCount();
        }
        return c;
    }

    /** {@return the components animated in the last step, over all tiles} */
    public long animatedComponents() {
        return animated;
    }

    /**
     * {@return the live tiles the last step only advanced the clock of} Tiles that no view could see at
     * this step and the last one: their plants are not animated (as unseen plants of any simulation),
     * and their simulation's frame is not republished.
     */
    public int idleTiles() {
        return idleTiles;
    }

    /** {@return the tiles built and taken in so far} */
    public long builtTiles() {
        return tiles.builtTiles();
    }

    /** {@return the tiles started and not live yet} */
    public int pendingTiles() {
        return tiles.pendingTiles();
    }

    /** {@return how often a step waited for a tile that was due and not built (0 while the workers keep pace)} */
    public long tileWaits() {
        return tiles.waits();
    }

    /** {@return the most tiles live at once per view (those within the radius plus one tile)} */
    public int maxLiveTiles() {
        return tiles.maxLiveTiles();
    }

    /** {@return the tiles' side, metres} */
    public double tileSize() {
        return placer.tileSize();
    }

    /** {@return the simulation time, seconds} */
    public double time() {
        return time;
    }

    /** {@return the fixed steps run} */
    public long steps() {
        return steps;
    }

    /** {@return the fixed steps dropped after long pauses} */
    public long droppedSteps() {
        return droppedSteps;
    }

    /** {@return the pre-computed species, shared by every tile} */
    public PlantModel plants() {
        return model;
    }

    /**
     * Waits until every started tile is built and takes them in, live at once (a loading screen).
     * Stepping thread.
     */
    public void settle() {
        synchronized (lock) {
            tiles.settle(); // each wait for a tile opens the builds' gate
        }
    }

    /**
     * A loading screen: fixed steps with {@code camera}, each followed by a {@link #settle}, until a step
     * starts no tile, so every tile within reach of the views is live; then the def's prewarm
     * ({@link org.jecosys.anim.AnimationDef#prewarm()}): that many fixed steps more, so the plants the game
     * starts among are already in motion (tiles that arrive later join the running wind at the radius).
     * Stepping thread; allocates.
     *
     * @param camera the viewer where the game starts
     */
    public void load(Camera camera) {
        for (int k = 0; k < 256; k++) {
            stepFixed(camera);
            boolean started = pendingTiles() > 0;
            settle();
            if (!started) {
                break;
            }
        }
        for (int i = def.animation().prewarmSteps(); i > 0; i--) {
            stepFixed(camera);
        }
    }

    /** Stops the workers and closes every tile. Idempotent; any thread. */
    @Override
    public void close() {
        closed = true;
        synchronized (lock) {
            tileSteps.close();
            tiles.close();
        }
    }
}
