package org.jecosys.anim;

import java.util.Arrays;
import org.jecosys.math.Rng;

/**
 * The spring runs of {@link AnimationState} (see "Update order" there) and the step that advances
 * them: maximal runs of consecutive components of one plant that share their spring coefficients
 * ({@link SpringKinds#springClass}) and their level-of-detail mask. Run r covers components
 * {@code start[r] .. start[r + 1] - 1} (no run is empty); plant p owns runs {@code plantRun[p] ..
 * plantRun[p + 1] - 1}. The arrays are built once (allocates) and then read in place by the caller;
 * the steps ({@link #setForce}, {@link #spring}, and RANDOM mode's {@link #randomise}) are static
 * over the caller's arrays and allocate nothing.
 */
final class SpringRuns {
    /** Force terms per run in {@code runForce}: bD P0x, cD P1x, bD P0z, cD P1z, bV P0x, cV P1x, bV P0z, cV P1z. */
    static final int FORCE_STRIDE = 8;

    /** Per run its first component, plus the component count at the end (length runs + 1). */
    final int[] start;
    /** Per run its spring class. */
    final int[] springClass;
    /** Per run its level-of-detail mask. */
    final int[] mask;
    /** Per plant its first run, plus the run count at the end (length plants + 1). */
    final int[] plantRun;

    /**
     * Cuts the components of each plant into runs. Build time; allocates.
     *
     * @param kinds          the component kinds
     * @param kind           per component its kind
     * @param firstComponent per plant its first component, plus the total at the end
     */
    SpringRuns(SpringKinds kinds, short[] kind, int[] firstComponent) {
        int plants = firstComponent.length - 1;
        int components = kind.length;
        int[] rs = new int[components + 1];
        int[] rc = new int[components];
        int[] rm = new int[components];
        plantRun = new int[plants + 1];
        int runs = 0;
        for (int p = 0; p < plants; p++) {
            plantRun[p] = runs;
            for (int c = firstComponent[p]; c < firstComponent[p + 1]; c++) {
                int cls = kinds.springClass(kind[c]);
                int m = kinds.lodMask[kind[c]];
                if (c == firstComponent[p] || cls != rc[runs - 1] || m != rm[runs - 1]) {
                    rs[runs] = c;
                    rc[runs] = cls;
                    rm[runs] = m;
                    runs++;
                }
            }
        }
        plantRun[plants] = runs;
        rs[runs] = components;
        start = Arrays.copyOf(rs, runs + 1);
        springClass = Arrays.copyOf(rc, runs);
        mask = Arrays.copyOf(rm, runs);
    }

    /** Number of runs. */
    int count() {
        return springClass.length;
    }

    /**
     * Writes run r's {@value #FORCE_STRIDE} force terms into {@code runForce} from the plant's force
     * before ({@code p0}) and now ({@code p1}), with the coefficients of its spring class cls.
     */
    static void setForce(int r, int cls, float[] co, float[] runForce, float p0x, float p0z, float p1x, float p1z) {
        int o = cls * SpringKinds.STRIDE;
        float bD = co[o + 2];
        float cD = co[o + 3];
        float bV = co[o + 6];
        float cV = co[o + 7];
        int f = r * FORCE_STRIDE;
        runForce[f] = bD * p0x;
        runForce[f + 1] = cD * p1x;
        runForce[f + 2] = bD * p0z;
        runForce[f + 3] = cD * p1z;
        runForce[f + 4] = bV * p0x;
        runForce[f + 5] = cV * p1x;
        runForce[f + 6] = bV * p0z;
        runForce[f + 7] = cV * p1z;
    }

    /**
     * RANDOM mode: each component of {@code c0 .. c1-1} whose kind's level-of-detail mask has
     * {@code bit} takes a random deviation in a disc of radius 0.3 length (paper Table 7's S2) from
     * rng, at zero velocity.
     *
     * @return components updated
     */
    static int randomise(int c0, int c1, int bit, short[] kind, int[] masks, float[] length, Rng rng, float[] devX,
                         float[] devZ, float[] velX, float[] velZ) {
        int updated = 0;
        for (int c = c0; c < c1; c++) {
            int k = kind[c];
            if ((masks[k] & bit) != 0) {
                float r = 0.3f * length[k] * (float) Math.sqrt(rng.nextDouble());
                float a = (float) (rng.nextDouble() * 2 * Math.PI);
                float ca = (float) StrictMath.cos(a);
                devX[c] = r * ca;
                devZ[c] = r * (float) StrictMath.sin(a);
                velX[c] = 0;
                velZ[c] = 0;
                updated++;
            }
        }
        return updated;
    }

    /**
     * Advances the components of runs {@code r0 .. r1-1} (contiguous, all of spring class cls) by
     * eq. 5's affine map: first the part common to the class ({@code aDD D + aDv v},
     * {@code aVD D + aVv v}) in one loop over the whole segment that C2 vectorises, then each run's
     * force terms, added in the order {@code (aDD D + aDv v) + bD P0 + cD P1}.
     *
     * @param co       the spring coefficients ({@link SpringKinds#coef}, {@link SpringKinds#STRIDE} per class)
     * @param runStart per run its first component, as {@link #start}
     * @param runForce per run its {@value #FORCE_STRIDE} force terms
     */
    static void spring(int r0, int r1, int cls, float[] co, int[] runStart, float[] runForce, float[] devX,
                       float[] devZ, float[] velX, float[] velZ) {
        final int o = cls * SpringKinds.STRIDE;
        final float aDD = co[o];
        final float aDv = co[o + 1];
        final float aVD = co[o + 4];
        final float aVv = co[o + 5];
        for (int c = runStart[r0], e = runStart[r1]; c < e; c++) {
            float x = devX[c];
            float z = devZ[c];
            float vx = velX[c];
            float vz = velZ[c];
            devX[c] = aDD * x + aDv * vx;
            devZ[c] = aDD * z + aDv * vz;
            velX[c] = aVD * x + aVv * vx;
            velZ[c] = aVD * z + aVv * vz;
        }
        for (int r = r0; r < r1; r++) {
            int f = r * FORCE_STRIDE;
            float dx0 = runForce[f];
            float dx1 = runForce[f + 1];
            float dz0 = runForce[f + 2];
            float dz1 = runForce[f + 3];
            float vx0 = runForce[f + 4];
            float vx1 = runForce[f + 5];
            float vz0 = runForce[f + 6];
            float vz1 = runForce[f + 7];
            for (int c = runStart[r], e = runStart[r + 1]; c < e; c++) {
                devX[c] = devX[c] + dx0 + dx1;
                devZ[c] = devZ[c] + dz0 + dz1;
                velX[c] = velX[c] + vx0 + vx1;
                velZ[c] = velZ[c] + vz0 + vz1;
            }
        }
    }
}
