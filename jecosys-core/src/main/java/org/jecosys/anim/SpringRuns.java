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
    /** Largest linear rest point kept, metres: far beyond every bend limit, so saturation is complete. */
    static final double MAX_TARGET = 1e20;
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
     * (m/s)^2, the plant's compliance included), and their magnitudes, capped at {@link #MAX_TARGET}.
     */
    static void setForce(int r, double gain, float[] runForce, float p0x, float p0z, float p1x, float p1z) {
        int f = r * FORCE_STRIDE;
        target(gain, p0x, p0z, runForce, f, f + 4);
        target(gain, p1x, p1z, runForce, f + 2, f + 5);
    }

    private static void target(double gain, float px, float pz, float[] out, int o, int om) {
        double tx = gain * px;
        double tz = gain * pz;
        double m = Math.sqrt(tx * tx + tz * tz);
        if (m > MAX_TARGET) {
            double k = MAX_TARGET / m;
            tx *= k;
            tz *= k;
            m = MAX_TARGET;
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
        float u = Math.max(0f, (x - KNEE) * INV_SPAN);
        return (Math.min(x, KNEE) + SPAN * (u / (1f + u))) / Math.max(x, Float.MIN_NORMAL);
    }

    /**
     * Puts the components {@code c0 .. c1-1} at the rest point of the linear rest point (tx, tz) of
     * magnitude m (metres), at zero velocity: the equilibrium of that force.
     *
     * @param invLimit per component, 1 / its bend limit, 1/m
     */
    static void settle(int c0, int c1, float tx, float tz, float m, float[] invLimit, float[] devX, float[] devZ,
                       float[] velX, float[] velZ) {
        for (int c = c0; c < c1; c++) {
            float k = saturation(m * invLimit[c]);
            devX[c] = k * tx;
            devZ[c] = k * tz;
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
     * {@code row}) by the step's affine map (eq. 5 integrated exactly, see {@link SpringKinds}) in the
     * form {@code D' = A + aDD (D - A) + aDv v + cD (B - A)}, {@code v' = aVD (D - A) + aVv v + cV (B - A)},
     * where A and B are the component's stiffened rest points at the start and the end of the step
     * (its run's linear rest points times {@link #saturation} of their size over its bend limit). One
     * short branch-free loop per run, over arrays indexed by component; each component's result
     * depends on its own values only.
     *
     * @param co       the spring coefficients ({@link SpringKinds#coef}, {@link SpringKinds#STRIDE} per row)
     * @param runStart per run its first component, as {@link #start}
     * @param runForce per run its {@value #FORCE_STRIDE} values ({@link #setForce})
     * @param invLimit per component, 1 / its bend limit, 1/m
     */
    static void spring(int r0, int r1, int row, float[] co, int[] runStart, float[] runForce, float[] invLimit,
                       float[] devX, float[] devZ, float[] velX, float[] velZ) {
        final int o = row * SpringKinds.STRIDE;
        final float aDD = co[o];
        final float aDv = co[o + 1];
        final float cD = co[o + 3];
        final float aVD = co[o + 4];
        final float aVv = co[o + 5];
        final float cV = co[o + 7];
        for (int r = r0; r < r1; r++) {
            int f = r * FORCE_STRIDE;
            float t0x = runForce[f];
            float t0z = runForce[f + 1];
            float t1x = runForce[f + 2];
            float t1z = runForce[f + 3];
            float m0 = runForce[f + 4];
            float m1 = runForce[f + 5];
            for (int c = runStart[r], e = runStart[r + 1]; c < e; c++) {
                float q = invLimit[c];
                float k0 = saturation(m0 * q);
                float k1 = saturation(m1 * q);
                float ax = k0 * t0x;
                float az = k0 * t0z;
                float dx = k1 * t1x - ax;
                float dz = k1 * t1z - az;
                float ex = devX[c] - ax;
                float ez = devZ[c] - az;
                float vx = velX[c];
                float vz = velZ[c];
                devX[c] = ax + aDD * ex + aDv * vx + cD * dx;
                devZ[c] = az + aDD * ez + aDv * vz + cD * dz;
                velX[c] = aVD * ex + aVv * vx + cV * dx;
                velZ[c] = aVD * ez + aVv * vz + cV * dz;
            }
        }
    }
}
