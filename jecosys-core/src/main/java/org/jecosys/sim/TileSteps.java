package org.jecosys.sim;

import java.util.Arrays;
import org.jecosys.math.Camera;
import org.jecosys.world.TileStreamer;
import org.joml.FrustumIntersection;
import org.joml.Matrix4f;

/**
 * The live tiles of an {@link OpenWorld}'s fixed step and the animation workers that step them: the
 * views' ground positions the tiles are streamed around, the views' frusta against which each tile is
 * marked idle (outside every frustum now and at the last step: only its clock advances), the tiles of
 * the step in live order, and the worker pool that steps each (its own simulation's fixed step, or an
 * idle step) and counts the components it animated. Between steps the tile array is the scratch the
 * world's flow changes list the started tiles in ({@link #started}). Stepping thread, under the open
 * world's lock; the workers read the step's tiles and camera while {@link #run} waits. Sized at
 * construction (allocates, starts the workers); a step allocates nothing.
 */
final class TileSteps {
    /** The live tiles of the step being run, read by the workers; between steps, scratch for flow changes. */
    final WorldTile[] tiles;
    private volatile int count;
    private volatile Camera camera;
    /** Per tile of the step, the components its step animated. */
    private final int[] animated;
    /** The ground positions of the camera and the registered views, metres. */
    final double[] viewX = new double[Simulation.MAX_VIEWS];
    final double[] viewZ = new double[Simulation.MAX_VIEWS];
    private final FrustumIntersection[] frusta = new FrustumIntersection[Simulation.MAX_VIEWS];
    private final Matrix4f matrix = new Matrix4f();
    /** The tallest plant of any species, metres. */
    private final double tallest;
    private final WorkerPool pool;

    /**
     * Room for {@code most} tiles per step, stepped by {@code workers} animation workers (started here).
     *
     * @param tallest the tallest plant of any species, metres (a tile's box reaches that high)
     */
    TileSteps(int most, int workers, double tallest) {
        for (int v = 0; v < frusta.length; v++) {
            frusta[v] = new FrustumIntersection();
        }
        this.tallest = tallest;
        tiles = new WorldTile[most];
        animated = new int[most];
        pool = new WorkerPool("jecosys-world", workers, most, (k, worker) -> {
            if (k < count) {
                WorldTile t = tiles[k];
                if (t.idle) {
                    t.simulation.loop.idleStep();
                    animated[k] = 0;
                } else {
                    t.simulation.loop.stepFixed(camera);
                    animated[k] = t.simulation.loop.chunkAnimator.animated();
                }
            }
        });
    }

    /**
     * Writes the ground positions of the camera and then the registered views into {@link #viewX} and
     * {@link #viewZ}.
     *
     * @return the number of views, the camera included
     */
    int viewsAt(Camera camera, Camera[] views) {
        viewX[0] = camera.x();
        viewZ[0] = camera.z();
        for (int v = 0; v < views.length; v++) {
            viewX[v + 1] = views[v].x();
            viewZ[v + 1] = views[v].z();
        }
        return 1 + views.length;
    }

    /**
     * Takes the live tiles in as the step's, in live order: each marked idle when no view's frustum
     * meets its box now nor did at the last step, started (at {@code time}, with the world's flows and
     * thinning) if it was not, and given the registered views if they changed.
     *
     * @return the idle tiles
     */
    int gather(TileStreamer<WorldTile> live, Camera camera, Camera[] views, double time, WorldFlows flows,
               double[] thinning) {
        int viewCount = 1 + views.length;
        for (int v = 0; v < viewCount; v++) {
            frusta[v].set((v == 0 ? camera : views[v - 1]).viewProjection(matrix), false);
        }
        int n = live.liveTiles();
        int idle = 0;
        for (int k = 0; k < n; k++) {
            WorldTile t = live.live(k);
            boolean outside = t.outside(frusta, viewCount, tallest);
            t.idle = outside && t.wasOutside;
            t.wasOutside = outside;
            idle += t.idle ? 1 : 0;
            if (!t.started) {
                t.start(time, flows, thinning);
            }
            if (t.views != views) {
                t.syncViews(views);
            }
            tiles[k] = t;
        }
        Arrays.fill(tiles, n, tiles.length, null);
        count = n;
        return idle;
    }

    /**
     * Steps the tiles {@link #gather} took in on the workers, this thread among them, with {@code camera}
     * as each simulation's camera, while {@code builds} holds the tile workers back: until this step's
     * end, or when another fixed step follows at once, until the burst's last step ends (so that a build
     * phase does not start between two fixed steps and run into the second).
     *
     * @param followed whether another fixed step follows at once (the workers spin for it)
     * @return the components animated, over all tiles
     */
    long run(Camera camera, TileBuilds builds, boolean followed) {
        this.camera = camera;
        builds.stepStarting(followed);
        try {
            pool.start(followed);
            pool.await();
        } finally {
            if (!followed) {
                builds.burstEnded();
            }
        }
        long sum = 0;
        for (int k = 0, n = count; k < n; k++) {
            sum += animated[k];
        }
        this.camera = null;
        return sum;
    }

    /** Lists the started live tiles in {@link #tiles}, for a change of the flows; returns how many. No allocation. */
    int started(TileStreamer<WorldTile> live) {
        int n = 0;
        for (int k = 0; k < live.liveTiles(); k++) {
            WorldTile t = live.live(k);
            if (t.started) {
                tiles[n++] = t;
            }
        }
        return n;
    }

    /** Stops the workers. */
    void close() {
        pool.close();
    }
}
