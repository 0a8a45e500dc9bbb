package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jecosys.math.Progress;
import org.jecosys.math.Rgb;
import org.junit.jupiter.api.Test;

class SpeciesModelTest {
    private static boolean sameTables(SpeciesModel a, SpeciesModel b) {
        for (int c = 0; c < a.componentCount(); c++) {
            for (int v = 0; v < a.variants(); v++) {
                PoseTable x = a.component(c).poseTable(v);
                PoseTable y = b.component(c).poseTable(v);
                for (int i = 0; i < x.floatCount(); i++) {
                    if (Float.floatToIntBits(x.get(i)) != Float.floatToIntBits(y.get(i))) {
                        return false;
                    }
                }
            }
        }
        return true;
    }

    @Test
    void variationIsDeterministicForASeed() {
        SpeciesDef def = SpeciesLibrary.grassTuftA();
        assertTrue(sameTables(SpeciesModel.build(def, 11), SpeciesModel.build(def, 11)));
        assertEquals(ComponentVariant.sample(def.variation(), 5, 2, 0), ComponentVariant.sample(def.variation(), 5, 2, 0));
    }

    @Test
    void variationDiffersBetweenSeedsAndBetweenVariants() {
        SpeciesDef def = SpeciesLibrary.grassTuftA();
        SpeciesModel a = SpeciesModel.build(def, 11);
        SpeciesModel b = SpeciesModel.build(def, 12);
        assertTrue(!sameTables(a, b));
        assertNotEquals(a.component(0).length(0), b.component(0).length(0));
        assertNotEquals(a.component(0).length(0), a.component(0).length(1));
    }

    @Test
    void variantsStayWithinTheDocumentedFractions() {
        VariationDef v = VariationDef.builder().variants(64).length(0.2).width(0.1).curvature(0.3).tilt(0.15).build();
        for (int i = 0; i < 64; i++) {
            ComponentVariant cv = ComponentVariant.sample(v, 99, i, 1);
            assertTrue(Math.abs(cv.lengthScale() - 1) <= 0.2);
            assertTrue(Math.abs(cv.widthScale() - 1) <= 0.1);
            assertTrue(Math.abs(cv.curvatureScale() - 1) <= 0.3);
            assertTrue(cv.extraTilt() >= 0 && cv.extraTilt() <= 0.15);
        }
    }

    @Test
    void plantPicksVariantAndAzimuthFromItsSeed() {
        SpeciesModel m = SpeciesModel.build(SpeciesLibrary.yellowFlowerB(), 1);
        int[] hits = new int[m.variants()];
        for (long s = 0; s < 600; s++) {
            int v = m.variantFor(s);
            assertEquals(v, m.variantFor(s));
            hits[v]++;
            double az = SpeciesModel.restAzimuthFor(s);
            assertTrue(az >= 0 && az < 2 * Math.PI);
        }
        for (int h : hits) {
            assertTrue(h > 0, "every variant used");
        }
        assertNotEquals(SpeciesModel.restAzimuthFor(1), SpeciesModel.restAzimuthFor(2));
    }

    @Test
    void slotsAttachToTheirParents() {
        SpeciesModel m = SpeciesModel.build(SpeciesLibrary.rose(), 1);
        assertEquals(19, m.slotCount());
        assertEquals(-1, m.slotParent(0));
        for (int s = 0; s < m.slotCount(); s++) {
            ComponentDef d = m.component(m.slotComponent(s)).def();
            if (d.attachTo() == null) {
                assertEquals(-1, m.slotParent(s));
            } else {
                assertEquals(d.attachTo(), m.component(m.slotComponent(m.slotParent(s))).def().id());
            }
            int v = m.slotVariant(s, 3);
            assertTrue(v >= 0 && v < m.variants());
        }
        LodMesh mesh = m.mesh(0);
        for (int v = 0; v < mesh.vertexCount(); v++) {
            int slot = mesh.vertexSlot(v);
            assertTrue(mesh.vertexPoint(v) < m.component(m.slotComponent(slot)).poseTable(0).points());
        }
    }

    @Test
    void noGravityBuildIsStraightPlusOwnCurvature() {
        ComponentDef c = new ComponentDef("blade", ComponentType.LEAF, ComponentShape.STRIP, 1, null, 4, 0.4,
                0.01, 0.01, 0, 0, 0, 1e-3, 0.2, 0.3, 0.001, new Rgb(0, 1, 0), List.of(4), null, null);
        SpeciesDef def = new SpeciesDef("s", "s", 8, 1.0, List.of(c),
                List.of(new LodDef(Double.POSITIVE_INFINITY, Primitive.TRIANGLES)), VariationDef.NONE, TrailDef.NONE);
        PoseTable t = SpeciesModel.build(def, 0, 0.0).component(0).poseTable(0);
        for (int i = 0; i < t.points(); i++) {
            assertEquals(0, t.get(t.offset(0, i)), 1e-7);
        }
        PoseTable g = SpeciesModel.build(def, 0, 9.81).component(0).poseTable(0);
        assertEquals(0, g.get(g.offset(0, 4)), 1e-7, "vertical and straight is an equilibrium");
    }

    @Test
    void buildAllReportsTimeAndProgress() {
        int[] calls = new int[1];
        Progress p = (step, done, total) -> calls[0]++;
        PlantModel pm = PlantModel.build(SpeciesLibrary.all(), 42, GravityBend.EARTH_GRAVITY, p);
        assertEquals(4, pm.species().size());
        assertEquals(4, calls[0]);
        assertTrue(pm.buildNanos() > 0);
        assertThrows(IllegalArgumentException.class, () -> PlantModel.build(List.of(), 1, 9.81, Progress.NONE));
        assertThrows(IllegalArgumentException.class, () -> SpeciesModel.build(SpeciesLibrary.rose(), 1, -1));
    }
}
