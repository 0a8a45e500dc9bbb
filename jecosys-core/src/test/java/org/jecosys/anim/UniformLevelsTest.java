package org.jecosys.anim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * A range animated with the box round its plants' bases ({@link AnimationStep#bounds}) takes the same
 * levels of detail and the same state as without it, bit for bit, whether its plants take one level
 * per species (the shortcut) or not: eyes near, far and at level edges, two species with different
 * edges, plants on a grid cut into ranges of 20.
 */
class UniformLevelsTest {
    @Test
    void boundsChangeNothingButTheWork() {
        SpringKinds.Builder b = new SpringKinds.Builder();
        b.add(0.2, 0.3, 0.0004, 0.002, 0.4, 0.05, 1.2, 16, 0b001);
        b.add(0.5, 0.6, 0.0008, 0.003, 0.3, 0.02, 1.0, 16, 0xFF);
        int plants = 400;
        int[] species = new int[plants];
        int[] first = new int[plants + 1];
        float[] x = new float[plants];
        float[] y = new float[plants];
        float[] z = new float[plants];
        for (int p = 0; p < plants; p++) {
            species[p] = p % 3 == 0 ? 1 : 0;
            x[p] = (p % 20) * 0.7f - 7;
            z[p] = (p / 20) * 0.7f - 7;
            y[p] = 0.05f * (p % 7);
            first[p + 1] = first[p] + 3;
        }
        int[] kind = new int[first[plants]];
        for (int c = 0; c < kind.length; c++) {
            kind[c] = c % 3 == 0 ? 0 : 1;
        }
        double[][] edges = {{2, 5}, {3, 8, 12}};
        AnimationState with = new AnimationState(b.build(), edges, species, first, x, y, z, kind, new float[kind.length]);
        AnimationState without = new AnimationState(b.build(), edges, species, first, x, y, z, kind,
                new float[kind.length]);
        int ranges = plants / 20;
        float[] box = new float[6 * ranges];
        for (int r = 0; r < ranges; r++) {
            box[6 * r] = box[6 * r + 1] = box[6 * r + 2] = Float.POSITIVE_INFINITY;
            box[6 * r + 3] = box[6 * r + 4] = box[6 * r + 5] = Float.NEGATIVE_INFINITY;
            for (int p = 20 * r; p < 20 * r + 20; p++) {
                float[] at = {x[p], y[p], z[p]};
                for (int k = 0; k < 3; k++) {
                    box[6 * r + k] = Math.min(box[6 * r + k], at[k]);
                    box[6 * r + 3 + k] = Math.max(box[6 * r + 3 + k], at[k]);
                }
            }
        }
        float[] wx = new float[plants];
        float[] wz = new float[plants];
        boolean[] visible = new boolean[plants];
        java.util.Arrays.fill(visible, true);
        AnimationStep[] stepWith = new AnimationStep[ranges];
        for (int r = 0; r < ranges; r++) {
            stepWith[r] = new AnimationStep().bounds(box, 6 * r);
        }
        AnimationStep stepWithout = new AnimationStep();
        double[][] eyes = {{0, 1, 0}, {0, 1.5, -9}, {0, 2, -12}, {14, 1, 3}, {-3, 25, 0}, {2, 6, 2}, {0, 0.1, -7.5}};
        int uniform = 0;
        int mixed = 0;
        byte[] table = new byte[2];
        for (int k = 0; k < 60; k++) {
            double[] e = eyes[k % eyes.length];
            for (int p = 0; p < plants; p++) {
                wx[p] = (float) (3 + Math.sin(0.1 * k + p));
                wz[p] = (float) Math.cos(0.07 * k * p);
            }
            for (int r = 0; r < ranges; r++) {
                stepWith[r].set(AnimationMode.CONSTRAINT, wx, wz, visible).eye(e[0], e[1], e[2]);
                stepWithout.set(AnimationMode.CONSTRAINT, wx, wz, visible).eye(e[0], e[1], e[2]);
                with.animate(20 * r, 20 * r + 20, stepWith[r]);
                without.animate(20 * r, 20 * r + 20, stepWithout);
                if (with.levels().uniform(box, 6 * r, e[0], e[1], e[2], 1, -1, table)) {
                    uniform++;
                } else {
                    mixed++;
                }
            }
            for (int p = 0; p < plants; p++) {
                assertEquals(without.level(p), with.level(p), "plant " + p + ", eye " + java.util.Arrays.toString(e));
            }
            assertEquals(without.stateHash(), with.stateHash(), "step " + k);
        }
        assertTrue(uniform > 100 && mixed > 100, "ranges with one level per species " + uniform + ", others " + mixed);
    }

    @Test
    void aBoxMustFitItsArray() {
        AnimationStep step = new AnimationStep();
        float[] box = new float[12];
        assertEquals(step, step.bounds(box, 6));
        assertEquals(step, step.bounds(null, -1));
        for (int bad : new int[] {-1, 7, 12}) {
            IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                    () -> step.bounds(box, bad));
            assertTrue(e.getMessage().contains("offset " + bad), e.getMessage());
        }
    }
}
