package org.jecosys.anim;

import java.util.Arrays;
import org.jecosys.math.Require;

/**
 * The flattening of plants by strong pushes, and its recovery: the trail a walker leaves through a
 * meadow, the ring a blast leaves (not in the paper; its spring of §4.2 is purely elastic). Only
 * species with a recovery time take part ({@code org.jecosys.plant.TrailDef}); a plant of another
 * species never touches this state and moves exactly as without it.
 *
 * <p>Per plant a flattening vector L, in fractions of the bend limit: a push of the point flows whose
 * equilibrium bend reaches the species' {@code flattenAt} flattens the plant, which then recovers as
 * {@code (1 + s) e^-s} with {@code s} the time since, in recovery times, and each spring run's rest
 * point becomes {@code L dMax + (1 - |L|) R(P)}. The model is in docs/model.md, "Trails: flattening
 * and recovery".
 *
 * <h2>Threads and determinism</h2>
 * Everything is per plant, computed from the plant's own force and the step's time ({@link StrictMath}
 * for the exponential, so interpreted and compiled code agree): the same bits for any split of the
 * plants into ranges and any number of workers. A caller touches only its own plants. Built once
 * (allocates); nothing else allocates.
 */
final class Trails {
    /** Recovery times after which the flattening is taken as gone: {@code (1 + s) e^-s} is below 1e-8 there. */
    static final double END = 24;

    /** Per species, the recovery time, seconds; 0 for none. */
    private final float[] recovery;
    /** Per species, the equilibrium bend fraction that flattens. */
    private final float[] flattenAt;
    /** Per plant, its species (shared with the state, read only). */
    private final int[] species;
    /** Per plant, the flattening A at its start, fractions of the bend limit. */
    private final float[] ampX;
    private final float[] ampZ;
    /** Per plant, the time the flattening A started, seconds of simulation time. */
    private final double[] start;
    /** Per plant, the flattening L at its last update, fractions of the bend limit. */
    final float[] nowX;
    final float[] nowZ;
    /**
     * Per plant, {@link #NONE} when its species leaves no trails, else {@link #UPRIGHT} or
     * {@link #FLATTENED} (amplitude not 0), in the one byte the step reads per plant. An UPRIGHT plant
     * has no flattening now and none at its last update: {@link #nowX}, {@link #nowZ} are 0 whenever
     * the amplitude is ({@link #at} sets them so, {@link #push} sets both, {@link #clear} clears both).
     */
    private final byte[] mode;
    /** {@link #mode}: a species without trails. */
    static final byte NONE = 0;
    /** {@link #mode}: trails, not flattened (amplitude 0). */
    static final byte UPRIGHT = 1;
    /** {@link #mode}: trails, flattened (amplitude not 0). */
    static final byte FLATTENED = 2;

    private Trails(float[] recovery, float[] flattenAt, int[] species) {
        this.recovery = recovery;
        this.flattenAt = flattenAt;
        this.species = species;
        int plants = species.length;
        ampX = new float[plants];
        ampZ = new float[plants];
        start = new double[plants];
        nowX = new float[plants];
        nowZ = new float[plants];
        mode = new byte[plants];
        for (int p = 0; p < plants; p++) {
            mode[p] = recovery[species[p]] > 0 ? UPRIGHT : NONE;
        }
    }

    /** {@return plant p's {@link #mode}: NONE, UPRIGHT or FLATTENED} */
    byte mode(int p) {
        return mode[p];
    }

    /** Sets the amplitude of plant p (whose species leaves trails), and its {@link #mode} with it. */
    private void amplitude(int p, float ax, float az) {
        ampX[p] = ax;
        ampZ[p] = az;
        mode[p] = ax == 0 && az == 0 ? UPRIGHT : FLATTENED;
    }

    /**
     * The trails of a set of plants, or null when no species recovers (recovery 0 everywhere). Build
     * time; allocates.
     *
     * @param recovery  per species, seconds, in [0, 3600]
     * @param flattenAt per species, fraction of the bend limit, in [0.1, 0.95]
     * @param species   per plant its species, kept by reference
     * @throws IllegalArgumentException when the arrays differ in length or a value is out of range
     */
    static Trails of(double[] recovery, double[] flattenAt, int[] species) {
        if (recovery.length != flattenAt.length) {
            throw new IllegalArgumentException("recovery and flattenAt must hold one value per species, got "
                    + recovery.length + " and " + flattenAt.length);
        }
        float[] r = new float[recovery.length];
        float[] f = new float[recovery.length];
        boolean any = false;
        for (int s = 0; s < r.length; s++) {
            r[s] = (float) Require.elementRange("recovery", s, recovery[s], 0, 3600);
            f[s] = (float) Require.elementRange("flattenAt", s, flattenAt[s], 0.1, 0.95);
            any |= r[s] > 0;
        }
        return any ? new Trails(r, f, species) : null;
    }

    /** The equilibrium bend fraction that flattens plant p. */
    float flattenAt(int p) {
        return flattenAt[species[p]];
    }

    /** Whether plant p's species leaves trails. */
    boolean on(int p) {
        return mode[p] != NONE;
    }

    /**
     * Moves plant p's flattening to time t (seconds): writes {@code L(t)} into {@link #nowX},
     * {@link #nowZ} and forgets a flattening past {@link #END} recovery times. No allocation.
     */
    void at(int p, double t) {
        float ax = ampX[p];
        float az = ampZ[p];
        if (ax == 0 && az == 0) {
            nowX[p] = 0;
            nowZ[p] = 0;
            return;
        }
        double s = Math.max(0, (t - start[p]) / recovery[species[p]]);
        if (s >= END) {
            amplitude(p, 0, 0);
            nowX[p] = 0;
            nowZ[p] = 0;
            return;
        }
        float g = (float) ((1 + s) * StrictMath.exp(-s));
        nowX[p] = ax * g;
        nowZ[p] = az * g;
    }

    /**
     * A push on plant p at time t (seconds, after {@link #at} for that time) by the wind
     * {@code (qx, qz)} (m/s) of the flows that flatten: flattens the plant along the push when the
     * equilibrium bend of its force on the plant's first run ({@link SpringRuns#equilibriumFraction})
     * reaches the species' threshold and exceeds the flattening left now. No allocation.
     */
    void push(int p, double t, float qx, float qz, SpringRuns runs) {
        float q = (float) Math.sqrt(qx * qx + qz * qz);
        float px = q * qx;
        float pz = q * qz;
        float a = runs.equilibriumFraction(runs.plantRun[p], px, pz);
        if (!(a >= flattenAt[species[p]])) {
            return;
        }
        float lx = nowX[p];
        float lz = nowZ[p];
        if (a * a <= lx * lx + lz * lz) {
            return;
        }
        float m = (float) Math.sqrt((double) px * px + (double) pz * pz);
        if (!(m > 0)) {
            return;
        }
        float k = a / m;
        amplitude(p, px * k, pz * k);
        start[p] = t;
        nowX[p] = ampX[p];
        nowZ[p] = ampZ[p];
    }

    /**
     * Puts the runs of plant p, just settled at the equilibrium of force {@code (px, pz)}
     * (m^2/s^2), at the flattened equilibrium of its flattening now (after {@link #at}); nothing
     * when it is not flattened. No allocation.
     */
    void settle(int p, SpringRuns runs, float px, float pz) {
        float lx = nowX[p];
        float lz = nowZ[p];
        if (lx == 0 && lz == 0) {
            return;
        }
        for (int r = runs.plantRun[p], e = runs.plantRun[p + 1]; r < e; r++) {
            runs.settleFlattened(r, px, pz, lx, lz);
        }
    }

    /** Forgets the flattening of plants {@code first .. end-1}. No allocation. */
    void clear(int first, int end) {
        Arrays.fill(ampX, first, end, 0f);
        Arrays.fill(ampZ, first, end, 0f);
        for (int p = first; p < end; p++) {
            mode[p] = mode[p] == NONE ? NONE : UPRIGHT;
        }
        Arrays.fill(start, first, end, 0d);
        Arrays.fill(nowX, first, end, 0f);
        Arrays.fill(nowZ, first, end, 0f);
    }

    /** The size of plant p's flattening at its last update, a fraction of its bend limit in [0, 1). */
    float flattening(int p) {
        return (float) Math.sqrt((double) nowX[p] * nowX[p] + (double) nowZ[p] * nowZ[p]);
    }

    /** Folds every plant's flattening state into hash h ({@link StateHash#mix}); one thread, no range running. */
    long hash(long h) {
        for (int p = 0; p < species.length; p++) {
            h = StateHash.mix(h, Float.floatToRawIntBits(ampX[p]));
            h = StateHash.mix(h, Float.floatToRawIntBits(ampZ[p]));
            long bits = Double.doubleToRawLongBits(start[p]);
            h = StateHash.mix(h, (int) bits);
            h = StateHash.mix(h, (int) (bits >>> 32));
            h = StateHash.mix(h, Float.floatToRawIntBits(nowX[p]));
            h = StateHash.mix(h, Float.floatToRawIntBits(nowZ[p]));
        }
        return h;
    }
}
