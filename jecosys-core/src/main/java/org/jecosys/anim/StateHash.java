package org.jecosys.anim;

/**
 * The fingerprint of an {@link AnimationState} ({@link AnimationState#stateHash}): a 64-bit FNV-1a
 * hash of the raw float bits of D, v, pose and azimuth of every component, in component order, then
 * of every plant's flattening when a species leaves trails ({@link Trails#hash}). Equal states give
 * equal hashes: the determinism tests compare runs with any number of workers by it. No allocation.
 */
final class StateHash {
    /** The FNV-1a 64-bit offset basis. */
    static final long START = 0xcbf29ce484222325L;

    private StateHash() {
    }

    /** The hash of the state; one thread, no range running. */
    static long of(AnimationState state, SpringRuns runs, ScatteredState scattered, Trails trails) {
        long h = START;
        for (int r = 0, n = runs.count(); r < n; r++) {
            boolean own = scattered.scattered[runs.runPlant[r]];
            for (int c = runs.start[r], e = runs.start[r + 1]; c < e; c++) {
                h = mix(h, (int) runs.compDev[c]); // X's bits
                h = mix(h, (int) (runs.compDev[c] >>> 32)); // Z's bits
                h = mix(h, Float.floatToRawIntBits(own ? scattered.velX[c] : runs.velX(r)));
                h = mix(h, Float.floatToRawIntBits(own ? scattered.velZ[c] : runs.velZ(r)));
                h = mix(h, Float.floatToRawIntBits(state.poseCoordinate(c)));
                h = mix(h, Float.floatToRawIntBits(state.azimuth(c)));
            }
        }
        return trails == null ? h : trails.hash(h);
    }

    /** Folds the four bytes of {@code bits}, lowest first, into h. */
    static long mix(long h, int bits) {
        for (int i = 0; i < 4; i++) {
            h ^= (bits >>> (8 * i)) & 0xff;
            h *= 0x100000001b3L;
        }
        return h;
    }
}
