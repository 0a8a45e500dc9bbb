package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import org.jecosys.anim.AnimationMode;
import org.jecosys.anim.AnimationState;
import org.jecosys.anim.AnimationStep;
import org.jecosys.anim.SpringKinds;
import org.jecosys.math.Rng;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Animation benchmark (issue "Animation and simulation", Performance): component updates per
 * second of the constraint updater for 10k, 100k, 1M and 4M components (all plants visible, wind
 * everywhere) with 1 and 2 workers over fixed chunks, including writing the deviations into a frame,
 * and the ratio of the step to a plain copy of the same six state arrays (D, v, pose, azimuth: the
 * memory bound) with the same workers. Reports only; asserts no timing. Run with
 * {@code mvn -B verify -Pbench}; writes target/bench/anim.md.
 *
 * <p>The plants are laid out like the shipped species: three in four are grass tufts of 25 leaves
 * (one component type, 8 shape variants, slot j of a plant of variant v using variant (v + j) mod 8,
 * as {@code SpeciesModel} assigns them), one in four a flower of 10 components (1 stem, 6 leaves, 3
 * heads: three component types of 4 variants each, the leaves not drawn at level 2). Kinds of one
 * component type share its spring constants (stiffness, response time, drag area) and differ in
 * shape (mass, length, lean, max bend), as {@code SpringKinds.of} builds them. The species of each
 * plant is random; the last plant is a tuft trimmed to the exact size. (Until this layout the
 * benchmark gave every component a random one of 16 unrelated kinds, which no scene does.)
 */
@Tag("benchmark")
class AnimBenchmarkTest {
    static final int TUFT = 25;
    static final int FLOWER = 10;

    /** State arrays of n components and their chunking. */
    static final class Case implements WorkerPool.ChunkTask {
        final AnimationState state;
        final int plants;
        final int[] chunkFirst;
        final float[] wx;
        final float[] wz;
        final boolean[] vis;
        /** The render states of a frame (deviations, 2 floats per component, one long). */
        final java.nio.LongBuffer states;
        /** Per chunk, its animate inputs (chunks run on several workers at once). */
        final AnimationStep[] steps;
        final float[][] src = new float[6][];
        final float[][] dst = new float[6][];
        boolean copyOnly;

        Case(int n) {
            SpringKinds.Builder b = new SpringKinds.Builder();
            // grass leaf: kinds 0..7; flower stem 8..11, leaf 12..15, head 16..19
            for (int v = 0; v < 8; v++) {
                b.add(0.2, 0.25, 0.0004 * (1 + 0.05 * v), 0.002, 0.45 * (0.9 + 0.03 * v), 0.08 + 0.01 * v,
                        1.2 - 0.02 * v, 16, 0b111);
            }
            for (int v = 0; v < 4; v++) {
                b.add(2.0, 0.4, 0.003, 0.004, 0.6 + 0.02 * v, 0.02 + 0.005 * v, 0.8, 16, 0b111);
            }
            for (int v = 0; v < 4; v++) {
                b.add(0.5, 0.3, 0.0005, 0.001, 0.2 + 0.01 * v, 0.05, 1.0, 16, 0b011);
            }
            for (int v = 0; v < 4; v++) {
                b.add(1.0, 0.35, 0.002, 0.003, 0.1, 0.01, 0.6, 16, 0b111);
            }
            SpringKinds kinds = b.build();
            Rng rng = new Rng(7);
            int[] kind = new int[n];
            float[] heading = new float[n];
            int[] firstTmp = new int[n + 1];
            int p = 0;
            int c = 0;
            while (c < n) {
                firstTmp[p++] = c;
                int v = rng.nextInt(8);
                double rest = rng.nextDouble(0, 6.28);
                if (rng.nextInt(4) == 0 && n - c >= FLOWER) {
                    for (int j = 0; j < FLOWER; j++, c++) {
                        int type = j == 0 ? 0 : j <= 6 ? 1 : 2;
                        kind[c] = 8 + 4 * type + (v + j) % 4;
                        heading[c] = (float) (rest + 2.4 * j);
                    }
                } else {
                    for (int j = 0; j < TUFT && c < n; j++, c++) {
                        kind[c] = (v + j) % 8;
                        heading[c] = (float) (rest + 2.4 * j);
                    }
                }
            }
            plants = p;
            firstTmp[p] = n;
            int[] first = Arrays.copyOf(firstTmp, plants + 1);
            state = new AnimationState(kinds, new double[][] {{}}, new int[plants], first, new float[plants],
                    new float[plants], new float[plants], kind, heading);
            wx = new float[plants];
            wz = new float[plants];
            vis = new boolean[plants];
            for (int q = 0; q < plants; q++) {
                wx[q] = (float) rng.nextDouble(1, 6);
                wz[q] = (float) rng.nextDouble(-3, 3);
                vis[q] = true;
            }
            states = java.nio.ByteBuffer.allocateDirect(8 * n).order(java.nio.ByteOrder.LITTLE_ENDIAN).asLongBuffer();
            int[] chunks = new int[plants + 2]; // the chunking rule of Simulation
            int m = 0;
            chunks[m++] = 0;
            int start = 0;
            for (int q = 0; q < plants; q++) {
                if (first[q + 1] - first[start] >= Simulation.CHUNK_COMPONENTS) {
                    chunks[m++] = q + 1;
                    start = q + 1;
                }
            }
            if (chunks[m - 1] != plants) {
                chunks[m++] = plants;
            }
            chunkFirst = Arrays.copyOf(chunks, m);
            steps = new AnimationStep[m - 1];
            for (int i = 0; i < steps.length; i++) {
                steps[i] = AnimationStep.of(AnimationMode.CONSTRAINT, wx, wz, vis);
            }
            for (int i = 0; i < 6; i++) {
                src[i] = new float[n];
                dst[i] = new float[n];
            }
            kinds.prepare(1.0 / 60, 4);
        }

        @Override
        public void runChunk(int chunk, int worker) {
            int p0 = chunkFirst[chunk];
            int p1 = chunkFirst[chunk + 1];
            int c0 = state.firstComponent(p0);
            int c1 = state.firstComponent(p1);
            if (copyOnly) {
                for (int i = 0; i < 6; i++) {
                    System.arraycopy(src[i], c0, dst[i], c0, c1 - c0);
                }
                return;
            }
            state.animate(p0, p1, steps[chunk]);
            state.copyDeviations(c0, c1, states);
        }
    }

    static double medianNanos(WorkerPool pool, int reps) {
        long[] t = new long[reps];
        for (int i = 0; i < reps; i++) {
            long t0 = System.nanoTime();
            pool.start(i + 1 < reps); // back to back: the workers spin for the next
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
                .append("Constraint mode, 4 sub-intervals, 3/4 grass tufts of ").append(TUFT)
                .append(" leaves (8 variants) and 1/4 flowers of ").append(FLOWER)
                .append(" components (3 types), all visible, fixed chunks of ").append(Simulation.CHUNK_COMPONENTS)
                .append(" components; step = update + deviations written into a frame. Copy = the six state ")
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
