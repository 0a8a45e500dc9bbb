package org.jecosys.sim;

import java.util.concurrent.atomic.AtomicLongArray;
import java.util.function.BooleanSupplier;
import org.jecosys.anim.SpringKinds;
import org.jecosys.field.ForceFieldFactory;
import org.jecosys.math.HeightFunction;
import org.jecosys.plant.PlantModel;
import org.jecosys.terrain.Heightfield;
import org.jecosys.world.TileFactory;
import org.jecosys.world.TilePlacer;
import org.jecosys.world.TilePlants;

/**
 * How {@link OpenWorld} builds a tile on a tile worker: its plants ({@link TilePlacer#place}), its
 * ground (the placer's height function sampled into a {@link Heightfield} centred on the tile, 1 m
 * cells), its {@link World} and a one-worker {@link Simulation} of it; and lets it go (closes the
 * simulation). Each of the three phases starts only while no step runs (a burst of fixed steps counts
 * as one: no phase starts between two steps of a burst), or while the stepping thread waits for a tile
 * ({@link #waiting}): building takes the frame's idle time, not the step's cores. When the bursts keep
 * a cadence (a game's frame), a phase starts only if it is expected to end {@link WorkerPool#LEAD_NANOS}
 * before the next burst (each phase's expected length: twice the mean of its recent runs), or
 * within {@link #FIRST_NANOS} of a burst's end whatever its length (the whole gap is ahead of it);
 * without a cadence, within {@link OpenWorld#BUILD_WINDOW_NANOS} of the last burst's end. The flags
 * are written by the stepping thread and read by the workers. Allocates (a tile's build).
 */
final class TileBuilds implements TileFactory<WorldTile> {
    /** Ground samples of a tile's heightfield per metre. */
    private static final double GROUND_SAMPLES_PER_METRE = 1;
    /** A phase may start this soon after a burst's end whatever its expected length, nanoseconds. */
    static final long FIRST_NANOS = 1_000_000;
    /** A phase is expected to take up to this many times its mean length. */
    private static final int PHASE_MARGIN = 2;

    private final SimulationDef def;
    private final PlantModel model;
    private final TilePlacer placer;
    private final BooleanSupplier closed;
    /** The species' kinds prepared for the usual step, which every tile's simulation copies; read only. */
    private final SpringKinds kinds;
    /** Whether a step or a burst of them is running (workers hold their next phase). */
    private volatile boolean stepping;
    /** System.nanoTime() at the end of the last burst of steps. */
    private volatile long stepEnded = System.nanoTime();
    /** System.nanoTime() at which the next burst is expected to start, or 0 when the bursts keep no cadence. */
    private volatile long nextBurst;
    /** The stepping thread's bursts of steps; stepping thread only. */
    private final Bursts bursts = new Bursts();
    /** Per phase (placement, world, simulation), its expected length on a tile worker, nanoseconds. */
    private final AtomicLongArray phaseNanos = new AtomicLongArray(3);
    /** Whether the stepping thread waits for a tile (a tile due, a settle): the gate is open. */
    volatile boolean loading;

    TileBuilds(SimulationDef def, PlantModel model, TilePlacer placer, BooleanSupplier closed) {
        this.def = def;
        this.model = model;
        this.placer = placer;
        this.closed = closed;
        kinds = SpringKinds.of(model.species());
        kinds.prepare(def.animation().fixedStep(), def.animation().subIntervals(), -1);
    }

    /**
     * A fixed step starts; {@code followed}: another follows at once, in the same burst. Stepping thread;
     * no allocation.
     */
    void stepStarting(boolean followed) {
        stepStarting(followed, System.nanoTime());
    }

    /** {@link #stepStarting(boolean)} at {@code now} (System.nanoTime()). */
    void stepStarting(boolean followed, long now) {
        if (bursts.step(followed, now)) {
            // the shorter of the last two intervals: a phase should rather wait than run into a step
            long interval = bursts.interval();
            long expected = Math.min(interval, bursts.lastInterval());
            nextBurst = expected > 0 && interval <= Bursts.LONGEST_INTERVAL ? now + expected : 0;
        }
        stepping = true;
    }

    /** The last fixed step of a burst ended (idempotent): the workers may build. Stepping thread. */
    void burstEnded() {
        burstEnded(System.nanoTime());
    }

    /** {@link #burstEnded()} at {@code now} (System.nanoTime()). */
    void burstEnded(long now) {
        bursts.end();
        if (stepping) {
            stepping = false;
            stepEnded = now;
        }
    }

    /** Whether phase {@code phase} (0 placement, 1 world, 2 simulation) may start at {@code now} (see the class comment). */
    boolean mayStart(int phase, long now) {
        if (stepping) {
            return false;
        }
        long since = now - stepEnded;
        if (since < FIRST_NANOS) {
            return true;
        }
        long next = nextBurst;
        if (next != 0 && next - now > 0) {
            return now + PHASE_MARGIN * phaseNanos.get(phase) + WorkerPool.LEAD_NANOS - next <= 0;
        }
        return since <= OpenWorld.BUILD_WINDOW_NANOS;
    }

    /**
     * Notes that phase {@code phase} ran {@code nanos}: its mean length follows its recent runs (an
     * exponential average over about eight), so that one run stretched by a collection does not hold the
     * phases back for long.
     */
    void ran(int phase, long nanos) {
        long old = phaseNanos.get(phase);
        phaseNanos.set(phase, old == 0 ? nanos : old + (nanos - old) / 8);
    }

    /** Holds a tile worker until it may start build phase {@code phase}. */
    private void gate(int phase) {
        while (!closed.getAsBoolean() && !loading && !mayStart(phase, System.nanoTime())) {
            java.util.concurrent.locks.LockSupport.parkNanos(250_000L);
            if (Thread.interrupted()) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    @Override
    public WorldTile build(int i, int j) {
        gate(0);
        long t0 = System.nanoTime();
        TilePlants plants = placer.place(i, j);
        ran(0, System.nanoTime() - t0);
        gate(1);
        t0 = System.nanoTime();
        double size = placer.tileSize();
        int res = (int) Math.max(2, Math.min(257, Math.ceil(size * GROUND_SAMPLES_PER_METRE) + 1));
        float[] h = new float[res * res];
        HeightFunction ground = placer.ground();
        double x0 = i * size;
        double z0 = j * size;
        for (int b = 0; b < res; b++) {
            for (int a = 0; a < res; a++) {
                h[b * res + a] = (float) ground.height(x0 + a * size / (res - 1), z0 + b * size / (res - 1));
            }
        }
        Heightfield hf = Heightfield.of(x0 + size / 2, z0 + size / 2, size, size, res, h);
        World world = World.tile(model, plants, hf);
        ran(1, System.nanoTime() - t0);
        gate(2);
        t0 = System.nanoTime();
        WorldTile tile = new WorldTile(i, j, world, new Simulation(world, def, 1, Simulation.CHUNK_COMPONENTS,
                ForceFieldFactory.QUADTREE, kinds));
        ran(2, System.nanoTime() - t0);
        return tile;
    }

    @Override
    public void waiting(boolean waiting) {
        loading = waiting;
    }

    @Override
    public int plants(WorldTile tile) {
        return tile.world().plantCount();
    }

    @Override
    public void release(WorldTile tile) {
        tile.simulation().close();
    }
}
