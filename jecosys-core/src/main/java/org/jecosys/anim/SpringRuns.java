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
 * of a run share one deviation D and one velocity v. They are kept once per run ({@link #state}),
 * and {@link #advance} steps a run, not each of its components, with the arithmetic the
 * per-component update had, so the bits are those of the per-component update. Each change of a
 * run's D is also written to its components' entries of {@link #compDev}, the deviation of every
 * component, packed in one long as a frame's render states hold it (X, Z), so that publishing them is
 * one bulk copy. RANDOM mode, which gives each component a deviation of its own, writes those
 * directly and keeps the velocities in {@link ScatteredState} until the plant settles again.
 *
 * <p>A run's rest point at the end of a step is its rest point at the start of the next (the plant's
 * force P at an update is where the next one starts), so it is kept with the P it came from
 * ({@link #restPoint}) and reused when the next step starts from that very P: one rest point per run
 * and step is worked out instead of two, with the same bits.
 *
 * <p>The arrays are built once (allocates) and then read and written in place by the caller; the
 * steps ({@link #advance}, {@link #settle}, {@link #rest}) allocate nothing. A caller touches only the
 * runs of its own plants, so disjoint plant ranges may run at once.
 */
final class SpringRuns {
    /**
     * Floats per run in {@link #state}: D (X, Z), metres; v (X, Z), m/s; the stiffened rest point of
     * the force P the run was last advanced or settled to (X, Z), metres, and that P (X, Z), m^2/s^2
     * ({@link #restPoint}). One run's state is one half of a 64-byte cache line.
     */
    static final int STRIDE = 8;
    private static final int VX = 2;
    private static final int VZ = 3;
    private static final int RX = 4;
    private static final int RZ = 5;
    private static final int PX = 6;
    private static final int PZ = 7;
    /**
     * Largest linear rest point kept, in knees of the run ({@link #knee}): far beyond every bend
     * limit, so the saturation is complete, and small enough for {@link #saturation}'s float products.
     */
    static final double MAX_TARGET_KNEES = 1e12;
    private static final float KNEE = SpringKinds.KNEE;
    /**
     * Below this share of the squared knee, the linear rest point's size m over the bend limit, taken
     * in float as {@link #restPoint} takes it, is below {@link SpringKinds#KNEE} whatever the rounding
     * (m below the knee by 5e-5 of it, the roundings about 2e-7), so {@link #saturation} is exactly 1.
     */
    private static final double SURELY_BELOW_KNEE = 1 - 1e-4;
    /** Above this share of the squared knee, that size is far above float's subnormals (see {@link #saturation}). */
    private static final double SURELY_NORMAL = 1e-60;
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
    /** Per run, {@value #STRIDE} floats of state (see {@link #STRIDE}), together so that a step streams one array. */
    private final float[] state;
    /** Per run, its equilibrium deviation per unit P = |u| u, metres per (m/s)^2, the plant's compliance included. */
    private final double[] gain;
    /** Per run, {@code KNEE / knee}: 1 / its shortest component's bend limit, 1/m. */
    private final float[] invLimit;
    /** Per run, its shortest component's bend limit dMax, metres ({@code knee / KNEE}). */
    private final float[] limit;
    /**
     * Per component c, its deviation D, metres, at {@code c}, packed ({@link #pack}): its run's, or its
     * own while its plant is scattered.
     */
    final long[] compDev;

    /**
     * Cuts the components of each plant into runs, all at rest. Build time; allocates.
     *
     * @param kinds          the component kinds
     * @param kind           per component its kind
     * @param firstComponent per plant its first component, plus the total at the end
     * @param compliance     per plant the factor on its equilibrium deviation
     */
    SpringRuns(SpringKinds kinds, short[] kind, int[] firstComponent, float[] compliance) {
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
        state = new float[runs * STRIDE];
        gain = new double[runs];
        invLimit = new float[runs];
        limit = new float[runs];
        for (int r = 0; r < runs; r++) {
            gain[r] = kinds.gain(springClass[r]) * (double) compliance[runPlant[r]];
            invLimit[r] = KNEE / knee[r];
            limit[r] = knee[r] / KNEE;
            state[r * STRIDE + PX] = Float.NaN; // a rest point of no P yet
        }
        compDev = new long[components];
    }

    /** Run r's deviation D, X part, metres. */
    float devX(int r) {
        return state[r * STRIDE];
    }

    /** Run r's deviation D, Z part, metres. */
    float devZ(int r) {
        return state[r * STRIDE + 1];
    }

    /** Run r's velocity v, X part, m/s. */
    float velX(int r) {
        return state[r * STRIDE + VX];
    }

    /** Run r's velocity v, Z part, m/s. */
    float velZ(int r) {
        return state[r * STRIDE + VZ];
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
     * Writes into {@link #restPoint} run r's stiffened rest point for the plant's force
     * {@code P = |u| u} (m^2/s^2), with P: the linear rest point {@code gain P} (metres, in double,
     * its magnitude capped at {@link #MAX_TARGET_KNEES} knees with its direction kept, then rounded to
     * float), times {@link #saturation} of its size over the bend limit of the run's shortest
     * component (see "Bounded bend" in {@link SpringKinds}), so no component passes its own limit.
     */
    private void restPoint(int r, float px, float pz) {
        double g = gain[r];
        double tx = g * px;
        double tz = g * pz;
        double m2 = tx * tx + tz * tz;
        double k2 = (double) knee[r] * knee[r];
        float s;
        if (m2 <= k2 * SURELY_BELOW_KNEE && m2 >= k2 * SURELY_NORMAL) {
            // clearly below the knee (and far above float's subnormals): the factor is exactly 1, as
            // the general path finds, without its square root
            s = 1f;
        } else {
            double m = Math.sqrt(m2);
            double most = MAX_TARGET_KNEES * knee[r];
            if (m > most) {
                double k = most / m;
                tx *= k;
                tz *= k;
                m = most;
            }
            s = saturation((float) m * invLimit[r]);
        }
        int f = r * STRIDE;
        float[] st = state;
        st[f + RX] = s * (float) tx;
        st[f + RZ] = s * (float) tz;
        st[f + PX] = px;
        st[f + PZ] = pz;
    }

    /**
     * The factor that turns a linear rest point into the stiffened one (see "Bounded bend" in
     * {@link SpringKinds}): {@code sigma(x) / x} for {@code x = |T| / dMax}; exactly 1 up to the knee,
     * then decreasing so that {@code x} times it stays below 1. No allocation.
     *
     * @param x the linear rest point over the bend limit, finite, &gt;= 0
     * @return the factor, in (0, 1]
     */
    static float saturation(float x) {
        if (x <= KNEE && x >= Float.MIN_NORMAL) {
            return 1f; // what the formula below gives there (x / x), without its division
        }
        // (min(x, KNEE) + SPAN u / (1 + u)) / x with one division; the minima and maxima as comparisons
        // (x is a number >= 0, so they equal Math.min and Math.max, whose float intrinsics cost more)
        float t = (x - KNEE) * INV_SPAN;
        float u = t > 0 ? t : 0f;
        float w = 1f + u;
        return ((x < KNEE ? x : KNEE) * w + SPAN * u) / ((x > Float.MIN_NORMAL ? x : Float.MIN_NORMAL) * w);
    }

    /**
     * Puts the components of run r at its stiffened rest point for the plant's force
     * {@code P = (px, pz) = |u| u} (as {@link #advance} stiffens it), at zero velocity: the
     * equilibrium of that force.
     */
    void settle(int r, float px, float pz) {
        restPoint(r, px, pz);
        int f = r * STRIDE;
        float[] st = state;
        st[f] = st[f + RX];
        st[f + 1] = st[f + RZ];
        st[f + VX] = 0;
        st[f + VZ] = 0;
        spread(r);
    }

    /** Writes run r's D to its components' entries of {@link #compDev}: one 8-byte store per component. */
    private void spread(int r) {
        long d = pack(devX(r), devZ(r));
        long[] cd = compDev;
        for (int c = start[r], e = start[r + 1]; c < e; c++) {
            cd[c] = d;
        }
    }

    /**
     * A deviation (X, Z), metres, as one long: X's bits low, Z's high, so that the long written to
     * little-endian memory is the two floats X, Z (a frame's render state).
     */
    static long pack(float x, float z) {
        return (long) Float.floatToRawIntBits(z) << 32 | Float.floatToRawIntBits(x) & 0xFFFF_FFFFL;
    }

    /** {@return the X part of a packed deviation ({@link #pack})} */
    static float unpackX(long d) {
        return Float.intBitsToFloat((int) d);
    }

    /** {@return the Z part of a packed deviation ({@link #pack})} */
    static float unpackZ(long d) {
        return Float.intBitsToFloat((int) (d >>> 32));
    }

    /** Puts the components of runs {@code r0 .. r1-1} at rest: D = v = 0. */
    void rest(int r0, int r1) {
        for (int f = r0 * STRIDE, e = r1 * STRIDE; f < e; f += STRIDE) {
            Arrays.fill(state, f, f + RX, 0f); // D and v; the kept rest point stays that of its P
        }
        Arrays.fill(compDev, start[r0], start[r1], 0L); // pack(0, 0)
    }

    /**
     * Advances the components of run r, whose spring coefficients start at {@code co[o]}
     * ({@link SpringKinds#coef}: aDD, aDv, bD, cD, aVD, aVv, bV, cV), by the step's affine map (eq. 5
     * integrated exactly, see {@link SpringKinds}) from the plant's force {@code P0 = (p0x, p0z)} at
     * the start of the step to {@code P1 = (p1x, p1z)} at its end (both {@code |u| u}, m^2/s^2):
     * {@code D' = aDD D + aDv v + bD A + cD B}, {@code v' = aVD D + aVv v + bV A + cV B}, where A and B
     * are the run's stiffened rest points of P0 and P1 ({@link #restPoint}; A is the one kept from the
     * last step when that was of P0, bit for bit). Evaluated as {@code ((aDD D + aDv v) + bD A) + cD B},
     * in float, the order of the per-component update it replaces, hence its bits. No allocation.
     */
    void advance(int r, float[] co, int o, float p0x, float p0z, float p1x, float p1z) {
        int f = startRestPoint(r, p0x, p0z);
        float[] st = state;
        float ax = st[f + RX];
        float az = st[f + RZ];
        restPoint(r, p1x, p1z);
        step(r, co, o, ax, az, st[f + RX], st[f + RZ]);
    }

    /**
     * Makes run r's kept rest point that of the step's starting force P0 (reused, bit for bit, when the
     * last step ended at that very P0; worked out otherwise) and returns its offset in
     * {@link #restPoint}. No allocation.
     */
    private int startRestPoint(int r, float p0x, float p0z) {
        int f = r * STRIDE;
        float[] st = state;
        if (Float.floatToRawIntBits(st[f + PX]) != Float.floatToRawIntBits(p0x)
                || Float.floatToRawIntBits(st[f + PZ]) != Float.floatToRawIntBits(p0z)) {
            restPoint(r, p0x, p0z);
        }
        return f;
    }

    /**
     * As {@link #advance}, for a flattened plant ({@link Trails}): the rest points are
     * {@code L dMax + (1 - |L|) R(P)}, with flattening L0 at the start of the step and L1 at its end
     * (fractions of the bend limit, |L| &lt; 1) and R the elastic rest points {@link #advance} uses. No
     * allocation.
     */
    void advanceFlattened(int r, float[] co, int o, float p0x, float p0z, float p1x, float p1z,
                          float l0x, float l0z, float l1x, float l1z) {
        int f = startRestPoint(r, p0x, p0z);
        float[] st = state;
        float lim = limit[r];
        float k0 = 1 - (float) Math.sqrt((double) l0x * l0x + (double) l0z * l0z);
        float ax = k0 * st[f + RX] + l0x * lim;
        float az = k0 * st[f + RZ] + l0z * lim;
        restPoint(r, p1x, p1z);
        float k1 = 1 - (float) Math.sqrt((double) l1x * l1x + (double) l1z * l1z);
        step(r, co, o, ax, az, k1 * st[f + RX] + l1x * lim, k1 * st[f + RZ] + l1z * lim);
    }

    /**
     * As {@link #settle}, for a flattened plant: puts run r at the rest point
     * {@code L dMax + (1 - |L|) R(P)} of force P and flattening L ({@link #advanceFlattened}), at zero
     * velocity. No allocation.
     */
    void settleFlattened(int r, float px, float pz, float lx, float lz) {
        restPoint(r, px, pz);
        int f = r * STRIDE;
        float[] st = state;
        float k = 1 - (float) Math.sqrt((double) lx * lx + (double) lz * lz);
        st[f] = k * st[f + RX] + lx * limit[r];
        st[f + 1] = k * st[f + RZ] + lz * limit[r];
        st[f + VX] = 0;
        st[f + VZ] = 0;
        spread(r);
    }

    /**
     * The equilibrium bend of run r under the plant's force {@code P = (px, pz)} (m^2/s^2), as a
     * fraction of its bend limit: the stiffened rest point's size over dMax, in [0, 1). No allocation.
     */
    float equilibriumFraction(int r, float px, float pz) {
        double g = gain[r];
        double tx = g * px;
        double tz = g * pz;
        double m = Math.min(Math.sqrt(tx * tx + tz * tz), MAX_TARGET_KNEES * knee[r]);
        float x = (float) m * invLimit[r];
        return x * saturation(x);
    }

    /**
     * The wind speed (m/s) whose force {@code P = |u| u} gives run r the equilibrium bend
     * {@code fraction} of its bend limit ({@link #equilibriumFraction} inverted): below it the run's
     * equilibrium bend stays below the fraction. Build time; no allocation.
     *
     * @param fraction in (0, 1)
     * @return m/s, &gt; 0
     */
    double speedFor(int r, double fraction) {
        double x = fraction;
        if (fraction > KNEE) {
            double q = (fraction - KNEE) / SPAN;
            x = KNEE + SPAN * q / (1 - q);
        }
        return Math.sqrt(x * limit[r] / gain[r]);
    }

    /**
     * The exact step of run r (see {@link #advance}) toward rest point A at the start of the step and B
     * at its end: {@code D' = aDD D + aDv v + bD A + cD B}, {@code v' = aVD D + aVv v + bV A + cV B}, in
     * the order {@code ((aDD D + aDv v) + bD A) + cD B}; then written to the run's components.
     */
    private void step(int r, float[] co, int o, float ax, float az, float bx, float bz) {
        int f = r * STRIDE;
        float[] st = state;
        float x = st[f];
        float z = st[f + 1];
        float vx = st[f + VX];
        float vz = st[f + VZ];
        st[f] = co[o] * x + co[o + 1] * vx + co[o + 2] * ax + co[o + 3] * bx;
        st[f + 1] = co[o] * z + co[o + 1] * vz + co[o + 2] * az + co[o + 3] * bz;
        st[f + VX] = co[o + 4] * x + co[o + 5] * vx + co[o + 6] * ax + co[o + 7] * bx;
        st[f + VZ] = co[o + 4] * z + co[o + 5] * vz + co[o + 6] * az + co[o + 7] * bz;
        spread(r);
    }
}
