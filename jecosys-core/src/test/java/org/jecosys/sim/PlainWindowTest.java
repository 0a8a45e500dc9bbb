package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

/**
 * The draw decision's shortcut for plants drawn whole at one level ({@code LevelBands.plain}) gives the
 * levels and dither windows of the full arithmetic, bit for bit: the same decisions are made with the
 * shortcut's windows emptied, for eyes placed at, just inside and just outside each level's edge and
 * transition band, with and without a band, with and without distance thinning, and for eyes anywhere.
 */
class PlainWindowTest {
    private static final double[] EDGES = {2.0, 3.5, 7.25};

    @Test
    void shortcutDecidesAsTheFullArithmetic() throws Exception {
        World world = SimFixtures.world();
        int species = world.plants().species().size();
        int plants = world.plantCount();
        DrawDecision.Edges edges = new DrawDecision.Edges() {
            @Override
            public int levels(int s) {
                return s % 2 == 0 ? EDGES.length + 1 : 2;
            }

            @Override
            public double edge(int s, int l) {
                return EDGES[l];
            }
        };
        float[] radius = new float[species];
        Arrays.fill(radius, 0.3f);
        SplittableRandom r = new SplittableRandom(5);
        int plainSeen = 0;
        int fullSeen = 0;
        for (double transition : new double[] {0, 0.4, 1.0}) {
            LevelBands fast = new LevelBands(species).fill(edges, transition);
            LevelBands slow = new LevelBands(species).fill(edges, transition);
            RangeDecision fastRange = new RangeDecision(world, fast, radius);
            RangeDecision slowRange = new RangeDecision(world, slow, radius);
            for (double[] w : slow.plain) {
                for (int i = 0; i < w.length; i += 2) {
                    w[i] = Double.POSITIVE_INFINITY; // no plain window: always the full arithmetic
                    w[i + 1] = Double.NEGATIVE_INFINITY;
                }
            }
            for (int trial = 0; trial < 400; trial++) {
                // an eye at a chosen distance from one plant, along a random direction
                int p = r.nextInt(plants);
                double target = trial < 300 ? distanceNear(r, transition) : r.nextDouble() * 12;
                double a = r.nextDouble() * 2 * Math.PI;
                double ex = world.plantX(p) + target * Math.cos(a);
                double ey = world.plantY(p);
                double ez = world.plantZ(p) + target * Math.sin(a);
                boolean thin = trial % 3 == 0;
                double thinStart = thin ? distanceNear(r, transition) : 30;
                double thinEnd = thinStart + 2;
                double thinMin = thin ? 0.3 : 1;
                byte[] lf = new byte[plants];
                byte[] ls = new byte[plants];
                int[] kf = new int[plants];
                int[] ks = new int[plants];
                for (RangeDecision d : new RangeDecision[] {fastRange, slowRange}) {
                    d.setEye(ex, ey, ez, 1, -1);
                    d.setFrustum(null, false);
                    d.setThinning(thinStart, thinEnd, thinMin);
                }
                fastRange.decide(0, plants, lf, kf);
                slowRange.decide(0, plants, ls, ks);
                String where = "transition " + transition + ", eye " + target + " m from plant " + p;
                assertArrayEquals(ls, lf, where);
                assertArrayEquals(ks, kf, where);
                for (int q = 0; q < plants; q++) {
                    if (ks[q] == 255) {
                        plainSeen++;
                    } else {
                        fullSeen++;
                    }
                }
            }
        }
        assertTrue(plainSeen > 1000 && fullSeen > 1000, "plain " + plainSeen + ", other " + fullSeen);
    }

    /** A distance at, or a few roundings from, an edge or an edge less the band. */
    private static double distanceNear(SplittableRandom r, double band) {
        double e = EDGES[r.nextInt(EDGES.length)] - (r.nextBoolean() ? band : 0);
        int ulps = r.nextInt(-3, 4);
        for (int i = 0; i < Math.abs(ulps); i++) {
            e = ulps > 0 ? Math.nextUp(e) : Math.nextDown(e);
        }
        return Math.max(0, e);
    }
}
