package org.jecosys.sim;

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
 * simulation). Each of the three phases starts only while no step runs and within
 * {@link OpenWorld#BUILD_WINDOW_NANOS} of the last step's end, or while the stepping thread waits for
 * tiles: building takes the frame's idle time, not the step's cores. The flags are written by the
 * stepping thread and read by the workers. Allocates (a tile's build).
 */
final class TileBuilds implements TileFactory<WorldTile> {
    /** Ground samples of a tile's heightfield per metre. */
    private static final double GROUND_SAMPLES_PER_METRE = 1;

    private final SimulationDef def;
    private final PlantModel model;
    private final TilePlacer placer;
    private final BooleanSupplier closed;
    /** The species' kinds prepared for the usual step, which every tile's simulation copies; read only. */
    private final SpringKinds kinds;
    /** Whether a step is running (workers hold their next phase). */
    volatile boolean stepping;
    /** System.nanoTime() at the end of the last step. */
    volatile long stepEnded = System.nanoTime();
    /** Whether the stepping thread waits for tiles (the tiles' update, a settle): the gate is open. */
    volatile boolean loading;

    TileBuilds(SimulationDef def, PlantModel model, TilePlacer placer, BooleanSupplier closed) {
        this.def = def;
        this.model = model;
        this.placer = placer;
        this.closed = closed;
        kinds = SpringKinds.of(model.species());
        kinds.prepare(def.animation().fixedStep(), def.animation().subIntervals(), -1);
    }

    /** Holds a tile worker until it may start a build phase. */
    private void gate() {
        while (!closed.getAsBoolean() && !loading
                && (stepping || System.nanoTime() - stepEnded > OpenWorld.BUILD_WINDOW_NANOS)) {
            java.util.concurrent.locks.LockSupport.parkNanos(250_000L);
            if (Thread.interrupted()) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    @Override
    public WorldTile build(int i, int j) {
        gate();
        TilePlants plants = placer.place(i, j);
        gate();
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
        gate();
        return new WorldTile(i, j, world, new Simulation(world, def, 1, Simulation.CHUNK_COMPONENTS,
                ForceFieldFactory.QUADTREE, kinds));
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
