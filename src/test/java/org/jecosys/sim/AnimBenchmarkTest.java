package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import org.jecosys.anim.AnimationMode;
import org.jecosys.anim.AnimationState;
import org.jecosys.anim.SpringKinds;
import org.jecosys.math.Rng;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Animation benchmark (issue "Animation and simulation", Performance): component updates per
 * second of the constraint updater for 10k, 100k, 1M and 4M components (plants of 10 components,
 * all visible, wind everywhere) with 1 and 2 workers over fixed chunks, including the copy of the
 * outputs into a frame, and the ratio of the step to a plain copy of the same six state arrays
 * (D, v, pose, azimuth: the memory bound) with the same workers. Reports only; asserts no timing.
 * Run with {@code mvn -B verify -Pbench}; writes target/bench/anim.md.
 */
@Tag("benchmark")
class AnimBenchmarkTest {
    static final int PER_PLANT = 10;

    /** State arrays of n components and their chunking. */
    static final class Case implements WorkerPool.ChunkTask {
        final AnimationState state;
        final int plants;
        final int[] chunkFirst;
        final float[] wx;
        final float[] wz;
        final boolean[] vis;
        final float[] poseOut;
        final float[] azOut;
        final float[][] src = new float[6][];
        final float[][] dst = new float[6][];
        boolean copyOnly;

        Case(int n) {
            plants = n / PER_PLANT;
            SpringKinds.Builder b = new SpringKinds.Builder();
            for (int k = 0; k < 16; k++) {
                b.add(0.2 + 0.05 * k, 0.2 + 0.02 * k, 0.001, 0.002, 0.3 + 0.01 * k, 0.05, 1.2, 16, 0xFF);
            }
            SpringKinds kinds = b.build();
            int[] first = new int[plants + 1];
            for (int p = 0; p <= plants; p++) {
                first[p] = p * PER_PLANT;
            }
            int[] kind = new int[n];
            float[] heading = new float[n];
            Rng rng = new Rng(7);
            for (int c = 0; c < n; c++) {
                kind[c] = rng.nextInt(16);
                heading[c] = (float) rng.nextDouble(0, 6.28);
            }
            state = new AnimationState(kinds, new double[][] {{}}, new int[plants], first, new float[plants],
                    new float[plants], new float[plants], kind, heading);
            wx = new float[plants];
            wz = new float[plants];
            vis = new boolean[plants];
            for (int p = 0; p < plants; p++) {
                wx[p] = (float) rng.nextDouble(1, 6);
                wz[p] = (float) rng.nextDouble(-3, 3);
                vis[p] = true;
            }
            poseOut = new float[n];
            azOut = new float[n];
            int chunkPlants = Simulation.CHUNK_COMPONENTS / PER_PLANT;
            int chunks = (plants + chunkPlants - 1) / chunkPlants;
            chunkFirst = new int[chunks + 1];
            for (int c = 0; c <= chunks; c++) {
                chunkFirst[c] = Math.min(plants, c * chunkPlants);
            }
            for (int i = 0; i < 6; i++) {
                src[i] = new float[n];
                dst[i] = new float[n];
            }
            kinds.prepare(1.0 / 60, 4);
        }

        @Override
        public void runChunk(int chunk) {
            int p0 = chunkFirst[chunk];
            int p1 = chunkFirst[chunk + 1];
            int c0 = p0 * PER_PLANT;
            int c1 = p1 * PER_PLANT;
            if (copyOnly) {
                for (int i = 0; i < 6; i++) {
                    System.arraycopy(src[i], c0, dst[i], c0, c1 - c0);
                }
                return;
            }
            state.animate(p0, p1, AnimationMode.CONSTRAINT, wx, wz, vis, 0, 0, 0, null);
            state.copyOutputs(c0, c1, poseOut, azOut);
        }
    }

    static double medianNanos(WorkerPool pool, int reps) {
        long[] t = new long[reps];
        for (int i = 0; i < reps; i++) {
            long t0 = System.nanoTime();
            pool.start();
            pool.await();
            t[i] = System.nanoTime() - t0;
        }
        Arrays.sort(t);
        return t[reps / 2];
    }

    @Test
    void componentUpdatesPerSecond() throws IOException {
        int[] sizes = {10_000, 100_000, 1_000_000, 4_000_000};
        StringBuilder md = new StringBuilder("# Animation benchmark\n\n")
                .append("Constraint mode, 4 sub-intervals, plants of ").append(PER_PLANT)
                .append(" components, all visible, fixed chunks of ").append(Simulation.CHUNK_COMPONENTS)
                .append(" components; step = update + copy of pose/azimuth into a frame. Copy = the six state ")
                .append("arrays copied by the same workers. Medians; ")
                .append(Runtime.getRuntime().availableProcessors()).append(" processors.\n\n")
                .append("| components | workers | step ms | updates/s | copy ms | step/copy | speed-up |\n")
                .append("|---:|---:|---:|---:|---:|---:|---:|\n");
        for (int n : sizes) {
            Case k = new Case(n);
            double one = 0;
            for (int w = 1; w <= 2; w++) {
                int reps = n >= 1_000_000 ? 40 : 400;
                int chunks = k.chunkFirst.length - 1;
                try (WorkerPool pool = new WorkerPool("bench", w, chunks, k)) {
                    k.copyOnly = false;
                    medianNanos(pool, reps / 2 + 10);
                    double step = medianNanos(pool, reps);
                    k.copyOnly = true;
                    medianNanos(pool, reps / 4 + 5);
                    double copy = medianNanos(pool, reps);
                    if (w == 1) {
                        one = step;
                    }
                    double ups = n / (step / 1e9);
                    md.append(String.format(Locale.ROOT, "| %,d | %d | %.3f | %.3g | %.3f | %.2f | %s |%n", n, w,
                            step / 1e6, ups, copy / 1e6, step / copy, w == 1 ? "1.00" : String.format(Locale.ROOT,
                                    "%.2f", one / step)));
                }
            }
            assertTrue(Float.isFinite(k.state.deviationX(n - 1)));
        }
        md.append("\nTargets (reported, not asserted): >= 2e8 updates/s with 2 workers, step <= 3x copy, ")
                .append("2 workers >= 1.8x one.\n");
        Path out = Path.of("target/bench/anim.md");
        Files.createDirectories(out.getParent());
        Files.writeString(out, md);
        System.out.println(md);
    }
}
