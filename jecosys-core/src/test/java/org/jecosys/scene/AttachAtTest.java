package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.ComponentType;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.plant.SpeciesModel;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code <component attachTo attachAt>}: leaves carried part-way up a flower stalk. The share snaps to a
 * skeleton point of the carrier, the child's gravity load on the carrier is weighted by it, it is
 * written back only where it is not the tip, and a share without a carrier or out of range is refused
 * at the component's line and column.
 */
class AttachAtTest {
    @TempDir
    Path dir;

    /** A flower: a 6-segment stalk, a head on its tip and leaves with the attributes {@code leaf} (line 7). */
    private Path scene(String leaf) throws Exception {
        Path file = dir.resolve("flower.xml");
        Files.writeString(file, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<scene version=\"1\">\n"
                + "  <terrain sizeX=\"4\" sizeZ=\"4\" resolution=\"17\"/>\n  <species id=\"flower\"><lod/>\n"
                + "    <component id=\"stalk\" type=\"stalk\" segments=\"6\" length=\"0.6\" baseWidth=\"0.004\" tilt=\"20\" mass=\"0.004\" stiffness=\"0.05\" lodSegments=\"6\"/>\n"
                + "    <component id=\"head\" type=\"head\" attachTo=\"stalk\" segments=\"2\" length=\"0.02\" baseWidth=\"0.01\" mass=\"0.002\" stiffness=\"1\" lodSegments=\"2\"/>\n"
                + "    <component id=\"leaf\" type=\"leaf\" count=\"2\" segments=\"4\" length=\"0.1\" baseWidth=\"0.01\" mass=\"0.002\"\n"
                + "        stiffness=\"0.3\" lodSegments=\"4\" " + leaf + "/>\n  </species>\n"
                + "  <plant species=\"flower\" x=\"0\" z=\"0\"/>\n</scene>\n", StandardCharsets.UTF_8);
        return file;
    }

    private static SpeciesModel model(SceneDef def) {
        return SpeciesModel.build(def.species().get(0), 1, 9.81);
    }

    /** Where the stalk's tip leans in its rest pose (variant 0), metres from its base axis. */
    private static double stalkLean(SpeciesModel m) {
        PoseTable t = m.component(0).poseTable(0);
        Vector3f tip = t.position(0, t.points() - 1, new Vector3f());
        return Math.hypot(tip.x, tip.z);
    }

    @Test
    void leavesSitOnTheStalksNearestPointAndLoadItByTheirShare() throws Exception {
        SceneDef half = SceneFiles.parse(scene("attachTo=\"stalk\" attachAt=\"0.5\""));
        SceneDef third = SceneFiles.parse(scene("attachTo=\"stalk\" attachAt=\"0.3\""));
        SceneDef tip = SceneFiles.parse(scene("attachTo=\"stalk\""));
        SceneDef ground = SceneFiles.parse(scene(""));
        SpeciesModel m = model(half);
        // slots: stalk, head, leaf, leaf
        assertEquals(-1, m.slotAttachPoint(0), "the stalk stands on the ground");
        assertEquals(6, m.slotAttachPoint(1), "the head on the stalk's tip");
        assertEquals(3, m.slotAttachPoint(2), "0.5 of 6 segments: point 3");
        assertEquals(3, m.slotAttachPoint(3));
        assertEquals(2, model(third).slotAttachPoint(2), "0.3 of 6 = 1.8: point 2");
        assertEquals(6, model(tip).slotAttachPoint(2), "no attachAt: the tip");
        assertEquals(1, ComponentDef.builder("x", ComponentType.LEAF).segments(2).length(0.1).baseWidth(0.01)
                .mass(1e-3).stiffness(1).lodSegments(java.util.List.of(2)).attachTo("s").attachAt(0.001).build()
                .attachPoint(6), "at least the first point above the base");
        // the leaves' 4 g load the stalk's tip at half their weight: the stalk leans between the two
        double leanGround = stalkLean(model(ground));
        double leanHalf = stalkLean(m);
        double leanTip = stalkLean(model(tip));
        assertTrue(leanGround < leanHalf && leanHalf < leanTip,
                "lean: leaves on the ground " + leanGround + ", half-way " + leanHalf + ", on the tip " + leanTip);
    }

    @Test
    void attachAtIsWrittenBackOnlyWhereItIsNotTheTip() throws Exception {
        SceneDef half = SceneFiles.parse(scene("attachTo=\"stalk\" attachAt=\"0.5\""));
        SpeciesDef s = half.species().get(0);
        assertEquals(0.5, s.components().get(2).attachAt());
        assertEquals(1.0, s.components().get(1).attachAt(), "the head: the default");
        String xml = SceneFiles.toXml(half);
        assertTrue(xml.contains("attachAt=\"0.5\""), xml);
        assertEquals(1, xml.split("attachAt=", -1).length - 1, "only the leaves' share is written: " + xml);
        Path again = dir.resolve("again.xml");
        Files.writeString(again, xml);
        assertEquals(half.species(), SceneFiles.parse(again).species(), "read back the same");
        assertFalse(SceneFiles.toXml(SceneFiles.parse(scene(""))).contains("attachAt"));
    }

    @Test
    void aShareWithoutACarrierOrOutOfRangeIsRefusedAtItsLineAndColumn() throws Exception {
        String[][] refused = {
            {"attachAt=\"0.5\"", "needs attachTo"},
            {"attachTo=\"stalk\" attachAt=\"0\"", "attachAt"},
            {"attachTo=\"stalk\" attachAt=\"1.5\"", "attachAt"},
            {"attachTo=\"stalk\" attachAt=\"half\"", "attachAt"},
        };
        for (String[] r : refused) {
            Path file = scene(r[0]);
            SceneLoadException e = assertThrows(SceneLoadException.class, () -> SceneFiles.read(file), r[0]);
            SceneProblem p = e.problems().get(0);
            assertTrue(p.line() == 7 || p.line() == 8, r[0] + ": " + p);
            assertTrue(p.column() > 1, r[0] + ": " + p);
            assertTrue(p.message().contains(r[1]), r[0] + ": " + p);
            assertTrue(e.getMessage().contains("flower.xml:"), r[0] + ": FILE:LINE:COL in " + e.getMessage());
        }
        assertThrows(IllegalArgumentException.class, () -> ComponentDef.builder("x", ComponentType.LEAF).segments(2)
                .length(0.1).baseWidth(0.01).mass(1e-3).stiffness(1).lodSegments(java.util.List.of(2)).attachAt(0.5)
                .build(), "the API refuses a share without a carrier too");
    }
}
