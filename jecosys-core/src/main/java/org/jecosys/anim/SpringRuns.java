package org.jecosys.anim;

import java.util.Arrays;
import org.jecosys.math.Rng;

/**
 * The spring runs of {@link AnimationState} (see "Update order" there) and the step that advances
 * them: maximal runs of consecutive components of one plant that share their spring coefficients
 * ({@link SpringKinds#springClass}) and their level-of-detail mask. Run r covers components
 * {@code start[r] .. start[r + 1] - 1} (no run is empty); plant p owns runs {@code plantRun[p] ..
 * plantRun[p + 1] - 1}. The arrays are built once (allocates) and then read in place by the caller;
 * the steps ({@link #setForce}, {@link #spring}, {@link #settle}, and RANDOM mode's {@link #randomise})
 * are static over the caller's arrays and allocate nothing.
 */
final class SpringRuns {
    /**
     * Values per run in {@code runForce}: the linear rest points (metres) at the start and the end of
     * the step, T0x, T0z, T1x, T1z, and their magnitudes |T0|, |T1|.
     */
    static final int FORCE_STRIDE = 6;
    /**
     * Largest linear rest point kept, in knees of the run ({@link #knees}): far beyond every bend
     * limit, so the saturation is complete, and small enough for {@link #saturation}'s float products.
     */
    static final double MAX_TARGET_KNEES = 1e12;
    private static final float KNEE = SpringKinds.KNEE;
    private static final float SPAN = 1 - KNEE;
    private static final float INV_SPAN = 1 / SPAN;

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
     * Writes run r's {@value #FORCE_STRIDE} values into {@code runForce}: the linear rest points
     * {@code gain P} of the plant's {@code P = |u| u} at the start ({@code p0}) and the end ({@code p1})
     * of the step, m^2/s^2, with {@code gain} the run's equilibrium deviation per unit P (metres per
     * (m/s)^2, the plant's compliance included), and their magnitudes, capped at
     * {@link #MAX_TARGET_KNEES} times the run's knee {@code knee} (metres) with their direction kept.
     */
    static void setForce(int r, double gain, float knee, float[] runForce, float p0x, float p0z, float p1x,
                         float p1z) {
        int f = r * FORCE_STRIDE;
        double most = MAX_TARGET_KNEES * knee;
        target(gain, most, p0x, p0z, runForce, f, f + 4);
        target(gain, most, p1x, p1z, runForce, f + 2, f + 5);
    }

    private static void target(double gain, double most, float px, float pz, float[] out, int o, int om) {
        double tx = gain * px;
        double tz = gain * pz;
        double m = Math.sqrt(tx * tx + tz * tz);
        if (m > most) {
            double k = most / m;
            tx *= k;
            tz *= k;
            m = most;
        }
        out[o] = (float) tx;
        out[o + 1] = (float) tz;
        out[om] = (float) m;
    }

    /**
     * The factor that turns a linear rest point into the stiffened one (see "Bounded bend" in
     * {@link SpringKinds}): {@code sigma(x) / x} for {@code x = |T| / dMax}; exactly 1 up to the knee,
     * then decreasing so that {@code x} times it stays below 1. Branch-free; no allocation.
     *
     * @param x the linear rest point over the bend limit, finite, &gt;= 0
     * @return the factor, in (0, 1]
     */
    static float saturation(float x) {
        // (min(x, KNEE) + SPAN u / (1 + u)) / x with one division
        float u = Math.max(0f, (x - KNEE) * INV_SPAN);
        float w = 1f + u;
        return (Math.min(x, KNEE) * w + SPAN * u) / (Math.max(x, Float.MIN_NORMAL) * w);
    }

    /**
     * Per run, the knee of the bend limit of its shortest component: {@code KNEE} times the smallest
     * bend limit, metres (the largest rest point that {@link #spring} leaves unchanged). Build time;
     * allocates.
     *
     * @param invLimit per component, 1 / its bend limit, 1/m
     * @return one value per run
     */
    float[] knees(float[] invLimit) {
        float[] k = new float[count()];
        for (int r = 0; r < k.length; r++) {
            float most = 0;
            for (int c = start[r]; c < start[r + 1]; c++) {
                most = Math.max(most, invLimit[c]);
            }
            k[r] = KNEE / most;
        }
        return k;
    }

    /**
     * Puts the components of run r at the rest point of its linear rest point (tx, tz) of magnitude m
     * (metres, as {@link #spring} stiffens it), at zero velocity: the equilibrium of that force.
     *
     * @param runKnee per run, the knee of its shortest component's bend limit, metres ({@link #knees})
     */
    static void settle(int r, int[] runStart, float tx, float tz, float m, float[] runKnee, float[] devX,
                       float[] devZ, float[] velX, float[] velZ) {
        float k = saturation(m * (KNEE / runKnee[r]));
        float x = k * tx;
        float z = k * tz;
        for (int c = runStart[r], e = runStart[r + 1]; c < e; c++) {
            devX[c] = x;
            devZ[c] = z;
            velX[c] = 0;
            velZ[c] = 0;
        }
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
     * Advances the components of runs {@code r0 .. r1-1} (contiguous, all of coefficient row
     * {@code row}) by the step's affine map (eq. 5 integrated exactly, see {@link SpringKinds}):
     * {@code D' = aDD D + aDv v + bD A + cD B}, {@code v' = aVD D + aVv v + bV A + cV B}, where A and B
     * are the run's stiffened rest points at the start and the end of the step: its linear rest points
     * times {@link #saturation} of their size over the bend limit of its shortest component (so no
     * component passes its own limit). First the part common to the row ({@code aDD D + aDv v},
     * {@code aVD D + aVv v}) in one loop over the whole segment that C2 vectorises, then each run's
     * rest-point terms, computed once per run and added in the order {@code (aDD D + aDv v) + bD A + cD B},
     * so the bits do not depend on how runs are grouped into segments.
     *
     * @param co       the spring coefficients ({@link SpringKinds#coef}, {@link SpringKinds#STRIDE} per row)
     * @param runStart per run its first component, as {@link #start}
     * @param runForce per run its {@value #FORCE_STRIDE} values ({@link #setForce})
     * @param runKnee  per run, the knee of its shortest component's bend limit, metres ({@link #knees})
     */
    static void spring(int r0, int r1, int row, float[] co, int[] runStart, float[] runForce, float[] runKnee,
                       float[] devX, float[] devZ, float[] velX, float[] velZ) {
        final int o = row * SpringKinds.STRIDE;
        final float aDD = co[o];
        final float aDv = co[o + 1];
        final float bD = co[o + 2];
        final float cD = co[o + 3];
        final float aVD = co[o + 4];
        final float aVv = co[o + 5];
        final float bV = co[o + 6];
        final float cV = co[o + 7];
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
            float q = KNEE / runKnee[r];
            float k0 = saturation(runForce[f + 4] * q);
            float k1 = saturation(runForce[f + 5] * q);
            float ax = k0 * runForce[f];
            float az = k0 * runForce[f + 1];
            float bx = k1 * runForce[f + 2];
            float bz = k1 * runForce[f + 3];
            float dx0 = bD * ax;
            float dx1 = cD * bx;
            float dz0 = bD * az;
            float dz1 = cD * bz;
            float vx0 = bV * ax;
            float vx1 = cV * bx;
            float vz0 = bV * az;
            float vz1 = cV * bz;
            for (int c = runStart[r], e = runStart[r + 1]; c < e; c++) {
                devX[c] = devX[c] + dx0 + dx1;
                devZ[c] = devZ[c] + dz0 + dz1;
                velX[c] = velX[c] + vx0 + vx1;
                velZ[c] = velZ[c] + vz0 + vz1;
            }
        }
    }
}
