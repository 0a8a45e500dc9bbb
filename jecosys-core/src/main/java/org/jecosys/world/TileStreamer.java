package org.jecosys.world;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Future;
import org.jecosys.math.Require;

/**
 * The tiles around the views: keeps a tile (its {@link TilePlants}, or whatever a {@link TileFactory}
 * builds from them) alive for every tile whose square comes within {@link #radius()} of a view, builds
 * the missing ones with the factory on worker threads, nearest first and at most {@link #budget()} started per {@link #update}, and lets a
 * tile go (its arrays to the garbage collector) once it is farther than the radius plus one tile from
 * every view. {@link #update} never waits for a tile: a tile finished on a worker becomes live at the
 * first update after it is done. Since a tile is a pure function of its coordinates, a tile that comes
 * back is the same tile, plant for plant, whatever the order tiles were built in and however many
 * workers built them.
 *
 * <p>What is alive is bounded: tiles within radius + one tile of a view, about
 * {@code pi (r / size + 2)^2} per view; {@link #maxLiveTiles()} gives the bound the streamer keeps.
 *
 * <p>The live tiles are also kept in a dense list in the order of their keys ({@link #live(int)}), so a
 * caller walks them each step without an iterator; the order does not depend on when tiles arrived.
 *
 * <p>Threads: one thread (the stepping thread) calls {@link #update}, {@link #tile}, {@link #live},
 * {@link #liveTiles} and {@link #close}; the workers only run the factory's {@link TileFactory#build}.
 * {@link #update} allocates a task and a map entry per tile started and taken in, and a few small
 * objects per call while tiles are missing (the maps' iterators and boxed keys): bookkeeping of the
 * order of a kilobyte per tile, against the megabytes a tile holds.
 *
 * @param <T> what a tile is built into
 */
public final class TileStreamer<T> implements AutoCloseable {
    private final TileFactory<T> factory;
    private final double size;
    private final double radius;
    private final int budget;
    private final BuildWorkers workers;
    private final Map<Long, T> live = new HashMap<>();
    /** The started tiles not live yet: key, build and the update that started it (dense, unordered). */
    private long[] pendingKeys = new long[16];
    private Future<?>[] pendingBuilds = new Future<?>[16];
    private long[] pendingStart = new long[16];
    private int pending;
    /** Updates a tile takes from its start to being live, or 0: as soon as it is built. */
    private final int latency;
    /** How much farther than the radius tiles are started, metres. */
    private final double prefetch;
    private long updates;
    private long waits;
    private long waitNanos;
    /** The live tiles by ascending key, and their keys. */
    private Object[] liveList = new Object[16];
    private long[] liveKeys = new long[16];
    /** Tiles wanted and missing at the last update, nearest first (reused). */
    private long[] wanted = new long[64];
    private double[] wantedDistance = new double[64];
    private final List<Long> leaving = new ArrayList<>();
    private long built;
    private long livePlants;
    private boolean closed;

    /**
     * A streamer of the placer's tiles' plants. Allocates; starts {@code workers} daemon threads.
     *
     * @param placer  the tiles' placement
     * @param radius  reach of a view, metres: tiles whose square comes this close are kept, &gt; 0 and at
     *                most 64 tiles
     * @param workers threads that build tiles, in [1, 64]
     * @param budget  most tiles started per {@link #update}, in [1, 1024]
     * @return the streamer
     * @throws IllegalArgumentException when an argument is out of range
     */
    public static TileStreamer<TilePlants> of(TilePlacer placer, double radius, int workers, int budget) {
        Require.nonNull("placer", placer);
        return new TileStreamer<>(placer.tileSize(), new TileFactory<>() {
            @Override
            public TilePlants build(int i, int j) {
                return placer.place(i, j);
            }

            @Override
            public int plants(TilePlants tile) {
                return tile.count();
            }
        }, radius, workers, budget);
    }

    /**
     * Makes a streamer. Allocates; starts {@code workers} daemon threads.
     *
     * @param tileSize the tiles' side, metres, in [{@link TilePlacer#MIN_TILE_SIZE}, {@link TilePlacer#MAX_TILE_SIZE}]
     * @param factory  builds a tile
     * @param radius   reach of a view, metres: tiles whose square comes this close are kept, &gt; 0 and at
     *                 most 64 tiles
     * @param workers  threads that build tiles, in [1, 64]
     * @param budget   most tiles started per {@link #update}, in [1, 1024]
     * @throws IllegalArgumentException when an argument is out of range
     */
    public TileStreamer(double tileSize, TileFactory<T> factory, double radius, int workers, int budget) {
        this(tileSize, factory, radius, 0, workers, budget, 0);
    }

    /**
     * Makes a streamer that builds tiles ahead and makes them live on a fixed rule: a tile is started
     * once its square comes within {@code radius + prefetch} of a view, and becomes live at the first
     * update at least {@code latency} updates after its start at which its square lies within
     * {@code radius} of a view, whatever the workers' speed: so what is live at each update depends only
     * on the views' path, never on the number of workers or the machine's load. An update waits for a
     * tile that is due then and not built yet ({@link #waits()} counts it; a streamer whose workers keep
     * pace with the views never waits). Allocates; starts {@code workers} daemon threads.
     *
     * @param tileSize the tiles' side, metres, in [{@link TilePlacer#MIN_TILE_SIZE}, {@link TilePlacer#MAX_TILE_SIZE}]
     * @param factory  builds a tile
     * @param radius   reach of a view, metres: tiles whose square comes this close are kept, &gt; 0 and at
     *                 most 64 tiles
     * @param workers  threads that build tiles, in [1, 64]
     * @param budget   most tiles started per {@link #update}, in [1, 1024]
     * @param prefetch how much farther than the radius tiles are started, metres, in [0, 16 tile sizes]
     * @param latency  fewest updates from a tile's start to its being live, in [1, 1000]; or 0 for as soon
     *                 as it is built (then what is live depends on the workers' speed)
     * @throws IllegalArgumentException when an argument is out of range
     */
    public TileStreamer(double tileSize, TileFactory<T> factory, double radius, double prefetch, int workers,
                        int budget, int latency) {
        this.latency = Require.range("latency", latency, 0, 1000);
        this.prefetch = Require.range("prefetch", prefetch, 0, 16 * tileSize);
        this.size = Require.range("tileSize", tileSize, TilePlacer.MIN_TILE_SIZE, TilePlacer.MAX_TILE_SIZE);
        this.factory = Require.nonNull("factory", factory);
        Require.range("radius", radius, 1e-3, 64 * tileSize);
        Require.range("workers", workers, 1, 64);
        this.budget = Require.range("budget", budget, 1, 1024);
        this.radius = radius;
        this.workers = new BuildWorkers("jecosys-tiles", workers);
    }

    /** {@return the reach of a view, metres} */
    public double radius() {
        return radius;
    }

    /** {@return the most tiles started per update} */
    public int budget() {
        return budget;
    }

    /** {@return the tiles' side, metres} */
    public double tileSize() {
        return size;
    }

    /** {@return the most tiles alive at once per view: those within the radius plus one tile of it} */
    public int maxLiveTiles() {
        int n = (int) Math.ceil((radius + size) / size) + 1;
        return (2 * n) * (2 * n);
    }

    /**
     * Brings the tiles up to date with the views: takes in the tiles finished since the last call, lets
     * go of those beyond radius + one tile of every view, and starts up to {@link #budget()} missing
     * tiles within the radius, nearest first. Waits only for a tile that is due (see the latency) and
     * not built yet. Stepping thread. Allocates nothing while no tile is started, taken in or let go.
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
        updates++;
        if (pending > 0) {
            collect(viewX, viewZ, views, false);
        }
        // let go of tiles beyond radius + one tile of every view
        double keep = radius + size;
        leaving.clear();
        int listed = live.size();
        for (int k = 0; k < listed; k++) {
            if (distance(liveKeys[k], viewX, viewZ, views, size) > keep) {
                leaving.add(liveKeys[k]);
            }
        }
        for (int i = 0; i < leaving.size(); i++) {
            long key = leaving.get(i);
            T t = live.remove(key);
            removeListed(key);
            livePlants -= factory.plants(t);
            factory.release(t);
        }
        for (int k = pending - 1; k >= 0; k--) {
            if (distance(pendingKeys[k], viewX, viewZ, views, size) > keep + prefetch) {
                pendingBuilds[k].cancel(false);
                removePending(k);
            }
        }
        // the missing tiles within the radius, nearest first
        int n = 0;
        for (int v = 0; v < views; v++) {
            double reach = radius + prefetch;
            int i0 = (int) Math.floor((viewX[v] - reach) / size);
            int i1 = (int) Math.floor((viewX[v] + reach) / size);
            int j0 = (int) Math.floor((viewZ[v] - reach) / size);
            int j1 = (int) Math.floor((viewZ[v] + reach) / size);
            for (int i = i0; i <= i1; i++) {
                for (int j = j0; j <= j1; j++) {
                    long key = key(i, j);
                    if (java.util.Arrays.binarySearch(liveKeys, 0, live.size(), key) >= 0
                            || contains(pendingKeys, pending, key) || contains(wanted, n, key)) {
                        continue;
                    }
                    double d = distance(key, viewX, viewZ, views, size);
                    if (d > radius + prefetch) {
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
            if (pending == pendingKeys.length) {
                pendingKeys = java.util.Arrays.copyOf(pendingKeys, 2 * pending);
                pendingBuilds = java.util.Arrays.copyOf(pendingBuilds, 2 * pending);
                pendingStart = java.util.Arrays.copyOf(pendingStart, 2 * pending);
            }
            pendingKeys[pending] = key;
            pendingBuilds[pending] = workers.submit(() -> factory.build(ti, tj));
            pendingStart[pending] = updates;
            pending++;
        }
    }

    /**
     * Takes in the tiles due: those finished on the workers (latency 0), those started at least
     * {@code latency} updates ago that lie within the radius of a view (waiting for them if need be), or
     * every started tile when {@code all}.
     */
    @SuppressWarnings("unchecked")
    private void collect(double[] viewX, double[] viewZ, int views, boolean all) {
        for (int k = pending - 1; k >= 0; k--) {
            long key = pendingKeys[k];
            Future<T> f = (Future<T>) pendingBuilds[k];
            if (!all && (latency == 0 ? !f.isDone() : updates - pendingStart[k] < latency
                    || distance(key, viewX, viewZ, views, size) > radius)) {
                continue;
            }
            if (!all && !f.isDone()) { // a settle waits by design: not counted
                long t0 = System.nanoTime();
                waitFor(f);
                waits++;
                waitNanos += System.nanoTime() - t0;
            }
            removePending(k);
            T t;
            try {
                t = f.get();
            } catch (InterruptedException ex) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while taking in a tile", ex);
            } catch (java.util.concurrent.ExecutionException ex) {
                throw new IllegalStateException("building tile " + (key >> 32) + ", " + (int) key
                        + " failed: " + ex.getCause(), ex.getCause());
            }
            live.put(key, t);
            addListed(key, t);
            livePlants += factory.plants(t);
            built++;
        }
    }

    /** Removes pending entry k (the last one takes its place). */
    private void removePending(int k) {
        pending--;
        pendingKeys[k] = pendingKeys[pending];
        pendingBuilds[k] = pendingBuilds[pending];
        pendingStart[k] = pendingStart[pending];
        pendingBuilds[pending] = null;
    }

    private void addListed(long key, T t) {
        int n = live.size() - 1; // entries listed before this one
        if (n == liveList.length) {
            liveList = java.util.Arrays.copyOf(liveList, 2 * n);
            liveKeys = java.util.Arrays.copyOf(liveKeys, 2 * n);
        }
        int at = n;
        while (at > 0 && liveKeys[at - 1] > key) {
            liveList[at] = liveList[at - 1];
            liveKeys[at] = liveKeys[at - 1];
            at--;
        }
        liveList[at] = t;
        liveKeys[at] = key;
    }

    private void removeListed(long key) {
        int n = live.size() + 1; // entries listed before the removal
        int at = 0;
        while (at < n && liveKeys[at] != key) {
            at++;
        }
        System.arraycopy(liveList, at + 1, liveList, at, n - at - 1);
        System.arraycopy(liveKeys, at + 1, liveKeys, at, n - at - 1);
        liveList[n - 1] = null;
    }

    /**
     * {@return live tile k, in ascending order of the tiles' keys (i, then j)} Stepping thread; no
     * allocation.
     *
     * @param k in [0, {@link #liveTiles()})
     */
    @SuppressWarnings("unchecked")
    public T live(int k) {
        Require.range("k", k, 0, live.size() - 1);
        return (T) liveList[k];
    }

    /**
     * {@return the index along X of live tile k} Stepping thread.
     *
     * @param k in [0, {@link #liveTiles()})
     */
    public int liveI(int k) {
        Require.range("k", k, 0, live.size() - 1);
        return (int) (liveKeys[k] >> 32);
    }

    /**
     * {@return the index along Z of live tile k} Stepping thread.
     *
     * @param k in [0, {@link #liveTiles()})
     */
    public int liveJ(int k) {
        Require.range("k", k, 0, live.size() - 1);
        return (int) liveKeys[k];
    }

    /**
     * Waits until every started tile is finished and takes them in (tests, loading screens). Stepping
     * thread.
     *
     * @throws IllegalStateException when a tile's placement failed
     */
    public void settle() {
        for (int k = 0; k < pending; k++) {
            waitFor(pendingBuilds[k]);
        }
        collect(null, null, 0, true);
    }

    private void waitFor(Future<?> f) {
        if (f.isDone()) {
            return;
        }
        factory.waiting(true);
        try {
            f.get();
        } catch (InterruptedException ex) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for tiles", ex);
        } catch (java.util.concurrent.ExecutionException ex) {
            throw new IllegalStateException("building a tile failed: " + ex.getCause(), ex.getCause());
        } finally {
            factory.waiting(false);
        }
    }

    /** {@return how often an update had to wait for a tile that was due and not built yet} */
    public long waits() {
        return waits;
    }

    /** {@return the time updates spent waiting for tiles, nanoseconds} */
    public long waitNanos() {
        return waitNanos;
    }

    /**
     * {@return tile (i, j) if it is alive, else null} Stepping thread; may box the key.
     *
     * @param i the tile's index along X
     * @param j the tile's index along Z
     */
    public T tile(int i, int j) {
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
        return pending;
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
            for (T t : live.values()) {
                factory.release(t);
            }
            live.clear();
            java.util.Arrays.fill(liveList, null);
            java.util.Arrays.fill(pendingBuilds, null);
            pending = 0;
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
