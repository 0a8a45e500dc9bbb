package org.jecosys.render;

import org.jecosys.render.ImageMetrics.Img;

/**
 * Frame-to-frame reversals of a picture sequence: of the pixels whose luma changed by more than
 * {@code threshold} levels from one frame to the next, how many change back the other way (again by more
 * than the threshold) in the frame after. Flicker (sub-pixel detail aliasing as it moves) reverses about
 * half its changes; light that travels reverses few. Feed the frames in order; allocates per frame.
 */
final class Reversals {
    private final int threshold;
    private int[] prev;
    private int[] prevDelta;
    private long changing;
    private long reversing;

    Reversals(int threshold) {
        this.threshold = threshold;
    }

    /** Adds the next frame's lumas (0-255, rounded), one per pixel, the same size as the others. */
    void add(int[] luma) {
        if (prev != null) {
            int[] delta = new int[luma.length];
            for (int k = 0; k < delta.length; k++) {
                delta[k] = luma[k] - prev[k];
                if (prevDelta != null && Math.abs(prevDelta[k]) > threshold) {
                    changing++;
                    if (Math.abs(delta[k]) > threshold && Integer.signum(delta[k]) != Integer.signum(prevDelta[k])) {
                        reversing++;
                    }
                }
            }
            prevDelta = delta;
        }
        prev = luma;
    }

    /** Adds the next frame. */
    void add(Img img) {
        int[] luma = new int[img.rgb().length];
        for (int i = 0; i < luma.length; i++) {
            luma[i] = (int) Math.round(ImageMetrics.luma(img.rgb()[i]));
        }
        add(luma);
    }

    /** {@return the changes over the threshold that had a next frame to reverse in} */
    long changing() {
        return changing;
    }

    /** {@return the share of those changes reversed in the next frame, 0 when none} */
    double share() {
        return changing == 0 ? 0 : reversing / (double) changing;
    }
}
