package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

class SpeciesLibraryTest {
    private static void assertCounts(SpeciesDef def, int lod1, int lod2, int lod3) {
        SpeciesModel m = SpeciesModel.build(def, 7);
        assertEquals(3, m.levels());
        assertEquals(Primitive.TRIANGLES, m.mesh(0).primitive());
        assertEquals(Primitive.TRIANGLES, m.mesh(1).primitive());
        assertEquals(Primitive.LINES, m.mesh(2).primitive());
        assertEquals(lod1, m.primitiveCount(0), def.name() + " LOD1");
        assertEquals(lod2, m.primitiveCount(1), def.name() + " LOD2");
        assertEquals(lod3, m.primitiveCount(2), def.name() + " LOD3");
    }

    @Test
    void grassTuftMatchesTable2() {
        assertCounts(SpeciesLibrary.grassTuftA(), 250, 150, 175);
        assertEquals(25, SpeciesLibrary.grassTuftA().componentsPerPlant());
    }

    @Test
    void yellowFlowerMatchesTable2() {
        assertCounts(SpeciesLibrary.yellowFlowerB(), 72, 52, 37);
        assertEquals(7, SpeciesLibrary.yellowFlowerB().componentsPerPlant());
    }

    @Test
    void purpleFlowerMatchesTable2() {
        assertCounts(SpeciesLibrary.purpleFlowerC(), 78, 58, 39);
        assertEquals(7, SpeciesLibrary.purpleFlowerC().componentsPerPlant());
    }

    @Test
    void roseMatchesTable1() {
        assertCounts(SpeciesLibrary.rose(), 177, 105, 118);
    }

    @Test
    void table3Bands() {
        var lods = SpeciesLibrary.table3Lods();
        assertEquals(10, lods.get(0).maxDistance(), 0);
        assertEquals(15, lods.get(1).maxDistance(), 0);
        assertEquals(Double.POSITIVE_INFINITY, lods.get(2).maxDistance(), 0);
    }

    @Test
    void librarySizesAreRealisticAndEveryPoseStaysAboveGround() {
        Vector3f p = new Vector3f();
        for (SpeciesDef def : SpeciesLibrary.all()) {
            SpeciesModel m = SpeciesModel.build(def, 3);
            double tallest = 0;
            for (int c = 0; c < m.componentCount(); c++) {
                PlantComponent cm = m.component(c);
                ComponentDef d = cm.def();
                assertTrue(d.responseTime() >= 0.2 && d.responseTime() <= 0.6, def.id() + " tau");
                for (int v = 0; v < cm.variants(); v++) {
                    PoseTable t = cm.poseTable(v);
                    for (int k = 0; k < t.poses(); k++) {
                        for (int i = 0; i < t.points(); i++) {
                            assertTrue(t.position(k, i, p).y >= 0f);
                        }
                    }
                    if (d.attachTo() == null) {
                        tallest = Math.max(tallest, t.position(0, t.points() - 1, p).y);
                    }
                }
            }
            assertTrue(tallest > 0.1 && tallest < 0.7, def.id() + " height " + tallest);
        }
    }
}
