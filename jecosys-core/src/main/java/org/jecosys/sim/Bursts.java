package org.jecosys.sim;

/**
 * The stepping thread's rhythm: its fixed steps come in bursts (the steps of one {@code step(dt)}, each
 * but the last saying another follows at once), and a game's loop starts a burst once a frame. Kept
 * for the animation pool ({@link WorkerPool}: when its threads wake before the next burst) and for an
 * open world's tile builds ({@link TileBuilds}: whether a build phase fits before it). Stepping thread
 * only; no allocation.
 */
final class Bursts {
    /** Intervals that differ from the period by at most this keep it, nanoseconds. */
    static final long MATCH_NANOS = 1_000_000;
    /** Intervals longer than this are no frame's rhythm (a pause), nanoseconds. */
    static final long LONGEST_INTERVAL = 250_000_000;
    /** How many intervals in a row may miss the period (a late frame, the early one after it) before it is dropped. */
    static final int MISSES_KEPT = 3;
    /** Farthest the frame's grid and the last start's own rhythm may disagree and both be expected, nanoseconds. */
    static final long GRID_SPREAD = 4_000_000;
    private boolean inBurst;
    private long start;
    private long interval;
    private long lastInterval;
    /** The steady interval between burst starts, ns; 0: none. */
    private long period;
    private int misses;
    /** Where the frame's grid puts the next burst's start (System.nanoTime()); 0: no grid. */
    private long grid;
    private long earliest;
    private long latest;

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
            rhythm(now);
        }
        inBurst = followed;
        return begins;
    }

    /**
     * Updates the period and the window in which the next burst is expected, at a burst's start
     * {@code now}. The period survives up to {@link #MISSES_KEPT} intervals that miss it by more than
     * {@link #MATCH_NANOS} (a late frame and the early one after it, as a loop paced by deadlines or a
     * display's refresh recovers); a new one is taken when two intervals in a row agree. The next start
     * is expected a period after this one, or a period after where the frame's grid put this one,
     * whichever is earlier, up to the other (at most {@link #GRID_SPREAD} apart).
     */
    private void rhythm(long now) {
        boolean pause = interval <= 0 || interval > LONGEST_INTERVAL;
        if (pause) {
            period = 0;
            misses = 0;
        } else if (period > 0 && Math.abs(interval - period) <= MATCH_NANOS) {
            period += (interval - period) / 4; // follows a slow drift of the loop's own clock
            misses = 0;
        } else if (lastInterval > 0 && Math.abs(interval - lastInterval) <= MATCH_NANOS) {
            period = interval; // a new rhythm: two intervals agree
            misses = 0;
        } else if (period > 0 && ++misses > MISSES_KEPT) {
            period = 0;
            misses = 0;
        }
        if (period == 0) {
            grid = 0;
            earliest = 0;
            latest = 0;
            return;
        }
        long own = now + period;
        long onGrid = grid != 0 && Math.abs(now - grid) <= GRID_SPREAD ? grid + period : own;
        grid = onGrid;
        earliest = Math.min(own, onGrid);
        latest = Math.max(own, onGrid);
    }

    /** {@return the steady interval between burst starts, ns; 0 when the bursts keep none} */
    long period() {
        return period;
    }

    /** {@return the earliest the next burst is expected to start, System.nanoTime(); 0: no rhythm} */
    long earliestNext() {
        return earliest;
    }

    /** {@return the latest the next burst is expected to start, System.nanoTime(); 0: no rhythm} */
    long latestNext() {
        return latest;
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
