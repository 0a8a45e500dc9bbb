package org.jecosys.sim;

/**
 * The stepping thread's rhythm: its fixed steps come in bursts (the steps of one {@code step(dt)}, each
 * but the last saying another follows at once), and a game's loop starts a burst once a frame. Kept
 * for the animation pool ({@link WorkerPool}: when its threads wake before the next burst) and for an
 * open world's tile builds ({@link TileBuilds}: whether a build phase fits before it). Stepping thread
 * only; no allocation.
 */
final class Bursts {
    private boolean inBurst;
    private long start;
    private long interval;
    private long lastInterval;

    /**
     * A fixed step starts at {@code now} (System.nanoTime()).
     *
     * @param followed whether another fixed step follows this one at once, in the same burst
     * @return whether this step began a burst (then {@link #start}, {@link #interval} and
     *         {@link #lastInterval} are this burst's)
     */
    boolean step(boolean followed, long now) {
        boolean begins = !inBurst;
        if (begins) {
            lastInterval = interval;
            interval = start == 0 ? 0 : now - start;
            start = now;
        }
        inBurst = followed;
        return begins;
    }

    /** The burst ended whatever its last step said (a step that threw): the next step begins one. */
    void end() {
        inBurst = false;
    }

    /** {@return when the last burst began, System.nanoTime(); 0 before the first} */
    long start() {
        return start;
    }

    /** {@return the interval from the burst before to the last one's start, ns; 0 for the first} */
    long interval() {
        return interval;
    }

    /** {@return the interval before {@link #interval()}, ns; 0 when there was none} */
    long lastInterval() {
        return lastInterval;
    }
}
