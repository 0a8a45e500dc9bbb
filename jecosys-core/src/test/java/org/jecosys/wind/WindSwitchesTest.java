package org.jecosys.wind;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;

/**
 * The wind field reports when the sum of its flows jumps ({@link WindField#lastEdge}), and a gust's
 * pattern travels with its mean wind (frozen turbulence).
 */
class WindSwitchesTest {
    static final double H = 1.0 / 30;

    /** The edges reported by 90 advances of 1/30 s, NaN where none. */
    static double[] edges(WindField f) {
        double[] out = new double[90];
        for (int i = 0; i < out.length; i++) {
            f.advance(H);
            out[i] = f.lastEdge();
        }
        return out;
    }

    static void assertOneEdge(double[] edges, double at) {
        int found = 0;
        for (int i = 0; i < edges.length; i++) {
            if (!Double.isNaN(edges[i])) {
                found++;
                assertEquals(at, edges[i], 0, "the edge's time");
                assertTrue(at > i * H - 1e-9 && at <= (i + 1) * H + 1e-9, "reported by the advance over it: " + i);
            }
        }
        assertEquals(1, found, "one edge");
    }

    @Test
    void windowsOpeningOrClosingWithoutARampAreEdges() {
        assertOneEdge(edges(WindField.of(List.of(FlowDef.builder("on", FlowKind.UNIFORM).strength(3).start(1)
                .build()))), 1);
        assertOneEdge(edges(WindField.of(List.of(FlowDef.builder("off", FlowKind.UNIFORM).strength(3).duration(2)
                .build()))), 2);
        assertOneEdge(edges(WindField.of(List.of(FlowDef.builder("mid", FlowKind.GUST).strength(3).start(1.01)
                .ramps(0, 0.5).duration(1.5).build()))), 1.01);
        double[] ramped = edges(WindField.of(List.of(FlowDef.builder("ramped", FlowKind.UNIFORM).strength(3)
                .start(1).ramps(0.2, 0.2).duration(1).build())));
        for (double e : ramped) {
            assertTrue(Double.isNaN(e), "a ramp is no jump");
        }
        WindField off = WindField.of(List.of(FlowDef.builder("disabled", FlowKind.UNIFORM).strength(3).start(1)
                .enabled(false).build()));
        for (double e : edges(off)) {
            assertTrue(Double.isNaN(e), "a disabled flow's window is no jump");
        }
    }

    @Test
    void switchingAddingAndRemovingFlowsAreEdgesAtTheTimeTheyHappen() {
        WindField f = WindField.of(List.of(FlowDef.uniform("a", 2, 0)));
        WindSource b = f.add(FlowDef.uniform("b", 1, 0));
        f.advance(H);
        assertTrue(Double.isNaN(f.lastEdge()), "building the field is no jump");
        f.advance(H);
        double t = f.time();
        b.setEnabled(false);
        f.advance(H);
        assertEquals(t, f.lastEdge(), 0, "disabled between two advances: at the time before the second");
        f.advance(H);
        assertTrue(Double.isNaN(f.lastEdge()));
        t = f.time();
        f.remove(f.get(0));
        f.advance(H);
        assertEquals(t, f.lastEdge(), 0, "removed");
        t = f.time();
        f.add(FlowDef.uniform("c", 1, 0));
        f.advance(H);
        assertEquals(t, f.lastEdge(), 0, "added");
        b.setEnabled(true);
        b.setEnabled(false);
        f.advance(H);
        assertTrue(Double.isNaN(f.lastEdge()), "switched on and off again: no change");
    }

    @Test
    void aGustPatternTravelsWithItsMeanWind() {
        double u = 5;
        double heading = 0.6;
        WindSource g = WindSource.of(FlowDef.builder("g", FlowKind.GUST).strength(u).direction(heading).noiseScale(6)
                .noiseFrequency(1e-9).gustStrength(0.8).turbulence(0.6).seed(4).build());
        Vector2d here = new Vector2d();
        Vector2d there = new Vector2d();
        double varied = 0;
        for (int i = 0; i < 200; i++) {
            double x = 1.3 * i - 70;
            double z = 0.7 * i - 40;
            double t = 0.05 * i;
            double dt = 1.7;
            g.velocity(x, z, t, here);
            g.velocity(x + u * Math.cos(heading) * dt, z + u * Math.sin(heading) * dt, t + dt, there);
            assertEquals(here.x, there.x, 1e-6, "frozen: the pattern moved with the mean wind");
            assertEquals(here.y, there.y, 1e-6);
            g.velocity(x, z, t + dt, there);
            varied = Math.max(varied, here.distance(there));
        }
        assertTrue(varied > 1, "a fixed point sees gusts pass: " + varied);
    }
}
