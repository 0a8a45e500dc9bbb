package org.jecosys.anim;

import java.util.Arrays;

/**
 * The spring runs of {@link AnimationState} (see "Update order" there), their state and the step
 * that advances them: maximal runs of consecutive components of one plant that share their spring
 * coefficients ({@link SpringKinds#springClass}) and their level-of-detail mask. Run r covers
 * components {@code start[r] .. start[r + 1] - 1} (no run is empty); plant p owns runs
 * {@code plantRun[p] .. plantRun[p + 1] - 1}.
 *
 * <p>Every component of a run gets the same spring update from the same force, and is put at the
 * same rest point when its plant settles or rests, so in CONSTRAINT and STATIC modes all components
 * of a run share one deviation D and one velocity v. They are kept once per run ({@link #devX} ...),
 * and {@link #advance} steps a run, not each of its components, with the arithmetic the
 * per-component update had, so the bits are those of the per-component update. Each change of a
 * run's D is also written to its components' entries of {@link #compDevX} and {@link #compDevZ}, the
 * deviation of every component, which the output loops read (they vectorise only over arrays indexed
 * by component). RANDOM mode, which gives each component a deviation of its own, writes those
 * directly and keeps the velocities in {@link ScatteredState} until the plant settles again.
 *
 * <p>The arrays are built once (allocates) and then read and written in place by the caller; the
 * steps ({@link #setForce}, {@link #advance}, {@link #settle}, {@link #rest}) allocate nothing. A
 * caller touches only the runs of its own plants, so disjoint plant ranges may run at once.
 */
final class SpringRuns {
    /**
     * Values per run in {@link #force}: the linear rest points (metres) at the start and the end of
     * the step, T0x, T0z, T1x, T1z, and their magnitudes |T0|, |T1|.
     */
    static final int FORCE_STRIDE = 6;
    /**
     * Largest linear rest point kept, in knees of the run ({@link #knee}): far beyond every bend
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
    /** Per run its plant. */
    final int[] runPlant;
    /** Per run, the knee of the bend limit of its shortest component, metres (see {@link #advance}). */
    final float[] knee;
    /** Per run, the deviation D (X, Z) of each of its components, metres. */
    final float[] devX;
    final float[] devZ;
    /** Per run, the velocity v (X, Z) of each of its components, m/s. */
    final float[] velX;
    final float[] velZ;
    /** Per run, its {@value #FORCE_STRIDE} force values of the last update ({@link #setForce}). */
    final float[] force;
    /** Per component, its deviation D (X, Z), metres: its run's, or its own while its plant is scattered. */
    final float[] compDevX;
    final float[] compDevZ;

    /**
     * Cuts the components of each plant into runs, all at rest. Build time; allocates.
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
        runPlant = new int[runs];
        for (int p = 0; p < plants; p++) {
            Arrays.fill(runPlant, plantRun[p], plantRun[p + 1], p);
        }
        knee = new float[runs];
        for (int r = 0; r < runs; r++) {
            float most = 0;
            for (int c = start[r]; c < start[r + 1]; c++) {
                most = Math.max(most, 1 / kinds.dMax[kind[c]]);
            }
            knee[r] = KNEE / most;
        }
        devX = new float[runs];
        devZ = new float[runs];
        velX = new float[runs];
        velZ = new float[runs];
        force = new float[runs * FORCE_STRIDE];
        compDevX = new float[components];
        compDevZ = new float[components];
    }

    /** Number of runs. */
    int count() {
        return springClass.length;
    }

    /** Components in run r. */
    int size(int r) {
        return start[r + 1] - start[r];
    }

    /** The run holding component c of plant p (a short scan of the plant's runs). */
    int runOf(int p, int c) {
        int r = plantRun[p];
        while (start[r + 1] <= c) {
            r++;
        }
        return r;
    }

    /**
     * Writes run r's {@value #FORCE_STRIDE} values into {@link #force}: the linear rest points
     * {@code gain P} of the plant's {@code P = |u| u} at the start ({@code p0}) and the end ({@code p1})
     * of the step, m^2/s^2, with {@code gain} the run's equilibrium deviation per unit P (metres per
     * (m/s)^2, the plant's compliance included), and their magnitudes, capped at
     * {@link #MAX_TARGET_KNEES} times the run's knee (metres) with their direction kept.
     */
    void setForce(int r, double gain, float p0x, float p0z, float p1x, float p1z) {
        int f = r * FORCE_STRIDE;
        double most = MAX_TARGET_KNEES * knee[r];
        target(gain, most, p0x, p0z, force, f, f + 4);
        target(gain, most, p1x, p1z, force, f + 2, f + 5);
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
     * Puts the components of run r at the stiffened rest point (as {@link #advance} stiffens it) of
     * the linear rest point at the start of the step in {@link #force}, at zero velocity: the
     * equilibrium of that force.
     */
    void settle(int r) {
        int f = r * FORCE_STRIDE;
        float k = saturation(force[f + 4] * (KNEE / knee[r]));
        devX[r] = k * force[f];
        devZ[r] = k * force[f + 1];
        velX[r] = 0;
        velZ[r] = 0;
        spread(r);
    }

    /** Writes run r's D to its components' entries of {@link #compDevX}, {@link #compDevZ}. */
    private void spread(int r) {
        float x = devX[r];
        float z = devZ[r];
        float[] cx = compDevX;
        float[] cz = compDevZ;
        for (int c = start[r], e = start[r + 1]; c < e; c++) {
            cx[c] = x;
            cz[c] = z;
        }
    }

    /** Puts the components of runs {@code r0 .. r1-1} at rest: D = v = 0. */
    void rest(int r0, int r1) {
        Arrays.fill(devX, r0, r1, 0f);
        Arrays.fill(devZ, r0, r1, 0f);
        Arrays.fill(velX, r0, r1, 0f);
        Arrays.fill(velZ, r0, r1, 0f);
        Arrays.fill(compDevX, start[r0], start[r1], 0f);
        Arrays.fill(compDevZ, start[r0], start[r1], 0f);
    }

    /**
     * Advances the components of run r, whose spring coefficients start at {@code co[o]}
     * ({@link SpringKinds#coef}: aDD, aDv, bD, cD, aVD, aVv, bV, cV), by the step's affine map (eq. 5
     * integrated exactly, see {@link SpringKinds}): {@code D' = aDD D + aDv v + bD A + cD B},
     * {@code v' = aVD D + aVv v + bV A + cV B}, where A and B are the run's stiffened rest points at
     * the start and the end of the step: its linear rest points ({@link #setForce}) times
     * {@link #saturation} of their size over the bend limit of its shortest component, so no
     * component passes its own limit. Evaluated as {@code ((aDD D + aDv v) + bD A) + cD B}, in float,
     * the order of the per-component update it replaces, hence its bits. No allocation.
     */
    void advance(int r, float[] co, int o) {
        int f = r * FORCE_STRIDE;
        float[] fr = force;
        float q = KNEE / knee[r];
        float k0 = saturation(fr[f + 4] * q);
        float k1 = saturation(fr[f + 5] * q);
        float ax = k0 * fr[f];
        float az = k0 * fr[f + 1];
        float bx = k1 * fr[f + 2];
        float bz = k1 * fr[f + 3];
        float x = devX[r];
        float z = devZ[r];
        float vx = velX[r];
        float vz = velZ[r];
        devX[r] = co[o] * x + co[o + 1] * vx + co[o + 2] * ax + co[o + 3] * bx;
        devZ[r] = co[o] * z + co[o + 1] * vz + co[o + 2] * az + co[o + 3] * bz;
        velX[r] = co[o + 4] * x + co[o + 5] * vx + co[o + 6] * ax + co[o + 7] * bx;
        velZ[r] = co[o + 4] * z + co[o + 5] * vz + co[o + 6] * az + co[o + 7] * bz;
        spread(r);
    }
}
