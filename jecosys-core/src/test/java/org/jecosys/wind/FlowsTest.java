package org.jecosys.wind;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;

class FlowsTest {
    private static final double EPS = 1e-12;

    static FlowDef def(FlowKind kind, double x, double z, double strength, double core, double influence,
                       ActivationDef act, MotionDef motion) {
        return new FlowDef(kind.xmlName(), kind, true, x, z, strength, 0.3, core, influence, act, motion, 8, 0.25, 42,
                FlowDef.DEFAULT_GUST_STRENGTH, FlowDef.DEFAULT_TURBULENCE);
    }

    static FlowDef point(FlowKind kind, double x, double z, double strength) {
        return def(kind, x, z, strength, 0.5, Double.POSITIVE_INFINITY, ActivationDef.ALWAYS, MotionDef.FIXED);
    }

    @Test
    void ofBuildsEveryKind() {
        assertInstanceOf(UniformFlow.class, WindSource.of(FlowDef.uniform("u", 1, 0)));
        assertInstanceOf(SourceFlow.class, WindSource.of(point(FlowKind.SOURCE, 0, 0, 1)));
        assertInstanceOf(SourceFlow.class, WindSource.of(point(FlowKind.SINK, 0, 0, 1)));
        assertInstanceOf(VortexFlow.class, WindSource.of(point(FlowKind.VORTEX, 0, 0, 1)));
        assertInstanceOf(GustFlow.class, WindSource.of(point(FlowKind.GUST, 0, 0, 1)));
        assertInstanceOf(BlastFlow.class, WindSource.of(point(FlowKind.BLAST, 0, 0, 1)));
        assertInstanceOf(RainFlow.class, WindSource.of(def(FlowKind.RAIN, 0, 0, 1, 0.5, 10,
                ActivationDef.ALWAYS, MotionDef.FIXED)));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> WindSource.of(point(FlowKind.RAIN, 0, 0, 1)));
        assertTrue(e.getMessage().contains("influenceRadius"));
    }

    @Test
    void uniformMatchesFormula() {
        WindSource u = WindSource.of(FlowDef.uniform("u", 3, Math.PI / 2));
        Vector2d v = u.velocity(17, -4, 5, new Vector2d());
        assertEquals(0, v.x, 1e-12);
        assertEquals(3, v.y, 1e-12);
    }

    @Test
    void sourceAndSinkMatchFormulaAtSamplePoints() {
        double a = 6;
        WindSource s = WindSource.of(point(FlowKind.SOURCE, 1, 2, a));
        WindSource k = WindSource.of(point(FlowKind.SINK, 1, 2, a));
        double[][] pts = {{4, 2}, {1, -3}, {3, 5}, {-7, 0.5}};
        Vector2d v = new Vector2d();
        for (double[] p : pts) {
            double dx = p[0] - 1;
            double dz = p[1] - 2;
            double r2 = dx * dx + dz * dz;
            s.velocity(p[0], p[1], 0, v);
            assertEquals(a / (2 * Math.PI) * dx / r2, v.x, EPS);
            assertEquals(a / (2 * Math.PI) * dz / r2, v.y, EPS);
            k.velocity(p[0], p[1], 0, v);
            assertEquals(-a / (2 * Math.PI) * dx / r2, v.x, EPS);
            assertEquals(-a / (2 * Math.PI) * dz / r2, v.y, EPS);
        }
    }

    @Test
    void sourceFallsOffAsOneOverR() {
        WindSource s = WindSource.of(point(FlowKind.SOURCE, 0, 0, 5));
        Vector2d v = new Vector2d();
        double r0 = 2;
        double speed0 = s.velocity(r0, 0, 0, v).length();
        for (double r = 2; r < 200; r *= 1.7) {
            double sp = s.velocity(r * Math.cos(r), r * Math.sin(r), 0, v).length();
            assertEquals(speed0 * r0 / r, sp, 1e-12);
        }
    }

    @Test
    void vortexIsTangentialAndCounterClockwiseFromAbove() {
        double g = 4;
        WindSource w = WindSource.of(point(FlowKind.VORTEX, -1, 3, g));
        Vector2d v = new Vector2d();
        // at c + (1, 0): toward -Z (counter-clockwise seen from above, +X right, +Z down the screen)
        w.velocity(0, 3, 0, v);
        assertEquals(0, v.x, EPS);
        assertEquals(-g / (2 * Math.PI), v.y, EPS);
        double[][] pts = {{2, 3}, {-1, 7}, {5, -2}, {-4, 1}};
        for (double[] p : pts) {
            double dx = p[0] + 1;
            double dz = p[1] - 3;
            double r2 = dx * dx + dz * dz;
            w.velocity(p[0], p[1], 0, v);
            assertEquals(g / (2 * Math.PI) * dz / r2, v.x, EPS);
            assertEquals(-g / (2 * Math.PI) * dx / r2, v.y, EPS);
            assertEquals(0, v.x * dx + v.y * dz, 1e-12, "tangential");
        }
    }

    @Test
    void finiteEverywhereAndZeroExactlyAtCentre() {
        FlowKind[] kinds = {FlowKind.SOURCE, FlowKind.SINK, FlowKind.VORTEX, FlowKind.BLAST};
        Vector2d v = new Vector2d();
        for (FlowKind k : kinds) {
            WindSource s = WindSource.of(point(k, 2, 2, 10));
            s.velocity(2, 2, 0.1, v);
            assertEquals(0, v.x, 0, k + " at centre");
            assertEquals(0, v.y, 0, k + " at centre");
            for (double d = 1e-300; d < 1e3; d *= 10) {
                s.velocity(2 + d, 2 - d, 0.1, v);
                assertTrue(Double.isFinite(v.x) && Double.isFinite(v.y), k + " at offset " + d);
            }
            // inside the core the magnitude tapers linearly: continuous at the core radius
            double inCore = s.velocity(2.25, 2, 0.1, v).length();
            double atCore = s.velocity(2.5, 2, 0.1, v).length();
            assertEquals(atCore / 2, inCore, 1e-12, k + " core taper");
        }
        WindSource gust = WindSource.of(point(FlowKind.GUST, 0, 0, 10));
        WindSource rain = WindSource.of(def(FlowKind.RAIN, 0, 0, 5, 0.2, 20, ActivationDef.ALWAYS, MotionDef.FIXED));
        for (double x = -30; x <= 30; x += 0.37) {
            for (double t = 0; t < 3; t += 0.31) {
                gust.velocity(x, -x * 0.5, t, v);
                assertTrue(Double.isFinite(v.x) && Double.isFinite(v.y));
                assertTrue(v.length() <= 10 * (1 + Math.sqrt(2) * GustFlow.AMPLITUDE) + 1e-9);
                rain.velocity(x, x * 0.3, t, v);
                assertTrue(Double.isFinite(v.x) && Double.isFinite(v.y));
            }
        }
    }

    @Test
    void influenceRadiusCutsTheFlow() {
        WindSource s = WindSource.of(def(FlowKind.SOURCE, 0, 0, 5, 0.5, 10, ActivationDef.ALWAYS, MotionDef.FIXED));
        Vector2d v = new Vector2d();
        assertTrue(s.velocity(9.9, 0, 0, v).length() > 0);
        assertEquals(0, s.velocity(10.1, 0, 0, v).length(), 0);
    }

    @Test
    void superpositionIsLinear() {
        WindField f = WindField.of(List.of(FlowDef.uniform("u", 2, 1.0), point(FlowKind.SOURCE, 1, 1, 3),
                new FlowDef("v", FlowKind.VORTEX, true, -2, 4, 5, 0, 0.5, Double.POSITIVE_INFINITY,
                        ActivationDef.ALWAYS, MotionDef.FIXED, 8, 0.25, 0, FlowDef.DEFAULT_GUST_STRENGTH,
                        FlowDef.DEFAULT_TURBULENCE),
                new FlowDef("g", FlowKind.GUST, true, 0, 0, 4, 0.2, 0.5, Double.POSITIVE_INFINITY,
                        ActivationDef.ALWAYS, MotionDef.FIXED, 8, 0.25, 7, FlowDef.DEFAULT_GUST_STRENGTH,
                        FlowDef.DEFAULT_TURBULENCE)));
        f.advance(1.3);
        Vector2d sum = new Vector2d();
        Vector2d one = new Vector2d();
        double[][] pts = {{0, 0}, {3, -2}, {-5, 6}, {1.01, 1}};
        for (double[] p : pts) {
            f.velocity(p[0], p[1], sum);
            double sx = 0;
            double sz = 0;
            for (int i = 0; i < f.size(); i++) {
                f.get(i).velocity(p[0], p[1], f.time(), one);
                sx += one.x;
                sz += one.y;
            }
            assertEquals(sx, sum.x, 1e-12);
            assertEquals(sz, sum.y, 1e-12);
        }
        // scaling the strength scales the velocity
        WindSource a = WindSource.of(point(FlowKind.VORTEX, 0, 0, 2));
        WindSource b = WindSource.of(point(FlowKind.VORTEX, 0, 0, 6));
        assertEquals(3 * a.velocity(3, 1, 0, one).x, b.velocity(3, 1, 0, sum).x, 1e-12);
    }

    @Test
    void gustIsSeededAndVaries() {
        WindSource a = WindSource.of(point(FlowKind.GUST, 0, 0, 5));
        WindSource b = WindSource.of(point(FlowKind.GUST, 0, 0, 5));
        Vector2d va = new Vector2d();
        Vector2d vb = new Vector2d();
        double min = Double.MAX_VALUE;
        double max = 0;
        for (int i = 0; i < 200; i++) {
            a.velocity(i * 0.7, i * 0.3, i * 0.5, va);
            b.velocity(i * 0.7, i * 0.3, i * 0.5, vb);
            assertEquals(va.x, vb.x, 0);
            assertEquals(va.y, vb.y, 0);
            min = Math.min(min, va.length());
            max = Math.max(max, va.length());
        }
        assertTrue(max - min > 0.5, "gusts vary: " + min + ".." + max);
    }

    @Test
    void blastIsAShortRadialPulse() {
        ActivationDef act = new ActivationDef(1, 0.5, 0, 0);
        WindSource b = WindSource.of(def(FlowKind.BLAST, 0, 0, 20, 0.5, Double.POSITIVE_INFINITY, act, MotionDef.FIXED));
        Vector2d v = new Vector2d();
        assertEquals(0, b.velocity(3, 0, 0.9, v).length(), 0, "before start");
        assertEquals(0, b.velocity(10, 0, 1.1, v).length(), 0, "beyond the front (4 m at 0.1 s)");
        b.velocity(3, 0, 1.1, v);
        double e = 1 - 0.1 / 0.5;
        assertEquals(e * e * 20 / (2 * Math.PI) / 3, v.x, 1e-12);
        assertEquals(0, v.y, 1e-12);
        assertEquals(0, b.velocity(3, 0, 1.6, v).length(), 0, "after the end");
    }

    @Test
    void rainGivesImpulsesOnlyOnItsDisc() {
        WindSource r = WindSource.of(new FlowDef("r", FlowKind.RAIN, true, 50, 50, 2, 0, 0.1, 10,
                ActivationDef.ALWAYS, MotionDef.FIXED, 1.0, 4.0, 9, FlowDef.DEFAULT_GUST_STRENGTH,
                FlowDef.DEFAULT_TURBULENCE));
        Vector2d v = new Vector2d();
        int nonZero = 0;
        for (double t = 0; t < 2; t += 0.05) {
            for (double x = 41; x < 60; x += 0.5) {
                if (r.velocity(x, 50.2, t, v).length() > 0) {
                    nonZero++;
                }
            }
            assertEquals(0, r.velocity(70, 50, t, v).length(), 0, "outside the disc");
            assertEquals(0, r.velocity(50, 38.5, t, v).length(), 0, "outside the disc");
        }
        assertTrue(nonZero > 50, "impulses seen: " + nonZero);
    }

    @Test
    void activationWindowAndRamps() {
        ActivationDef act = new ActivationDef(2, 10, 1, 4);
        WindSource s = WindSource.of(def(FlowKind.UNIFORM, 0, 0, 1, 0.5, Double.POSITIVE_INFINITY, act, MotionDef.FIXED));
        assertEquals(0, s.weight(1.99), 0);
        assertEquals(0, s.weight(2), 0);
        assertEquals(0.5, s.weight(2.5), 1e-12);
        assertEquals(1, s.weight(3), 1e-12);
        assertEquals(1, s.weight(8), 1e-12);
        assertEquals(0.5, s.weight(10), 1e-12);
        assertEquals(0, s.weight(12), 0);
        assertTrue(s.expired(12));
        Vector2d v = new Vector2d();
        assertEquals(0.5, s.velocity(0, 0, 10, v).length(), 1e-12);
        s.setEnabled(false);
        assertEquals(0, s.weight(5), 0);
        assertEquals(0, s.velocity(0, 0, 5, v).length(), 0);
        s.setEnabled(true);
        assertEquals(1, s.weight(5), 0);
        assertEquals(1, WindSource.of(FlowDef.uniform("f", 1, 0)).weight(1e9), 0);
    }
}
