package org.jecosys.render;

import java.nio.ByteBuffer;

/** How much of a band of a picture is not sky, for the open world's tests in this module and the app's. */
public final class SkyShare {
    private SkyShare() {
    }

    /**
     * {@return the share of the pixels in rows [y0, y1) (from the bottom) of an RGBA picture {@code width}
     * pixels wide that are not sky: not clearly bluest}
     */
    public static double covered(ByteBuffer px, int width, int y0, int y1) {
        int n = 0;
        int hit = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = 0; x < width; x++) {
                int i = 4 * (y * width + x);
                int r = px.get(i) & 255;
                int g = px.get(i + 1) & 255;
                int b = px.get(i + 2) & 255;
                hit += b > r + 12 && b > g + 6 ? 0 : 1;
                n++;
            }
        }
        return hit / (double) n;
    }
}
