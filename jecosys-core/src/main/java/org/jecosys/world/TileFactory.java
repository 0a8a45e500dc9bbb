package org.jecosys.world;

/**
 * Builds a tile on a worker thread, and counts what it holds.
 *
 * @param <T> what a tile is built into
 */
public interface TileFactory<T> {
    /**
     * Builds tile (i, j): a pure function of the indices (and what the factory was made with), so a
     * tile built twice is the same tile. Runs on a worker thread; may allocate.
     *
     * @param i the tile's index along X
     * @param j the tile's index along Z
     * @return the tile, not null
     */
    T build(int i, int j);

    /**
     * {@return the plants in a built tile}
     *
     * @param tile a tile this factory built
     */
    int plants(T tile);

    /**
     * Called on the stepping thread when a live tile is let go (or the streamer closes), to free
     * what it holds beyond the garbage collector's reach. The default does nothing.
     *
     * @param tile a tile this factory built
     */
    default void release(T tile) {
    }

    /**
     * Called on the stepping thread with {@code true} before the streamer waits for a tile being built
     * (a tile due and not finished, or a settle), and with {@code false} when the wait is over: a
     * factory that holds its builds back while the game's frame runs lets them through meanwhile. The
     * default does nothing.
     *
     * @param waiting whether the stepping thread is about to wait (true) or done waiting (false)
     */
    default void waiting(boolean waiting) {
    }
}
