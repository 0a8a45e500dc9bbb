package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.render.ImageMetrics.Blobs;
import org.jecosys.render.ImageMetrics.Img;
import org.junit.jupiter.api.Test;

/** The look tests' image measurements on small synthetic pictures with known answers. */
class ImageMetricsTest {
    private static final int SKY = 0x87CEEB;
    private static final int SOIL = 0x6B5A3A;
    private static final int GRASS = 0x3C8C28;

    @Test
    void vegetationIsWhereThePlantsShowAndArePresent() {
        Img ground = Img.filled(4, 2, SOIL);
        Img empty = Img.filled(4, 2, SKY);
        Img full = Img.filled(4, 2, SOIL);
        Img plants = Img.filled(4, 2, SKY);
        full.set(0, 0, GRASS);
        plants.set(0, 0, GRASS); // a visible blade
        plants.set(1, 0, GRASS); // a blade behind a hill: the full picture shows ground
        full.set(2, 0, 0x5B4A2A); // ground darkened by plants, no blade there
        full.set(3, 0, SOIL + 0x020202); // within the tolerance
        plants.set(3, 0, GRASS);
        boolean[] m = ImageMetrics.vegetation(full, ground, plants, empty, 3);
        assertArrayEquals(new boolean[] {true, false, false, false, false, false, false, false}, m);
    }

    @Test
    void coverageCountsTheLowerHalfInGlOrder() {
        boolean[] m = new boolean[4 * 4];
        m[0] = true; // bottom row
        m[1] = true;
        m[4 * 3] = true; // top row: not counted
        assertEquals(2 / 8.0, ImageMetrics.lowerHalfCoverage(m, 4, 4), 1e-12);
        assertEquals(1 / 4.0, ImageMetrics.coverage(m, 4, 3, 4), 1e-12);
    }

    @Test
    void isolatedPixelsHaveNoneOfTheirEightNeighbours() {
        int w = 6;
        boolean[] m = new boolean[w * 5];
        m[0] = true; // corner, alone
        m[2 * w + 2] = true; // a diagonal pair: not isolated
        m[3 * w + 3] = true;
        m[4 * w + 5] = true; // alone at the top edge
        assertEquals(2, ImageMetrics.isolated(m, w, 5));
        assertEquals(0.5, ImageMetrics.isolatedShare(m, w, 5), 1e-12);
        assertEquals(0, ImageMetrics.isolatedShare(new boolean[w * 5], w, 5));
    }

    @Test
    void blobsAreEightConnectedComponentsWithTheirMeanColour() {
        int w = 5;
        int h = 3;
        boolean[] m = new boolean[w * h];
        Img img = Img.filled(w, h, 0);
        m[0] = true;
        m[w + 1] = true; // diagonal to 0: same blob
        img.set(0, 0, ImageMetrics.rgb(100, 0, 0));
        img.set(1, 1, ImageMetrics.rgb(200, 0, 0));
        m[4] = true;
        m[w + 4] = true;
        m[2 * w + 4] = true;
        img.set(4, 0, ImageMetrics.rgb(0, 30, 0));
        img.set(4, 1, ImageMetrics.rgb(0, 60, 0));
        img.set(4, 2, ImageMetrics.rgb(0, 90, 0));
        Blobs b = ImageMetrics.blobs(m, w, h);
        assertEquals(2, b.count());
        assertArrayEquals(new int[] {2, 3}, b.sizes());
        assertEquals(b.labels()[0], b.labels()[w + 1]);
        assertEquals(-1, b.labels()[1]);
        double[][] mean = ImageMetrics.blobMeans(img, b);
        assertArrayEquals(new double[] {150, 0, 0}, mean[b.labels()[0]], 1e-9);
        assertArrayEquals(new double[] {0, 60, 0}, mean[b.labels()[4]], 1e-9);
    }

    @Test
    void hueAndValueOfKnownColours() {
        assertArrayEquals(new double[] {120, 1, 1}, ImageMetrics.hsv(0x00FF00), 1e-9);
        assertArrayEquals(new double[] {240, 1, 0.5}, ImageMetrics.hsv(new double[] {0, 0, 127.5}), 1e-9);
        assertEquals(0, ImageMetrics.hsv(0xFF0000)[0], 1e-9);
        assertEquals(300, ImageMetrics.hsv(0xFF00FF)[0], 1e-9);
        // 350 and 10 degrees are 10 apart from their mean at 0, not 170
        assertEquals(10, ImageMetrics.circularSdDegrees(new double[] {350, 10}), 1e-9);
        assertEquals(1, ImageMetrics.sd(new double[] {1, 3}), 1e-12);
    }

    @Test
    void laplacianSeesFineDetailNotFlatAreas() {
        int w = 8;
        int h = 8;
        Img flat = Img.filled(w, h, 0x404040);
        Img checker = Img.filled(w, h, 0);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                checker.set(x, y, (x + y) % 2 == 0 ? 0xFFFFFF : 0);
            }
        }
        boolean[] all = new boolean[w * h];
        java.util.Arrays.fill(all, true);
        assertEquals(0, ImageMetrics.meanAbsLaplacian(flat, all), 1e-9);
        assertEquals(4 * 255, ImageMetrics.meanAbsLaplacian(checker, all), 1e-6);
        assertTrue(Double.isNaN(ImageMetrics.meanAbsLaplacian(flat, new boolean[w * h])));
    }

    @Test
    void differencesOverAMask() {
        Img a = Img.filled(2, 1, 0x000000);
        Img b = Img.filled(2, 1, 0x000000);
        b.set(1, 0, 0x0C0C0C); // 12 in every channel
        assertEquals(6, ImageMetrics.meanAbsDiff(a, b, null), 1e-12);
        assertEquals(12, ImageMetrics.meanAbsDiff(a, b, new boolean[] {false, true}), 1e-12);
        assertEquals(0, ImageMetrics.meanAbsDiff(a, b, new boolean[] {true, false}), 1e-12);
        boolean[] d = ImageMetrics.differ(a, b, 11);
        assertFalse(d[0]);
        assertTrue(d[1]);
        assertFalse(ImageMetrics.differ(a, b, 12)[1]);
    }

    @Test
    void halfPixelResidualIsZeroForSmoothShiftsAndLargeForJumpingEdges() {
        int w = 6;
        Img ramp = Img.filled(w, 1, 0);
        Img rampShifted = Img.filled(w, 1, 0);
        Img edge = Img.filled(w, 1, 0);
        Img edgeJumped = Img.filled(w, 1, 0);
        for (int x = 0; x < w; x++) {
            int v = 20 * x;
            ramp.set(x, 0, ImageMetrics.rgb(v, v, v));
            int s = (int) Math.round(20 * (x - 0.5));
            s = Math.max(0, s);
            rampShifted.set(x, 0, ImageMetrics.rgb(s, s, s));
            edge.set(x, 0, x >= 3 ? 0xFFFFFF : 0);
            edgeJumped.set(x, 0, x >= 4 ? 0xFFFFFF : 0); // an aliased edge jumps a whole pixel
        }
        boolean[] inner = {false, false, true, true, true, true};
        assertEquals(0, ImageMetrics.halfPixelResidual(ramp, rampShifted, inner), 1e-9);
        assertEquals(127.5 / 4, ImageMetrics.halfPixelResidual(edge, edgeJumped, inner), 1e-9);
    }

    @Test
    void largestAndMedianFrameChange() {
        assertArrayEquals(new double[] {9, 2.5}, ImageMetrics.largestAndMedian(new double[] {3, 1, 9, 2}), 1e-12);
        assertArrayEquals(new double[] {5, 4}, ImageMetrics.largestAndMedian(new double[] {4, 5, 1}), 1e-12);
        Img a = Img.filled(1, 1, 0);
        Img b = Img.filled(1, 1, 0x030303);
        assertArrayEquals(new double[] {3, 3, 0}, ImageMetrics.frameChanges(new Img[] {a, b, a, a}), 1e-12);
    }
}
