package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.HexFormat;
import org.jecosys.math.Progress;
import org.jecosys.plant.LodMesh;
import org.jecosys.plant.PlantComponent;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.scene.SceneFiles;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The paper's scenes (C1-C3 of Tables 4-7, the rose of Table 1) and the prairie build exactly the
 * plants they built before natural placement and tuft shape were added (issue 25): the new
 * {@code <distribution>} and {@code <variation>} attributes default to the old behaviour. The
 * reference digests were computed on the code before that change; a digest covers every plant's
 * position, rest azimuth, species and variant, every slot's variant, azimuth and base offset, every
 * pose table of every (component, variant) and every level's whole-plant mesh.
 */
class PaperScenesUnchangedTest {
    @ParameterizedTest
    @CsvSource({
            "c1.xml, d52546c8239c92585902884bf2547911",
            "c2.xml, 9351ae981edffc9e5efe92ead2e4c67d",
            "c3.xml, c893e675c95ba4af2db7f647653a18eb",
            "rose.xml, 78d5ef05968d565dbcd34ba07f19bef0",
            "prairie.xml, be66c1a2b309d0c18b4dcf073201b6f9"})
    void buildsTheSamePlantsAsBefore(String file, String reference) throws Exception {
        World w = World.build(SceneFiles.parse(Path.of("scenes", file)).simulationDef(), Path.of("scenes"), 2,
                Progress.NONE);
        String digest = digest(w);
        System.out.printf("%s: %d plants, %d components, digest %s%n", file, w.plantCount(), w.componentCount(),
                digest);
        assertEquals(reference, digest, file + " built other plants than before");
    }

    static String digest(World w) throws Exception {
        MessageDigest md = MessageDigest.getInstance("SHA-256");
        ByteBuffer b = ByteBuffer.allocate(64);
        for (SpeciesModel m : w.plants().species()) {
            for (int c = 0; c < m.componentCount(); c++) {
                PlantComponent pc = m.component(c);
                for (int v = 0; v < pc.variants(); v++) {
                    PoseTable t = pc.poseTable(v);
                    for (int i = 0; i < t.floatCount(); i++) {
                        md.update(b.clear().putFloat(t.get(i)).flip());
                    }
                    md.update(b.clear().putDouble(pc.length(v)).putDouble(pc.mass(v)).flip());
                }
            }
            for (int s = 0; s < m.slotCount(); s++) {
                md.update(b.clear().putInt(m.slotComponent(s)).putInt(m.slotParent(s)).putDouble(m.slotAzimuth(s))
                        .putDouble(m.slotBaseX(s)).putDouble(m.slotBaseZ(s)).flip());
                for (int v = 0; v < m.variants(); v++) {
                    md.update(b.clear().putInt(m.slotVariant(s, v)).flip());
                }
            }
            for (int l = 0; l < m.levels(); l++) {
                LodMesh mesh = m.mesh(l);
                float[] vs = new float[4 * mesh.vertexCount()];
                int[] is = new int[mesh.indexCount()];
                mesh.copyVertices(vs, 0);
                mesh.copyIndices(is, 0);
                ByteBuffer mb = ByteBuffer.allocate(4 * (vs.length + is.length));
                mb.asFloatBuffer().put(vs);
                mb.position(4 * vs.length);
                mb.asIntBuffer().put(is);
                md.update(mb.clear());
            }
        }
        for (int p = 0; p < w.plantCount(); p++) {
            md.update(b.clear().putFloat(w.plantX(p)).putFloat(w.plantY(p)).putFloat(w.plantZ(p))
                    .putFloat(w.plantRestAzimuth(p)).putInt(w.plantSpecies(p)).putInt(w.plantVariant(p)).flip());
        }
        return HexFormat.of().formatHex(md.digest(), 0, 16);
    }
}
