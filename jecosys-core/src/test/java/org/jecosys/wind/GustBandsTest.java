package org.jecosys.wind;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;

/**
 * Issue 41, "wind that runs in waves", in the field itself: a gust flow with {@code gustStretch} k reads
 * its gust pattern stretched across the wind, so the gusts' speed pattern is a set of bands k times longer
 * across the wind than along it (measured: the lag at which the pattern's autocorrelation falls to one half,
 * across over along, at least 2 for k = 4, about 1 for round gusts) that run with the mean wind (the
 * pattern one second later matches best when shifted by the wind's travel, within 20%). Round gusts (k = 1)
 * are the earlier pattern, value for value.
 */
class GustBandsTest {
    private static final double SCALE = 8;
    private static final double STEP = 0.5;
    private static final int N = 96;
    /** The wind: 4 m/s toward 30 degrees. */
    private static final double DIR = Math.toRadians(30);

    private static GustFlow gust(double stretch) {
        return new GustFlow(FlowDef.builder("g", FlowKind.GUST).strength(4).direction(DIR).noiseScale(SCALE)
                .noiseFrequency(0.1).gustStrength(0.6).seed(7).gustStretch(stretch).build());
    }

    /** The gust's speed over a grid whose rows run along the wind and columns across it, at time t. */
    private static double[][] speeds(GustFlow g, double t, double shift) {
        double hx = Math.cos(DIR);
        double hz = Math.sin(DIR);
        Vector2d u = new Vector2d();
        double[][] s = new double[N][N];
        for (int i = 0; i < N; i++) {        // along
            for (int j = 0; j < N; j++) {    // across
                double a = i * STEP + shift;
                double c = j * STEP;
                g.unweighted(a * hx - c * hz, a * hz + c * hx, t, u);
                s[i][j] = u.length();
            }
        }
        return s;
    }

    /** The lag (m) where the autocorrelation along (axis 0) or across (axis 1) first falls to one half. */
    private static double halfLag(double[][] s, int axis) {
        double mean = 0;
        for (double[] row : s) {
            for (double v : row) {
                mean += v;
            }
        }
        mean /= N * N;
        double var = 0;
        for (double[] row : s) {
            for (double v : row) {
                var += (v - mean) * (v - mean);
            }
        }
        for (int lag = 1; lag < N / 2; lag++) {
            double c = 0;
            int n = 0;
            for (int i = 0; i + (axis == 0 ? lag : 0) < N; i++) {
                for (int j = 0; j + (axis == 1 ? lag : 0) < N; j++) {
                    c += (s[i][j] - mean) * (s[i + (axis == 0 ? lag : 0)][j + (axis == 1 ? lag : 0)] - mean);
                    n++;
                }
            }
            if (c / n <= 0.5 * var / (N * N)) {
                return lag * STEP;
            }
        }
        return N / 2 * STEP;
    }

    private static double correlation(double[][] a, double[][] b) {
        double ma = 0;
        double mb = 0;
        for (int i = 0; i < N; i++) {
            for (int j = 0; j < N; j++) {
                ma += a[i][j];
                mb += b[i][j];
            }
        }
        ma /= N * N;
        mb /= N * N;
        double ab = 0;
        double aa = 0;
        double bb = 0;
        for (int i = 0; i < N; i++) {
            for (int j = 0; j < N; j++) {
                ab += (a[i][j] - ma) * (b[i][j] - mb);
                aa += (a[i][j] - ma) * (a[i][j] - ma);
                bb += (b[i][j] - mb) * (b[i][j] - mb);
            }
        }
        return ab / Math.sqrt(aa * bb);
    }

    @Test
    void stretchedGustsAreBandsAcrossTheWindThatRunWithIt() {
        double[][] round = speeds(gust(1), 3, 0);
        double[][] bands = speeds(gust(4), 3, 0);
        double roundRatio = halfLag(round, 1) / halfLag(round, 0);
        double bandRatio = halfLag(bands, 1) / halfLag(bands, 0);
        // one second later, the pattern compared at shifts along the wind: the best is the wind's travel (4 m)
        double best = 0;
        double bestCorr = -2;
        for (double shift = 0; shift <= 8; shift += 0.5) {
            double c = correlation(bands, speeds(gust(4), 4, shift));
            if (c > bestCorr) {
                bestCorr = c;
                best = shift;
            }
        }
        System.out.printf(Locale.ROOT, "[wind] half-correlation lengths across/along: round gusts %.2f, stretch 4 %.2f; "
                + "the bands one second later match best %.1f m downwind (wind 4 m/s), correlation %.3f%n", roundRatio,
                bandRatio, best, bestCorr);
        assertTrue(roundRatio > 0.6 && roundRatio < 1.6, "round gusts are about round: " + roundRatio);
        assertTrue(bandRatio >= 2, "stretched gusts are bands across the wind: " + bandRatio);
        assertEquals(4, best, 0.8, "the bands run with the wind");
        assertTrue(bestCorr > 0.8, "and keep their shape for a second: " + bestCorr);
    }

    @Test
    void roundGustsAreTheEarlierPatternValueForValue() {
        FlowDef d = gust(1).def();
        FlowDef before = new FlowDef(d.id(), d.kind(), d.enabled(), d.x(), d.z(), d.strength(), d.direction(),
                d.coreRadius(), d.influenceRadius(), d.activation(), d.motion(), d.noiseScale(), d.noiseFrequency(),
                d.seed(), d.gustStrength(), d.turbulence());
        assertEquals(d, before, "the constructor without a stretch gives round gusts");
        GustFlow g = new GustFlow(before);
        Vector2d u = new Vector2d();
        Vector2d w = new Vector2d();
        for (int k = 0; k < 50; k++) {
            double x = 3.7 * k;
            double z = -1.3 * k;
            double t = 0.21 * k;
            g.unweighted(x, z, t, u);
            // the pattern as it was read before stretching existed: at q = (p - U t) / s
            double qx = (x - 4 * Math.cos(DIR) * t) / SCALE;
            double qz = (z - 4 * Math.sin(DIR) * t) / SCALE;
            double along = 1 + 0.6 * org.jecosys.math.Noise.value3(7, qx, qz, 0.1 * t);
            double across = 0.6 * org.jecosys.math.Noise.value3(8, qx, qz, 0.1 * t);
            double ux = 4 * Math.cos(DIR);
            double uz = 4 * Math.sin(DIR);
            w.set(ux * along - uz * across, uz * along + ux * across);
            assertEquals(w.x, u.x, 1e-12);
            assertEquals(w.y, u.y, 1e-12);
        }
    }
}
