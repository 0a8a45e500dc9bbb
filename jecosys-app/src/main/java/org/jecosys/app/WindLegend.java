package org.jecosys.app;

import org.jecosys.field.FieldDebugView;

/**
 * The speed scale of the wind overlay and its legend: the top of the scale is a round number (1, 2
 * or 5 times a power of ten, m/s) at or above the wind that 90% of what the visible plants feel stays
 * under (the wind of the force field's visible effective nodes, paper §3; the few nodes by a vortex's
 * core would otherwise turn everything else blue). It rises at once when the wind gets faster and
 * falls only once the wind has stayed below 40% of it for two seconds, so the colours do not flicker
 * with every gust. Render thread; no allocation once its buffer has grown to the field's size.
 */
final class WindLegend {
    /** Lowest top of the scale, m/s. */
    static final double MIN_SCALE = 1;
    /** Seconds the wind must stay low before the scale falls. */
    static final double FALL_DELAY = 2;

    private static final double[] STEPS = {1, 2, 5, 10};

    private double scale = MIN_SCALE;
    private double low;
    private double speed;

    /** The smallest of 1, 2, 5 x 10^k m/s at or above {@code speed}, at least {@link #MIN_SCALE}. */
    static double niceScale(double speed) {
        if (!(speed > MIN_SCALE)) {
            return MIN_SCALE;
        }
        double p = Math.pow(10, Math.floor(Math.log10(speed)));
        for (double m : STEPS) {
            if (m * p >= speed * (1 - 1e-12)) {
                return m * p;
            }
        }
        return 10 * p;
    }

    private float[] speeds = new float[256];

    /**
     * The wind speed that 90% of the visible effective nodes stay at or under, m/s (0 with no field).
     * Sorts a reused buffer.
     */
    double typical(FieldDebugView view) {
        if (view == null) {
            return 0;
        }
        int n = 0;
        for (int i = 0; i < view.nodeCount(); i++) {
            if (view.effective(i) && view.visible(i)) {
                float x = view.windX(i);
                float z = view.windZ(i);
                if (n == speeds.length) {
                    speeds = java.util.Arrays.copyOf(speeds, 2 * n);
                }
                speeds[n++] = (float) Math.sqrt(x * x + z * z);
            }
        }
        if (n == 0) {
            return 0;
        }
        java.util.Arrays.sort(speeds, 0, n);
        return speeds[Math.min(n - 1, (int) Math.ceil(0.9 * n) - 1)];
    }

    /**
     * Updates the scale with the wind now.
     *
     * @param speed the typical fast wind now ({@link #typical}), m/s
     * @param dt    seconds since the last update
     */
    void update(double speed, double dt) {
        this.speed = speed;
        double want = niceScale(speed);
        if (want > scale) {
            scale = want;
            low = 0;
        } else if (speed < 0.4 * scale) {
            low += dt;
            if (low >= FALL_DELAY) {
                scale = want;
                low = 0;
            }
        } else {
            low = 0;
        }
    }

    /** {@return the wind speed at the top of the scale (drawn red), m/s} */
    double scale() {
        return scale;
    }

    /** {@return the speed given to the last update, m/s} */
    double speed() {
        return speed;
    }
}
