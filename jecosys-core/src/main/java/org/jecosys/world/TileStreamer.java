package org.jecosys.world;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.ThreadFactory;
import org.jecosys.math.Require;

/**
 * The tiles around the views (issue 39): keeps {@link TilePlants} alive for every tile whose square
 * comes within {@link #radius()} of a view, builds the missing ones with a {@link TilePlacer} on
 * worker threads, nearest first and at most {@link #budget()} started per {@link #update}, and lets a
 * tile go (its arrays to the garbage collector) once it is farther than the radius plus one tile from
 * every view. {@link #update} never waits for a tile: a tile finished on a worker becomes live at the
 * first update after it is done. Since a tile is a pure function of its coordinates, a tile that comes
 * back is the same tile, plant for plant, whatever the order tiles were built in and however many
 * workers built them.
 *
 * <p>What is alive is bounded: tiles within radius + one tile of a view, about
 * {@code pi (r / size + 2)^2} per view; {@link #maxLiveTiles()} gives the bound the streamer keeps.
 *
 * <p>Threads: one thread (the stepping thread) calls {@link #update}, {@link #tile}, {@link #liveTiles}
 * and {@link #close}; the workers only run {@link TilePlacer#place}. {@link #update} allocates a
 * task and a map entry per tile started and a few small objects per call (the maps' iterators and
 * boxed keys): this is the tiles' bookkeeping, not yet the per-frame path of a streaming simulation.
 */
public final class TileStreamer implements AutoCloseable {
    private final TilePlacer placer;
    private final double radius;
    private final int budget;
    private final ExecutorService workers;
    private final Map<Long, TilePlants> live = new HashMap<>();
    private final Map<Long, Future<TilePlants>> pending = new HashMap<>();
    /** Tiles wanted and missing at the last update, nearest first (reused). */
    private long[] wanted = new long[64];
    private double[] wantedDistance = new double[64];
    private final List<Long> leaving = new ArrayList<>();
    private long built;
    private long livePlants;
    private boolean closed;

    /**
     * Makes a streamer. Allocates; starts {@code workers} daemon threads.
     *
     * @param placer  the tiles' placement
     * @param radius  reach of a view, metres: tiles whose square comes this close are kept, &gt; 0 and at
     *                most 64 tiles
     * @param workers threads that build tiles, in [1, 64]
     * @param budget  most tiles started per {@link #update}, in [1, 1024]
     * @throws IllegalArgumentException when an argument is out of range
     */
    public TileStreamer(TilePlacer placer, double radius, int workers, int budget) {
        this.placer = Require.nonNull("placer", placer);
        Require.range("radius", radius, 1e-3, 64 * placer.tileSize());
        Require.range("workers", workers, 1, 64);
        this.budget = Require.range("budget", budget, 1, 1024);
        this.radius = radius;
        ThreadFactory daemons = r -> {
            Thread t = new Thread(r, "jecosys-tiles");
            t.setDaemon(true);
            return t;
        };
        this.workers = Executors.newFixedThreadPool(workers, daemons);
    }

    /** {@return the reach of a view, metres} */
    public double radius() {
        return radius;
    }

    /** {@return the most tiles started per update} */
    public int budget() {
        return budget;
    }

    /** {@return the most tiles alive at once per view: those within the radius plus one tile of it} */
    public int maxLiveTiles() {
        int n = (int) Math.ceil((radius + placer.tileSize()) / placer.tileSize()) + 1;
        return (2 * n) * (2 * n);
    }

    /**
     * Brings the tiles up to date with the views: takes in the tiles finished since the last call, lets
     * go of those beyond radius + one tile of every view, and starts up to {@link #budget()} missing
     * tiles within the radius, nearest first. Never waits. Stepping thread.
     *
     * @param viewX X of each view, metres
     * @param viewZ Z of each view, metres
     * @param views how many views (the first entries of the arrays), &gt;= 1
     * @throws IllegalStateException when the streamer is closed, or a tile's placement failed
     */
    public void update(double[] viewX, double[] viewZ, int views) {
        if (closed) {
            throw new IllegalStateException("the tile streamer is closed");
        }
        Require.range("views", views, 1, Math.min(viewX.length, viewZ.length));
        collect();
        double size = placer.tileSize();
        // let go of tiles beyond radius + one tile of every view
        double keep = radius + size;
        leaving.clear();
        for (Long key : live.keySet()) {
            if (distance(key, viewX, viewZ, views, size) > keep) {
                leaving.add(key);
            }
        }
        for (int i = 0; i < leaving.size(); i++) {
            TilePlants t = live.remove(leaving.get(i));
            livePlants -= t.count();
        }
        for (Iterator<Map.Entry<Long, Future<TilePlants>>> it = pending.entrySet().iterator(); it.hasNext();) {
            Map.Entry<Long, Future<TilePlants>> e = it.next();
            if (distance(e.getKey(), viewX, viewZ, views, size) > keep) {
                e.getValue().cancel(false);
                it.remove();
            }
        }
        // the missing tiles within the radius, nearest first
        int n = 0;
        for (int v = 0; v < views; v++) {
            int i0 = (int) Math.floor((viewX[v] - radius) / size);
            int i1 = (int) Math.floor((viewX[v] + radius) / size);
            int j0 = (int) Math.floor((viewZ[v] - radius) / size);
            int j1 = (int) Math.floor((viewZ[v] + radius) / size);
            for (int i = i0; i <= i1; i++) {
                for (int j = j0; j <= j1; j++) {
                    long key = key(i, j);
                    if (live.containsKey(key) || pending.containsKey(key) || contains(wanted, n, key)) {
                        continue;
                    }
                    double d = distance(key, viewX, viewZ, views, size);
                    if (d > radius) {
                        continue;
                    }
                    if (n == wanted.length) {
                        wanted = java.util.Arrays.copyOf(wanted, 2 * n);
                        wantedDistance = java.util.Arrays.copyOf(wantedDistance, 2 * n);
                    }
                    // insertion by distance (ties by key): a fixed order
                    int at = n;
                    while (at > 0 && (wantedDistance[at - 1] > d || wantedDistance[at - 1] == d && wanted[at - 1] > key)) {
                        wanted[at] = wanted[at - 1];
                        wantedDistance[at] = wantedDistance[at - 1];
                        at--;
                    }
                    wanted[at] = key;
                    wantedDistance[at] = d;
                    n++;
                }
            }
        }
        for (int k = 0; k < n && k < budget; k++) {
            long key = wanted[k];
            int ti = (int) (key >> 32);
            int tj = (int) key;
            pending.put(key, workers.submit(() -> placer.place(ti, tj)));
        }
    }

    /** Takes in the tiles finished on the workers. */
    private void collect() {
        for (Iterator<Map.Entry<Long, Future<TilePlants>>> it = pending.entrySet().iterator(); it.hasNext();) {
            Map.Entry<Long, Future<TilePlants>> e = it.next();
            Future<TilePlants> f = e.getValue();
            if (!f.isDone()) {
                continue;
            }
            it.remove();
            TilePlants t;
            try {
                t = f.get();
            } catch (InterruptedException ex) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while taking in a tile", ex);
            } catch (java.util.concurrent.ExecutionException ex) {
                throw new IllegalStateException("placing tile " + (e.getKey() >> 32) + ", " + (int) (long) e.getKey()
                        + " failed: " + ex.getCause(), ex.getCause());
            }
            live.put(e.getKey(), t);
            livePlants += t.count();
            built++;
        }
    }

    /**
     * Waits until every started tile is finished and takes them in (tests, loading screens). Stepping
     * thread.
     *
     * @throws IllegalStateException when a tile's placement failed
     */
    public void settle() {
        for (Future<TilePlants> f : pending.values()) {
            try {
                f.get();
            } catch (InterruptedException ex) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while waiting for tiles", ex);
            } catch (java.util.concurrent.ExecutionException ex) {
                throw new IllegalStateException("placing a tile failed: " + ex.getCause(), ex.getCause());
            }
        }
        collect();
    }

    /**
     * {@return tile (i, j) if it is alive, else null} Stepping thread; may box the key.
     *
     * @param i the tile's index along X
     * @param j the tile's index along Z
     */
    public TilePlants tile(int i, int j) {
        return live.get(key(i, j));
    }

    /** {@return the tiles alive now} */
    public int liveTiles() {
        return live.size();
    }

    /** {@return the plants of the tiles alive now} */
    public long livePlants() {
        return livePlants;
    }

    /** {@return the tiles started and not yet taken in} */
    public int pendingTiles() {
        return pending.size();
    }

    /** {@return the tiles built and taken in since the streamer was made} */
    public long builtTiles() {
        return built;
    }

    /** Stops the workers (a tile being placed finishes) and lets go of every tile. Idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            workers.shutdownNow();
            live.clear();
            pending.clear();
            livePlants = 0;
        }
    }

    private static long key(int i, int j) {
        return ((long) i << 32) | (j & 0xFFFFFFFFL);
    }

    private static boolean contains(long[] keys, int n, long key) {
        for (int k = 0; k < n; k++) {
            if (keys[k] == key) {
                return true;
            }
        }
        return false;
    }

    /** The least distance from a view to the tile's square, metres (0 inside it). */
    private static double distance(long key, double[] viewX, double[] viewZ, int views, double size) {
        int i = (int) (key >> 32);
        int j = (int) key;
        double x0 = i * size;
        double z0 = j * size;
        double best = Double.MAX_VALUE;
        for (int v = 0; v < views; v++) {
            double dx = Math.max(0, Math.max(x0 - viewX[v], viewX[v] - (x0 + size)));
            double dz = Math.max(0, Math.max(z0 - viewZ[v], viewZ[v] - (z0 + size)));
            best = Math.min(best, Math.sqrt(dx * dx + dz * dz));
        }
        return best;
    }
}
