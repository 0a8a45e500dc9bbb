package org.jecosys.bench;

/**
 * The open-world bench's slow steps (over 1.5 times the median wall time): how many did the usual work
 * on fewer cores, and how many overlapped a collector's pause. Bench only; static helpers that allocate
 * their results.
 */
final class SlowSteps {
    /** A step is slow when its wall time is over this many times the median's. */
    static final double FACTOR = 1.5;

    private SlowSteps() {
    }

    /**
     * Of steps' wall and CPU times (ms, per fixed step): how many took over 1.5 times the median wall
     * time, how many of those had a CPU time within 1.3 times the median CPU time, and the median CPU over
     * wall ratio in those slow steps and in all. A step whose work was the usual one but whose wall time
     * was long waited for a core: the machine's, not the library's.
     */
    static double[] count(double[] wallMs, double[] cpuMs) {
        double wallMedian = Stats.median(wallMs);
        double cpuMedian = Stats.median(cpuMs);
        int slow = 0;
        int usual = 0;
        double[] slowRatio = new double[wallMs.length];
        double[] ratio = new double[wallMs.length];
        for (int i = 0; i < wallMs.length; i++) {
            ratio[i] = cpuMs[i] / wallMs[i];
            if (wallMs[i] > FACTOR * wallMedian) {
                slowRatio[slow++] = ratio[i];
                usual += cpuMs[i] <= 1.3 * cpuMedian ? 1 : 0;
            }
        }
        return new double[] {slow, usual, slow > 0 ? Stats.median(java.util.Arrays.copyOf(slowRatio, slow)) : Double.NaN,
                Stats.median(ratio)};
    }

    /** {@return for each of the first {@code n} steps ({@code start} to {@code end}, ns) whether one of {@code pauses} overlapped it} */
    static boolean[] inPause(long[] start, long[] end, int n, CollectorPauses pauses) {
        boolean[] in = new boolean[n];
        for (int i = 0; i < n; i++) {
            in[i] = pauses.overlaps(start[i], end[i]);
        }
        return in;
    }

    /** {@return how many steps over {@link #FACTOR} times the median wall time fell in a pause ({@code inPause})} */
    static int inPauses(double[] wallMs, boolean[] inPause) {
        double median = Stats.median(wallMs);
        int n = 0;
        for (int i = 0; i < wallMs.length; i++) {
            n += wallMs[i] > FACTOR * median && inPause[i] ? 1 : 0;
        }
        return n;
    }
}
