package org.jecosys.render;

import java.nio.ByteBuffer;
import java.util.Arrays;
import org.jecosys.render.gl.Pixels;

/**
 * Image measurements for the look tests of issue 13 (vegetation coverage, isolated pixels, per-plant
 * colour, fine-detail contrast, image differences, frame-to-frame change). Images are {@link Img}:
 * packed 0xRRGGBB, rows bottom-up as OpenGL reads them (row 0 is the bottom of the picture), so "the
 * lower half" is rows {@code [0, height / 2)}. Masks are {@code boolean[width * height]} in the same
 * order. Pure functions over arrays; test code only.
 */
final class ImageMetrics {
    private ImageMetrics() {
    }

    /** An RGB image, packed 0xRRGGBB per pixel, rows bottom-up. */
    record Img(int width, int height, int[] rgb) {
        /** Copies an RGBA buffer as {@link Pixels#read} fills it. */
        static Img of(ByteBuffer rgba, int width, int height) {
            int[] px = new int[width * height];
            for (int i = 0; i < px.length; i++) {
                int o = 4 * i;
                px[i] = (rgba.get(o) & 0xFF) << 16 | (rgba.get(o + 1) & 0xFF) << 8 | (rgba.get(o + 2) & 0xFF);
            }
            return new Img(width, height, px);
        }

        static Img filled(int width, int height, int rgb) {
            int[] px = new int[width * height];
            Arrays.fill(px, rgb);
            return new Img(width, height, px);
        }

        int at(int x, int y) {
            return rgb[y * width + x];
        }

        void set(int x, int y, int c) {
            rgb[y * width + x] = c;
        }
    }

    static int r(int c) {
        return c >> 16 & 0xFF;
    }

    static int g(int c) {
        return c >> 8 & 0xFF;
    }

    static int b(int c) {
        return c & 0xFF;
    }

    static int rgb(int r, int g, int b) {
        return r << 16 | g << 8 | b;
    }

    /** Rec. 709 luma of a packed colour, 0..255. */
    static double luma(int c) {
        return 0.2126 * r(c) + 0.7152 * g(c) + 0.0722 * b(c);
    }

    /** {hue degrees [0, 360), saturation [0, 1], value [0, 1]} of a packed colour. */
    static double[] hsv(int c) {
        double rr = r(c) / 255.0;
        double gg = g(c) / 255.0;
        double bb = b(c) / 255.0;
        double max = Math.max(rr, Math.max(gg, bb));
        double min = Math.min(rr, Math.min(gg, bb));
        double d = max - min;
        double h;
        if (d == 0) {
            h = 0;
        } else if (max == rr) {
            h = 60 * (((gg - bb) / d) % 6);
        } else if (max == gg) {
            h = 60 * ((bb - rr) / d + 2);
        } else {
            h = 60 * ((rr - gg) / d + 4);
        }
        if (h < 0) {
            h += 360;
        }
        return new double[] {h, max == 0 ? 0 : d / max, max};
    }

    /**
     * Whether two packed colours are "the same" to the eye: no channel differs by more than 3 levels or
     * 6% of the larger value, whichever is larger (a ratio, so dark soil and bright soil are judged alike).
     */
    static boolean sameColour(int p, int q) {
        return close(r(p), r(q)) && close(g(p), g(q)) && close(b(p), b(q));
    }

    private static boolean close(int a, int b) {
        return Math.abs(a - b) <= Math.max(3, 0.06 * Math.max(a, b));
    }

    /** Whether two packed colours differ by more than {@link Shots#TOLERANCE} in some channel. */
    static boolean differ(int p, int q) {
        return Math.max(Math.abs(r(p) - r(q)), Math.max(Math.abs(g(p) - g(q)), Math.abs(b(p) - b(q))))
                > Shots.TOLERANCE;
    }

    /** Pixels whose largest channel difference between a and b exceeds {@code tolerance} (0..255). */
    static boolean[] differ(Img a, Img b, int tolerance) {
        check(a, b);
        boolean[] m = new boolean[a.rgb.length];
        for (int i = 0; i < m.length; i++) {
            int p = a.rgb[i];
            int q = b.rgb[i];
            int d = Math.max(Math.abs(r(p) - r(q)), Math.max(Math.abs(g(p) - g(q)), Math.abs(b(p) - b(q))));
            m[i] = d > tolerance;
        }
        return m;
    }

    /**
     * The vegetation mask: pixels where the plants show in the full picture (it differs from the same
     * view without plants) and where plant geometry is (the plants drawn alone differ from the empty
     * view). The second condition keeps out ground that the plants only darken or tint.
     *
     * @param full       terrain and plants
     * @param ground     terrain alone
     * @param plantsOnly plants alone (no terrain)
     * @param empty      neither (sky only)
     * @param tolerance  largest channel difference still counted as equal, 0..255
     */
    static boolean[] vegetation(Img full, Img ground, Img plantsOnly, Img empty, int tolerance) {
        boolean[] a = differ(full, ground, tolerance);
        boolean[] b = differ(plantsOnly, empty, tolerance);
        for (int i = 0; i < a.length; i++) {
            a[i] &= b[i];
        }
        return a;
    }

    static int count(boolean[] mask) {
        int n = 0;
        for (boolean v : mask) {
            if (v) {
                n++;
            }
        }
        return n;
    }

    /** Share of the pixels of rows {@code [y0, y1)} that are in the mask. */
    static double coverage(boolean[] mask, int width, int y0, int y1) {
        int n = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = 0; x < width; x++) {
                if (mask[y * width + x]) {
                    n++;
                }
            }
        }
        return n / (double) (width * (y1 - y0));
    }

    /** Share of the lower half's pixels (rows {@code [0, height / 2)}, GL order) in the mask. */
    static double lowerHalfCoverage(boolean[] mask, int width, int height) {
        return coverage(mask, width, 0, height / 2);
    }

    /** Mask pixels with none of their 8 neighbours in the mask (outside the image counts as not). */
    static int isolated(boolean[] mask, int width, int height) {
        int n = 0;
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                if (mask[y * width + x] && neighbours(mask, width, height, x, y) == 0) {
                    n++;
                }
            }
        }
        return n;
    }

    /** {@link #isolated} as a share of the mask's pixels (0 for an empty mask). */
    static double isolatedShare(boolean[] mask, int width, int height) {
        int all = count(mask);
        return all == 0 ? 0 : isolated(mask, width, height) / (double) all;
    }

    private static int neighbours(boolean[] mask, int width, int height, int x, int y) {
        int n = 0;
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                int xx = x + dx;
                int yy = y + dy;
                if ((dx != 0 || dy != 0) && xx >= 0 && yy >= 0 && xx < width && yy < height
                        && mask[yy * width + xx]) {
                    n++;
                }
            }
        }
        return n;
    }

    /** 8-connected components of a mask: {@code labels[i]} is -1 off the mask, else the blob index. */
    record Blobs(int[] labels, int count, int[] sizes) {
    }

    static Blobs blobs(boolean[] mask, int width, int height) {
        int[] labels = new int[mask.length];
        Arrays.fill(labels, -1);
        int[] stack = new int[mask.length];
        int[] sizes = new int[16];
        int count = 0;
        for (int start = 0; start < mask.length; start++) {
            if (!mask[start] || labels[start] >= 0) {
                continue;
            }
            if (count == sizes.length) {
                sizes = Arrays.copyOf(sizes, 2 * count);
            }
            int top = 0;
            stack[top++] = start;
            labels[start] = count;
            int size = 0;
            while (top > 0) {
                int i = stack[--top];
                size++;
                int x = i % width;
                int y = i / width;
                for (int dy = -1; dy <= 1; dy++) {
                    for (int dx = -1; dx <= 1; dx++) {
                        int xx = x + dx;
                        int yy = y + dy;
                        if (xx >= 0 && yy >= 0 && xx < width && yy < height) {
                            int j = yy * width + xx;
                            if (mask[j] && labels[j] < 0) {
                                labels[j] = count;
                                stack[top++] = j;
                            }
                        }
                    }
                }
            }
            sizes[count++] = size;
        }
        return new Blobs(labels, count, Arrays.copyOf(sizes, count));
    }

    /** Mean colour of each blob: {@code [blob][r, g, b]}, 0..255. */
    static double[][] blobMeans(Img img, Blobs blobs) {
        double[][] m = new double[blobs.count()][3];
        for (int i = 0; i < img.rgb.length; i++) {
            int l = blobs.labels()[i];
            if (l >= 0) {
                int c = img.rgb[i];
                m[l][0] += r(c);
                m[l][1] += g(c);
                m[l][2] += b(c);
            }
        }
        for (int l = 0; l < m.length; l++) {
            for (int k = 0; k < 3; k++) {
                m[l][k] /= blobs.sizes()[l];
            }
        }
        return m;
    }

    /** {hue degrees, saturation, value} of a mean colour {r, g, b} in 0..255 (not rounded). */
    static double[] hsv(double[] mean) {
        double max = Math.max(mean[0], Math.max(mean[1], mean[2]));
        double min = Math.min(mean[0], Math.min(mean[1], mean[2]));
        double d = max - min;
        double h;
        if (d == 0) {
            h = 0;
        } else if (max == mean[0]) {
            h = 60 * (((mean[1] - mean[2]) / d) % 6);
        } else if (max == mean[1]) {
            h = 60 * ((mean[2] - mean[0]) / d + 2);
        } else {
            h = 60 * ((mean[0] - mean[1]) / d + 4);
        }
        if (h < 0) {
            h += 360;
        }
        return new double[] {h, max == 0 ? 0 : d / max, max / 255};
    }

    /**
     * Writes the mean luma of each {@code block} x {@code block} tile of img (row-major from the bottom
     * left, {@code width / block} per row, whole tiles only) into {@code series[tile][frame]}.
     */
    static void blockLuma(Img img, int block, double[][] series, int frame) {
        int bx = img.width() / block;
        int by = img.height() / block;
        for (int j = 0; j < by; j++) {
            for (int i = 0; i < bx; i++) {
                double sum = 0;
                for (int y = j * block; y < (j + 1) * block; y++) {
                    for (int x = i * block; x < (i + 1) * block; x++) {
                        sum += luma(img.at(x, y));
                    }
                }
                series[j * bx + i][frame] = sum / (block * block);
            }
        }
    }

    /** Population standard deviation; exactly 0 when every value is the same (no rounding left over). */
    static double sd(double[] v) {
        boolean same = true;
        for (double x : v) {
            same &= x == v[0];
        }
        if (same) {
            return 0;
        }
        double mean = 0;
        for (double x : v) {
            mean += x;
        }
        mean /= v.length;
        double s = 0;
        for (double x : v) {
            s += (x - mean) * (x - mean);
        }
        return Math.sqrt(s / v.length);
    }

    /** Standard deviation of angles in degrees, about their circular mean (wraps at 360). */
    static double circularSdDegrees(double[] degrees) {
        double sx = 0;
        double sy = 0;
        for (double d : degrees) {
            sx += Math.cos(Math.toRadians(d));
            sy += Math.sin(Math.toRadians(d));
        }
        double mean = Math.toDegrees(Math.atan2(sy, sx));
        double[] dev = new double[degrees.length];
        for (int i = 0; i < degrees.length; i++) {
            double d = degrees[i] - mean;
            d = ((d % 360) + 540) % 360 - 180;
            dev[i] = d;
        }
        double s = 0;
        for (double d : dev) {
            s += d * d;
        }
        return Math.sqrt(s / dev.length);
    }

    /**
     * Fine-detail contrast: mean absolute Laplacian of the luma, {@code |4 L - L(x +- 1) - L(y +- 1)|},
     * over the mask's pixels that are not on the image border (0..1020 range, luma levels). NaN for none.
     */
    static double meanAbsLaplacian(Img img, boolean[] mask) {
        int w = img.width;
        int h = img.height;
        double s = 0;
        long n = 0;
        for (int y = 1; y < h - 1; y++) {
            for (int x = 1; x < w - 1; x++) {
                int i = y * w + x;
                if (mask[i]) {
                    double lap = 4 * luma(img.rgb[i]) - luma(img.rgb[i - 1]) - luma(img.rgb[i + 1])
                            - luma(img.rgb[i - w]) - luma(img.rgb[i + w]);
                    s += Math.abs(lap);
                    n++;
                }
            }
        }
        return n == 0 ? Double.NaN : s / n;
    }

    /** Mean absolute channel difference between a and b over the mask (null: every pixel), 0..255. */
    static double meanAbsDiff(Img a, Img b, boolean[] mask) {
        check(a, b);
        double s = 0;
        long n = 0;
        for (int i = 0; i < a.rgb.length; i++) {
            if (mask == null || mask[i]) {
                int p = a.rgb[i];
                int q = b.rgb[i];
                s += Math.abs(r(p) - r(q)) + Math.abs(g(p) - g(q)) + Math.abs(b(p) - b(q));
                n += 3;
            }
        }
        return n == 0 ? 0 : s / n;
    }

    /**
     * How far {@code shifted} (the picture moved right by half a pixel) is from what a band-limited
     * picture moved by half a pixel would be, the average of {@code a}'s pixel and its left neighbour:
     * mean absolute channel difference over the mask (column 0 left out), 0..255. Zero for content
     * that is smooth at the pixel scale, large where edges alias (they jump by whole pixels).
     */
    static double halfPixelResidual(Img a, Img shifted, boolean[] mask) {
        check(a, shifted);
        int w = a.width;
        double s = 0;
        long n = 0;
        for (int i = 0; i < a.rgb.length; i++) {
            if (i % w == 0 || mask != null && !mask[i]) {
                continue;
            }
            int p = a.rgb[i];
            int l = a.rgb[i - 1];
            int q = shifted.rgb[i];
            s += Math.abs(r(q) - 0.5 * (r(p) + r(l))) + Math.abs(g(q) - 0.5 * (g(p) + g(l)))
                    + Math.abs(b(q) - 0.5 * (b(p) + b(l)));
            n += 3;
        }
        return n == 0 ? 0 : s / n;
    }

    /**
     * The width, pixels, over which a horizon-like edge (the sky above, the ground below) goes from 10%
     * to 90% of the way from one to the other, median over the columns with a clear edge. In each
     * column the edge is the first row from the top whose luminance differs from the sky's (the top
     * row) by more than a quarter of the contrast to the ground {@code margin} rows further down; the
     * 10% and 90% crossings are interpolated linearly between rows. NaN when no column qualifies.
     *
     * @param img    the picture
     * @param margin rows past the edge where the ground's luminance is read
     */
    static double edgeWidth(Img img, int margin) {
        int w = img.width;
        int h = img.height;
        double[] widths = new double[w];
        int n = 0;
        for (int x = 0; x < w; x++) {
            double sky = luma(img.at(x, h - 1));
            int edge = -1;
            for (int y = h - 2; y > margin; y--) {
                double l = luma(img.at(x, y));
                double ground = luma(img.at(x, Math.max(0, y - margin)));
                if (Math.abs(ground - sky) > 20 && Math.abs(l - sky) > 0.25 * Math.abs(ground - sky)) {
                    edge = y;
                    break;
                }
            }
            if (edge < 0 || edge + margin >= h - 1 || edge - margin < 0) {
                continue;
            }
            double top = luma(img.at(x, Math.min(h - 1, edge + margin)));
            double bottom = luma(img.at(x, edge - margin));
            double c = bottom - top;
            if (Math.abs(c) < 20) {
                continue;
            }
            double y10 = crossing(img, x, edge + margin, edge - margin, top + 0.1 * c);
            double y90 = crossing(img, x, edge + margin, edge - margin, top + 0.9 * c);
            if (Double.isNaN(y10) || Double.isNaN(y90)) {
                continue;
            }
            widths[n++] = Math.abs(y10 - y90);
        }
        if (n == 0) {
            return Double.NaN;
        }
        double[] v = Arrays.copyOf(widths, n);
        Arrays.sort(v);
        return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    }

    /** The row (fractional) going down column x from y0 to y1 where the luminance first crosses level. */
    private static double crossing(Img img, int x, int y0, int y1, double level) {
        double prev = luma(img.at(x, y0));
        for (int y = y0 - 1; y >= y1; y--) {
            double l = luma(img.at(x, y));
            if ((prev - level) * (l - level) <= 0 && prev != l) {
                return y + 1 - (level - prev) / (l - prev);
            }
            prev = l;
        }
        return Double.NaN;
    }

    /** {@code {largest, median}} of the values (median of an even count: mean of the middle two). */
    static double[] largestAndMedian(double[] values) {
        double[] v = values.clone();
        Arrays.sort(v);
        int n = v.length;
        double median = n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
        return new double[] {v[n - 1], median};
    }

    /**
     * A pop's own measure, free of the slow drift of what the picture shows (hills, the horizon): each
     * frame change over the median of its neighbours within {@code half} frames either side (itself
     * left out). A plant or tile popping in makes one frame's change stand out from its neighbours';
     * a walk over a hill raises several in a row and hardly moves this ratio.
     *
     * @param changes frame changes ({@link #frameChanges})
     * @param half    neighbours each side, &gt;= 1
     * @return per change, its ratio to its neighbours' median
     */
    static double[] localRatios(double[] changes, int half) {
        double[] out = new double[changes.length];
        double[] nb = new double[2 * half];
        for (int i = 0; i < changes.length; i++) {
            int n = 0;
            for (int j = Math.max(0, i - half); j <= Math.min(changes.length - 1, i + half); j++) {
                if (j != i) {
                    nb[n++] = changes[j];
                }
            }
            double[] v = Arrays.copyOf(nb, n);
            Arrays.sort(v);
            double median = n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
            out[i] = median > 0 ? changes[i] / median : 1;
        }
        return out;
    }

    /** Frame-to-frame change of a sequence: mean absolute difference of each picture from the previous. */
    static double[] frameChanges(Img[] frames) {
        double[] d = new double[frames.length - 1];
        for (int i = 1; i < frames.length; i++) {
            d[i - 1] = meanAbsDiff(frames[i - 1], frames[i], null);
        }
        return d;
    }

    /** Mean luma over the mask (NaN for an empty mask). */
    static double meanLuma(Img img, boolean[] mask) {
        double s = 0;
        long n = 0;
        for (int i = 0; i < img.rgb.length; i++) {
            if (mask[i]) {
                s += luma(img.rgb[i]);
                n++;
            }
        }
        return n == 0 ? Double.NaN : s / n;
    }

    private static void check(Img a, Img b) {
        if (a.width != b.width || a.height != b.height) {
            throw new IllegalArgumentException(a.width + "x" + a.height + " vs " + b.width + "x" + b.height);
        }
    }

    /**
     * The colour of {@code palette} (0xRRGGBB) whose hue is nearest the pixel's, or -1 when the pixel is
     * duller than {@code minSaturation} or darker than {@code minValue} (HSB, 0 to 1).
     */
    static int nearestHue(int rgb, int[] palette, float minSaturation, float minValue) {
        float[] hsv = java.awt.Color.RGBtoHSB((rgb >> 16) & 255, (rgb >> 8) & 255, rgb & 255, null);
        if (hsv[1] < minSaturation || hsv[2] < minValue) {
            return -1;
        }
        int best = -1;
        double bestD = 9;
        for (int b = 0; b < palette.length; b++) {
            float[] h = java.awt.Color.RGBtoHSB((palette[b] >> 16) & 255, (palette[b] >> 8) & 255, palette[b] & 255, null);
            double d = Math.abs(hsv[0] - h[0]);
            d = Math.min(d, 1 - d);
            if (d < bestD) {
                bestD = d;
                best = b;
            }
        }
        return best;
    }
}
