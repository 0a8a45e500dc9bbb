package org.jecosys.bench;

import java.util.Arrays;

/** Medians, percentiles, means and standard deviations of samples. Pure; any thread; allocates a sorted copy. */
public final class Stats {
    private Stats() {
    }

    /** The median. */
    public static double median(double[] xs) {
        return percentile(xs, 0.5);
    }

    /** The p-th quantile (0..1) by nearest rank of a sorted copy. */
    public static double percentile(double[] xs, double p) {
        if (xs.length == 0) {
            return Double.NaN;
        }
        double[] s = xs.clone();
        Arrays.sort(s);
        int i = (int) Math.min(s.length - 1, Math.max(0, Math.round(p * (s.length - 1))));
        return s[i];
    }

    public static double mean(double[] xs) {
        double sum = 0;
        for (double x : xs) {
            sum += x;
        }
        return xs.length == 0 ? Double.NaN : sum / xs.length;
    }

    /** Sample standard deviation. */
    public static double sd(double[] xs) {
        if (xs.length < 2) {
            return 0;
        }
        double m = mean(xs);
        double ss = 0;
        for (double x : xs) {
            ss += (x - m) * (x - m);
        }
        return Math.sqrt(ss / (xs.length - 1));
    }
}
