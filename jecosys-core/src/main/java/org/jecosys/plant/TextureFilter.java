package org.jecosys.plant;

import java.util.Arrays;

/**
 * The image work behind {@link PlantTextures}, on float RGBA texels in [0, 1] with rows from the bottom:
 * the colour bleed under transparent texels, the resampling to a square layer, and the mip chain whose
 * alpha keeps the full image's coverage. Build time; allocates; pure functions.
 */
final class TextureFilter {
    /** Alpha at and above which a texel counts as visible (for the bleed) and as covering (the coverage). */
    static final float VISIBLE = 0.02f;
    static final float HALF = 0.5f;

    private TextureFilter() {
    }

    /** The image's pixels as float RGBA, rows flipped so that row 0 is the image's bottom row. */
    static float[] floats(PlantTextures.Image img) {
        int w = img.width();
        int h = img.height();
        float[] out = new float[4 * w * h];
        int[] argb = img.argb();
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int p = argb[(h - 1 - y) * w + x];
                int o = 4 * (y * w + x);
                out[o] = ((p >>> 16) & 255) / 255f;
                out[o + 1] = ((p >>> 8) & 255) / 255f;
                out[o + 2] = (p & 255) / 255f;
                out[o + 3] = (p >>> 24) / 255f;
            }
        }
        return out;
    }

    /**
     * Gives each transparent texel (alpha below {@link #VISIBLE}) the colour of the nearest visible one,
     * in steps of a texel (4-neighbours, breadth first), keeping its alpha; an image with no visible
     * texel keeps its colours. In place; returns {@code rgba}.
     */
    static float[] bleed(float[] rgba, int w, int h) {
        int n = w * h;
        int[] queue = new int[n];
        boolean[] done = new boolean[n];
        int head = 0;
        int tail = 0;
        for (int i = 0; i < n; i++) {
            if (rgba[4 * i + 3] >= VISIBLE) {
                done[i] = true;
                queue[tail++] = i;
            }
        }
        if (tail == 0) {
            return rgba;
        }
        while (head < tail) {
            int i = queue[head++];
            int x = i % w;
            int y = i / w;
            tail = spread(rgba, done, queue, tail, i, x > 0 ? i - 1 : -1);
            tail = spread(rgba, done, queue, tail, i, x < w - 1 ? i + 1 : -1);
            tail = spread(rgba, done, queue, tail, i, y > 0 ? i - w : -1);
            tail = spread(rgba, done, queue, tail, i, y < h - 1 ? i + w : -1);
        }
        return rgba;
    }

    /** Copies texel {@code from}'s colour to {@code to} (when it is a texel not yet reached) and queues it. */
    private static int spread(float[] rgba, boolean[] done, int[] queue, int tail, int from, int to) {
        if (to < 0 || done[to]) {
            return tail;
        }
        done[to] = true;
        rgba[4 * to] = rgba[4 * from];
        rgba[4 * to + 1] = rgba[4 * from + 1];
        rgba[4 * to + 2] = rgba[4 * from + 2];
        queue[tail] = to;
        return tail + 1;
    }

    /**
     * The image resampled to {@code side} x {@code side}: each texel the mean of 4 x 4 bilinear taps
     * spread over its footprint in the image (a box filter when shrinking, bilinear when growing).
     */
    static float[] resample(float[] rgba, int w, int h, int side) {
        float[] out = new float[4 * side * side];
        final int taps = 4;
        float[] px = new float[4];
        for (int j = 0; j < side; j++) {
            for (int i = 0; i < side; i++) {
                float r = 0;
                float g = 0;
                float b = 0;
                float a = 0;
                for (int ty = 0; ty < taps; ty++) {
                    for (int tx = 0; tx < taps; tx++) {
                        double u = (i + (tx + 0.5) / taps) / side * w - 0.5;
                        double v = (j + (ty + 0.5) / taps) / side * h - 0.5;
                        bilinear(rgba, w, h, u, v, px);
                        r += px[0];
                        g += px[1];
                        b += px[2];
                        a += px[3];
                    }
                }
                float k = 1f / (taps * taps);
                int o = 4 * (j * side + i);
                out[o] = r * k;
                out[o + 1] = g * k;
                out[o + 2] = b * k;
                out[o + 3] = a * k;
            }
        }
        return out;
    }

    /** Bilinear sample at texel coordinates (u, v) (texel centres at integers), clamped at the edges. */
    private static void bilinear(float[] rgba, int w, int h, double u, double v, float[] out) {
        double cu = Math.max(0, Math.min(w - 1, u));
        double cv = Math.max(0, Math.min(h - 1, v));
        int x0 = (int) Math.floor(cu);
        int y0 = (int) Math.floor(cv);
        int x1 = Math.min(w - 1, x0 + 1);
        int y1 = Math.min(h - 1, y0 + 1);
        float fx = (float) (cu - x0);
        float fy = (float) (cv - y0);
        for (int c = 0; c < 4; c++) {
            float a = rgba[4 * (y0 * w + x0) + c] * (1 - fx) + rgba[4 * (y0 * w + x1) + c] * fx;
            float b = rgba[4 * (y1 * w + x0) + c] * (1 - fx) + rgba[4 * (y1 * w + x1) + c] * fx;
            out[c] = a * (1 - fy) + b * fy;
        }
    }

    /** The alpha-weighted mean colour (r, g, b); the plain mean when nothing is visible. */
    static float[] mean(float[] rgba) {
        double r = 0;
        double g = 0;
        double b = 0;
        double wsum = 0;
        int n = rgba.length / 4;
        for (int i = 0; i < n; i++) {
            double a = rgba[4 * i + 3];
            r += a * rgba[4 * i];
            g += a * rgba[4 * i + 1];
            b += a * rgba[4 * i + 2];
            wsum += a;
        }
        if (wsum <= 1e-9) {
            for (int i = 0; i < n; i++) {
                r += rgba[4 * i];
                g += rgba[4 * i + 1];
                b += rgba[4 * i + 2];
            }
            wsum = Math.max(1, n);
        }
        return new float[] {(float) (r / wsum), (float) (g / wsum), (float) (b / wsum)};
    }

    /**
     * The mip chain of a square layer as RGBA bytes: level 0 the layer itself, each next level the mean
     * of 2 x 2 texels of the one before (of its unscaled alpha), its alpha then scaled so that the share
     * of texels at or above {@link #HALF} matches level 0's ({@link #alphaScale}).
     */
    static byte[][] mips(float[] square, int side) {
        int count = Integer.numberOfTrailingZeros(side) + 1;
        byte[][] out = new byte[count][];
        out[0] = bytes(square, 1f);
        double target = coverage(square);
        float[] prev = square;
        int s = side;
        for (int m = 1; m < count; m++) {
            int t = s / 2;
            float[] next = new float[4 * t * t];
            for (int y = 0; y < t; y++) {
                for (int x = 0; x < t; x++) {
                    for (int c = 0; c < 4; c++) {
                        next[4 * (y * t + x) + c] = 0.25f * (prev[4 * (2 * y * s + 2 * x) + c]
                                + prev[4 * (2 * y * s + 2 * x + 1) + c] + prev[4 * ((2 * y + 1) * s + 2 * x) + c]
                                + prev[4 * ((2 * y + 1) * s + 2 * x + 1) + c]);
                    }
                }
            }
            out[m] = bytes(next, alphaScale(next, target));
            prev = next;
            s = t;
        }
        return out;
    }

    /**
     * The factor on alpha (in [1/16, 16]) that brings the share of texels whose scaled alpha is at or
     * above {@link #HALF} closest to {@code target}; 1 when the target is 0 or 1 (nothing or everything
     * covered: no outline to keep).
     */
    static float alphaScale(float[] rgba, double target) {
        if (target <= 0 || target >= 1) {
            return 1f;
        }
        int n = rgba.length / 4;
        float[] alpha = new float[n];
        for (int i = 0; i < n; i++) {
            alpha[i] = rgba[4 * i + 3];
        }
        Arrays.sort(alpha);
        // the k texels with the largest alpha should cover: scale so that the k-th largest reaches HALF
        int k = (int) Math.round(target * n);
        if (k <= 0) {
            return 1f;
        }
        float kth = alpha[n - k];
        if (kth <= 0) {
            return 16f;
        }
        return Math.max(1f / 16, Math.min(16f, HALF / kth));
    }

    /** The share of texels with alpha at or above {@link #HALF}. */
    static double coverage(float[] rgba) {
        int n = rgba.length / 4;
        int hit = 0;
        for (int i = 0; i < n; i++) {
            hit += rgba[4 * i + 3] >= HALF ? 1 : 0;
        }
        return n == 0 ? 0 : hit / (double) n;
    }

    /** The share of RGBA byte texels with alpha at or above one half (128). */
    static double coverage(byte[] rgba) {
        int n = rgba.length / 4;
        int hit = 0;
        for (int i = 0; i < n; i++) {
            hit += (rgba[4 * i + 3] & 255) >= 128 ? 1 : 0;
        }
        return n == 0 ? 0 : hit / (double) n;
    }

    /** RGBA bytes of float texels, alpha times {@code alphaScale} (clamped to 1). */
    private static byte[] bytes(float[] rgba, float alphaScale) {
        byte[] out = new byte[rgba.length];
        for (int i = 0; i < rgba.length; i++) {
            float v = (i & 3) == 3 ? rgba[i] * alphaScale : rgba[i];
            out[i] = (byte) Math.round(Math.max(0f, Math.min(1f, v)) * 255f);
        }
        return out;
    }
}
