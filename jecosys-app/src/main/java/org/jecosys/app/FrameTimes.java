package org.jecosys.app;

/** Frame times over the last second: mean and standard deviation of the frame rate for the HUD. No allocation. */
final class FrameTimes {
    private final double[] dt = new double[2048];
    private int head;
    private int count;

    void add(double seconds) {
        dt[head] = seconds;
        head = (head + 1) % dt.length;
        count = Math.min(count + 1, dt.length);
    }

    /** Writes {mean fps, sd fps} over the frames of the last second into dest. */
    void fps(double[] dest) {
        double sum = 0;
        int n = 0;
        for (int i = 1; i <= count && sum < 1.0; i++) {
            sum += dt[(head - i + dt.length) % dt.length];
            n++;
        }
        if (n == 0) {
            dest[0] = 0;
            dest[1] = 0;
            return;
        }
        double mean = 0;
        for (int i = 1; i <= n; i++) {
            mean += 1 / Math.max(1e-6, dt[(head - i + dt.length) % dt.length]);
        }
        mean /= n;
        double var = 0;
        for (int i = 1; i <= n; i++) {
            double f = 1 / Math.max(1e-6, dt[(head - i + dt.length) % dt.length]) - mean;
            var += f * f;
        }
        dest[0] = mean;
        dest[1] = Math.sqrt(var / n);
    }
}
