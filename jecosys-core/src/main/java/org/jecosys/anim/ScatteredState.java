package org.jecosys.anim;

import org.jecosys.math.Rng;

/**
 * The per-component velocities of plants in RANDOM mode (paper Table 7's S2), where each component
 * takes a random deviation of its own, so the components of a spring run no longer share their state
 * ({@link SpringRuns}). A plant is <em>scattered</em> from its first random update until it settles or
 * rests again; meanwhile its components' D are their own entries of {@link SpringRuns#compDev}
 * (not their run's) and their v are read here. Sized at construction (every component may scatter); no allocation after. A caller
 * touches only its own plants' entries, so disjoint plant ranges may run at once.
 */
final class ScatteredState {
    /** Per plant, whether its components' state lives here. */
    final boolean[] scattered;
    /** Per component its velocity (X, Z), m/s, while its plant is scattered. */
    final float[] velX;
    final float[] velZ;

    ScatteredState(int plants, int components) {
        scattered = new boolean[plants];
        velX = new float[components];
        velZ = new float[components];
    }

    /**
     * RANDOM mode for plant p: scatters it first (each component keeps its run's D and takes its v), then each
     * of its components {@code c0 .. c1-1} whose kind's level-of-detail mask has {@code bit} takes a
     * random deviation in a disc of radius 0.3 length from rng, at zero velocity, in component order.
     *
     * @return components updated
     */
    int randomise(int p, int c0, int c1, int bit, SpringRuns runs, short[] kind, int[] masks, float[] length,
                  Rng rng) {
        if (!scattered[p]) {
            for (int r = runs.plantRun[p], re = runs.plantRun[p + 1]; r < re; r++) {
                int s = runs.start[r];
                int e = runs.start[r + 1];
                java.util.Arrays.fill(velX, s, e, runs.velX(r));
                java.util.Arrays.fill(velZ, s, e, runs.velZ(r));
            }
            scattered[p] = true;
        }
        int updated = 0;
        for (int c = c0; c < c1; c++) {
            int k = kind[c];
            if ((masks[k] & bit) != 0) {
                float r = 0.3f * length[k] * (float) Math.sqrt(rng.nextDouble());
                float a = (float) (rng.nextDouble() * 2 * Math.PI);
                float ca = (float) StrictMath.cos(a);
                runs.compDev[c] = SpringRuns.pack(r * ca, r * (float) StrictMath.sin(a));
                velX[c] = 0;
                velZ[c] = 0;
                updated++;
            }
        }
        return updated;
    }
}
