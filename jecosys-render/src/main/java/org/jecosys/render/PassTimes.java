package org.jecosys.render;

import java.util.Arrays;

/**
 * The GPU time of each pass of a {@link SceneRenderer}'s frames (issue 42), from timer queries read a few
 * frames after they were issued and only once the GL says they are ready, so that measuring never makes
 * the CPU wait for the GPU ({@link SceneRenderer#setPassTiming}). Every fourth timed frame is measured
 * whole instead (one query around the frame: timer queries do not nest), so that the passes' sum can be
 * checked against the frame's own GPU time. A pass that a frame does not draw (the shadow map on the
 * ground path, the cover in a scene without one) counts 0.
 *
 * <p>Read on the render thread; the values are the latest completed measurement; no allocation.
 */
public final class PassTimes {
    /** The passes of a frame, in the order a multisampled frame draws them. */
    public enum Pass {
        /** The ground's maps: the splatted sun shadow and contact darkening, when they change. */
        GROUND_MAPS,
        /** The near plants' lists and uploads and the per-component resolve pass. */
        RESOLVE,
        /** The plants drawn from the sun into the shadow map ({@link ShadowPath#MAP}). */
        SHADOW_MAP,
        /** The near levels' instanced draws (triangles). */
        NEAR_PLANTS,
        /** The ground cover's blades. */
        COVER,
        /** The terrain, or the cover's skin over a host's ground. */
        GROUND,
        /** The sky. */
        SKY,
        /** The far (line) levels. */
        FAR_PLANTS,
        /** The field and wind overlays. */
        OVERLAY
    }

    /** Every pass, in order. */
    static final Pass[] PASSES = Pass.values();

    private final long[] nanos = new long[PASSES.length];
    private long frameNanos = -1;
    private long passFrames;
    private long wholeFrames;
    private long dropped;

    PassTimes() {
        Arrays.fill(nanos, -1);
    }

    /**
     * {@return the GPU time of the pass in the latest frame measured pass by pass, nanoseconds; -1 before
     * the first}
     *
     * @param pass the pass
     */
    public long nanos(Pass pass) {
        return nanos[pass.ordinal()];
    }

    /** {@return the sum of the passes of the latest frame measured pass by pass, nanoseconds; -1 before the first} */
    public long passSumNanos() {
        if (passFrames == 0) {
            return -1;
        }
        long s = 0;
        for (long n : nanos) {
            s += n;
        }
        return s;
    }

    /** {@return the GPU time of the latest frame measured whole, nanoseconds; -1 before the first} */
    public long frameNanos() {
        return frameNanos;
    }

    /** {@return how many frames were measured pass by pass so far} */
    public long passFrames() {
        return passFrames;
    }

    /** {@return how many frames were measured whole so far} */
    public long wholeFrames() {
        return wholeFrames;
    }

    /** {@return how many timed frames were dropped because their queries were not ready when their slot came round} */
    public long dropped() {
        return dropped;
    }

    void passes(long[] measured) {
        System.arraycopy(measured, 0, nanos, 0, nanos.length);
        passFrames++;
    }

    void whole(long measured) {
        frameNanos = measured;
        wholeFrames++;
    }

    void drop() {
        dropped++;
    }
}
