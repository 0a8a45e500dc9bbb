package org.jecosys.bench;

import org.jecosys.math.Require;

/**
 * Several configurations measured side by side, taking turns: each round, every configuration runs
 * a block of {@code block} steps, and the order of the turns is rotated by one from round to round.
 * On a shared machine the speed of the same work drifts over seconds (other processes, the GL
 * rasteriser's threads); run one after the other, each configuration would get a different share of
 * fast and slow stretches, while in turns they get the same share, so their ratios compare like with
 * like. One thread; no allocation.
 */
final class Turns {
    /** One step of one configuration. */
    interface Step {
        /**
         * @param config the configuration, 0 .. configs-1
         * @param index  this configuration's step number, 0 .. total-1
         */
        void run(int config, int index);
    }

    private Turns() {
    }

    /**
     * Runs {@code total} steps of each of {@code configs} configurations in turns of {@code block}.
     *
     * @param block steps per turn, &gt;= 1
     */
    static void run(int configs, int total, int block, Step step) {
        Require.range("configs", configs, 1, 1 << 10);
        Require.range("total", total, 0, Integer.MAX_VALUE);
        Require.range("block", block, 1, Integer.MAX_VALUE);
        for (int done = 0; done < total; done += block) { // one round; every configuration is at done
            int steps = Math.min(block, total - done);
            int round = done / block;
            for (int j = 0; j < configs; j++) {
                int c = (j + round) % configs;
                for (int b = 0; b < steps; b++) {
                    step.run(c, done + b);
                }
            }
        }
    }
}
