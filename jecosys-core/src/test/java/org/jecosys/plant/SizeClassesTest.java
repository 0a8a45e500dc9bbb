package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * Size classes and uneven tufts of a species' variation ({@link VariationDef#sizeClasses()},
 * {@link VariationDef#size()}, {@link VariationDef#azimuth()}; issue 25): a plant's leaves vary within
 * its own size class, classes scale the lengths evenly, tuft heights spread; ground leaves leave the
 * golden-angle spread by at most the azimuth; the defaults are the old mapping and layout.
 */
class SizeClassesTest {
    private static VariationDef tufted(int variants, int classes, double size, double azimuthDegrees) {
        return VariationDef.builder().variants(variants).length(0.3).width(0.1).curvature(0.2).tilt(Math.toRadians(15))
                .build().withTufts(size, classes,
                Math.toRadians(azimuthDegrees));
    }

    @Test
    void oneSizeClassIsTheOldMapping() {
        VariationDef v = VariationDef.builder().variants(8).length(0.25).width(0.15).curvature(0.3).tilt(0.15).build();
        assertEquals(VariationDef.DEFAULT_SIZE_CLASSES, v.sizeClasses());
        for (int p = 0; p < 8; p++) {
            assertEquals(1.0, v.sizeScale(p));
            for (int off = 0; off < 40; off++) {
                assertEquals((p + off) % 8, v.slotVariant(p, off));
            }
        }
    }

    @Test
    void aPlantsInstancesStayInItsClassAndReachAllOfIt() {
        for (int[] c : new int[][] {{48, 8}, {50, 8}, {24, 7}, {5, 5}}) {
            VariationDef v = tufted(c[0], c[1], 0.5, 0);
            int[] classSize = new int[c[1]];
            for (int u = 0; u < c[0]; u++) {
                classSize[v.sizeClassOf(u)]++;
            }
            for (int g = 0; g < c[1]; g++) {
                assertTrue(classSize[g] == c[0] / c[1] || classSize[g] == c[0] / c[1] + 1,
                        "classes of nearly equal size: " + classSize[g]);
            }
            for (int p = 0; p < c[0]; p++) {
                int g = v.sizeClassOf(p);
                boolean[] seen = new boolean[c[0]];
                int reached = 0;
                for (int off = 0; off < 64; off++) {
                    int u = v.slotVariant(p, off);
                    assertEquals(g, v.sizeClassOf(u), "variants " + c[0] + " classes " + c[1] + " plant " + p);
                    if (!seen[u]) {
                        seen[u] = true;
                        reached++;
                    }
                }
                assertEquals(classSize[g], reached);
                assertEquals(p, v.slotVariant(p, 0), "instance 0 uses the plant's own variant");
            }
        }
    }

    @Test
    void classesScaleLengthsEvenlyOverTheSpread() {
        VariationDef v = tufted(40, 4, 0.4, 0);
        assertEquals(0.7, v.sizeScale(0), 1e-12);
        assertEquals(0.9, v.sizeScale(10), 1e-12);
        assertEquals(1.1, v.sizeScale(20), 1e-12);
        assertEquals(1.3, v.sizeScale(39), 1e-12);
        SpeciesDef flower = SpeciesLibrary.yellowFlowerB();
        SpeciesModel plain = SpeciesModel.build(flower.toBuilder().variation(tufted(40, 1, 0, 0)).build(), 7);
        SpeciesModel sized = SpeciesModel.build(flower.toBuilder().variation(v).build(), 7);
        for (int c = 0; c < flower.components().size(); c++) {
            boolean ground = flower.components().get(c).attachTo() == null;
            for (int u = 0; u < 40; u++) {
                double ratio = sized.component(c).length(u) / plain.component(c).length(u);
                double f = ground ? v.sizeScale(u) : 1;
                assertEquals(f, ratio, 1e-9, "component " + c + " variant " + u
                        + ": stalks and ground leaves scale with the class, petals and heads keep their size");
                assertEquals(f * f, sized.component(c).mass(u) / plain.component(c).mass(u), 1e-9,
                        "mass follows length and width");
            }
        }
    }

    @Test
    void tuftHeightsSpreadWithSizeClasses() {
        SpeciesDef base = SpeciesLibrary.grassTuftA();
        SpeciesModel even = SpeciesModel.build(base.toBuilder().variation(tufted(48, 1, 0, 0)).build(), 3);
        SpeciesModel sized = SpeciesModel.build(base.toBuilder().variation(tufted(48, 8, 0.5, 0)).build(), 3);
        double[] e = heightStats(even);
        double[] s = heightStats(sized);
        System.out.printf("tuft height over 48 plant variants: one class %.3f m s.d. %.1f%%, 8 classes size 0.5 "
                + "%.3f m s.d. %.1f%%%n", e[0], 100 * e[1] / e[0], s[0], 100 * s[1] / s[0]);
        assertTrue(e[1] / e[0] < 0.05, "with one class the tufts share their leaves, so their height");
        // gravity bends long leaves more, so heights spread less than lengths (the classes' lengths: s.d. 29% here)
        assertTrue(s[1] / s[0] >= 0.15 && s[1] / s[0] >= 3 * e[1] / e[0], "size classes spread tuft heights");
    }

    /** {mean, s.d.} over the plant variants of the height of the highest skeleton point at rest. */
    private static double[] heightStats(SpeciesModel m) {
        Vector3f p = new Vector3f();
        double[] h = new double[m.variants()];
        for (int v = 0; v < h.length; v++) {
            for (int s = 0; s < m.slotCount(); s++) {
                PoseTable t = m.slotPoseTable(s, v);
                for (int k = 0; k < t.points(); k++) {
                    h[v] = Math.max(h[v], t.position(0, k, p).y);
                }
            }
        }
        double mean = 0;
        for (double x : h) {
            mean += x / h.length;
        }
        double var = 0;
        for (double x : h) {
            var += (x - mean) * (x - mean) / h.length;
        }
        return new double[] {mean, Math.sqrt(var)};
    }

    @Test
    void groundLeavesLeaveTheEvenSpreadByAtMostTheAzimuth() {
        SpeciesDef base = SpeciesLibrary.grassTuftA();
        SpeciesModel even = SpeciesModel.build(base, 5);
        SpeciesModel jittered = SpeciesModel.build(base.toBuilder().variation(base.variation().withTufts(0, 1,
                Math.toRadians(60))).build(), 5);
        SpeciesModel again = SpeciesModel.build(base.toBuilder().variation(base.variation().withTufts(0, 1,
                Math.toRadians(60))).build(), 5);
        int moved = 0;
        for (int s = 0; s < even.slotCount(); s++) {
            double d = Math.IEEEremainder(jittered.slotAzimuth(s) - even.slotAzimuth(s), 2 * Math.PI);
            assertTrue(Math.abs(d) <= Math.toRadians(60) + 1e-9, "slot " + s + " moved " + Math.toDegrees(d));
            assertTrue(jittered.slotAzimuth(s) >= 0 && jittered.slotAzimuth(s) < 2 * Math.PI);
            assertEquals(again.slotAzimuth(s), jittered.slotAzimuth(s), "seeded");
            double r = Math.hypot(jittered.slotBaseX(s), jittered.slotBaseZ(s));
            assertEquals(Math.hypot(even.slotBaseX(s), even.slotBaseZ(s)), r, 1e-12, "same disc radius");
            moved += Math.abs(d) > 1e-6 ? 1 : 0;
        }
        assertTrue(moved >= even.slotCount() - 1, "the leaves moved: " + moved);
        assertNotEquals(even.slotAzimuth(1), jittered.slotAzimuth(1));
    }

    @Test
    void attachedAndSingleInstancesKeepTheirAzimuth() {
        SpeciesDef base = SpeciesLibrary.yellowFlowerB();
        SpeciesModel even = SpeciesModel.build(base, 5);
        SpeciesModel jittered = SpeciesModel.build(base.toBuilder().variation(base.variation().withTufts(0, 1,
                Math.toRadians(90))).build(), 5);
        for (int s = 0; s < even.slotCount(); s++) {
            int c = even.slotComponent(s);
            if (even.slotParent(s) >= 0 || base.components().get(c).count() == 1) {
                assertEquals(even.slotAzimuth(s), jittered.slotAzimuth(s), "slot " + s);
            }
        }
    }

    @Test
    void badValuesAreRefusedWithTheRange() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> tufted(8, 9, 0.3, 0));
        assertTrue(e.getMessage().startsWith("sizeClasses must be in [1, variants = 8]"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> tufted(8, 0, 0.3, 0));
        assertThrows(IllegalArgumentException.class, () -> tufted(8, 4, 0.95, 0));
        assertThrows(IllegalArgumentException.class, () -> tufted(8, 4, -0.1, 0));
        assertThrows(IllegalArgumentException.class, () -> tufted(8, 4, 0.3, 181));
        assertThrows(IllegalArgumentException.class, () -> tufted(8, 4, 0.3, -1));
    }
}
