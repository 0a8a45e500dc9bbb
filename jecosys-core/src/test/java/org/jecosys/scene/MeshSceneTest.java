package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.GltfFiles;
import org.jecosys.plant.LodMesh;
import org.jecosys.plant.MeshGeometry;
import org.jecosys.plant.MeshMode;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code <component mesh meshMode meshScale>} (issue 40): a glTF mesh read through the scene's image
 * source, built where the component uses all its segments, saved back; every file the build could not
 * use is refused at the component's line and column, {@code check} included.
 */
class MeshSceneTest {
    static final float[] CARD = {-0.5f, 0, 0, 0.5f, 0, 0, 0.5f, 1, 0, -0.5f, 1, 0};
    static final float[] UV = {0, 1, 1, 1, 1, 0, 0, 0};
    static final int[] TWO = {0, 1, 2, 0, 2, 3};

    @TempDir
    Path dir;

    /** A scene whose one component has the attributes {@code extra}, on line 5; two levels (all 4 segments, then 2). */
    private Path scene(String extra) throws Exception {
        Path file = dir.resolve("s/scene.xml");
        Files.createDirectories(file.getParent());
        Files.writeString(file, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<scene version=\"1\">\n"
                + "  <terrain sizeX=\"4\" sizeZ=\"4\" resolution=\"17\"/>\n  <species id=\"grass\">\n"
                + "    <lod maxDistance=\"10\"/><lod/><component id=\"leaf\" type=\"leaf\" segments=\"4\" length=\"0.3\" "
                + "baseWidth=\"0.01\" " + extra + "\n"
                + "        mass=\"0.0004\" stiffness=\"0.2\" lodSegments=\"4 2\"/>\n  </species>\n"
                + "  <plant species=\"grass\" x=\"0\" z=\"0\"/>\n</scene>\n", StandardCharsets.UTF_8);
        return file;
    }

    private void write(String name, byte[] bytes) throws Exception {
        Path f = dir.resolve("s").resolve(name).normalize();
        Files.createDirectories(f.getParent());
        Files.write(f, bytes);
    }

    @Test
    void aMeshComponentLoadsBuildsAndSavesBack() throws Exception {
        write("meshes/card.gltf", GltfFiles.utf8(GltfFiles.json(CARD, null, UV, TWO, "card.bin", 4, true)));
        write("meshes/card.bin", GltfFiles.buffer(CARD, null, UV, TWO));
        Scene s = SceneFiles.read(scene("mesh=\"meshes/card.gltf\" meshMode=\"rigid\" meshScale=\"0.05\""));
        ComponentDef c = s.def().species().get(0).components().get(0);
        assertEquals("meshes/card.gltf", c.mesh().path());
        assertEquals(MeshMode.RIGID, c.mesh().mode());
        assertEquals(0.05, c.mesh().scale());
        World w = World.build(s.def().simulationDef(), s.images(), 1, Progress.NONE);
        LodMesh near = w.plants().species().get(0).mesh(0);
        LodMesh far = w.plants().species().get(0).mesh(1);
        assertEquals(4, near.vertexCount(), "the card's 4 vertices where the leaf uses all its segments");
        assertTrue(near.vertexFromFile(0));
        assertEquals(4f, near.meshValue(2, org.jecosys.plant.ComponentMesh.MESH_POINT), 0f, "rigid: at the tip");
        assertEquals(0.05f, near.meshValue(2, org.jecosys.plant.ComponentMesh.MESH_C), 1e-7f, "1 m up, scaled");
        assertTrue(!far.vertexFromFile(0), "the strip where it uses 2 of its 4 segments");
        String xml = SceneFiles.toXml(s.def());
        assertTrue(xml.contains("mesh=\"meshes/card.gltf\"") && xml.contains("meshMode=\"rigid\"")
                && xml.contains("meshScale=\"0.05\""), xml);
        Path again = dir.resolve("s/again.xml");
        Files.writeString(again, xml);
        assertEquals(s.def().species(), SceneFiles.parse(again).species(), "read back the same");
    }

    @Test
    void unusableMeshesAreRefusedAtTheComponentsLineAndColumn() throws Exception {
        write("nopos.gltf", GltfFiles.utf8(GltfFiles.json(CARD, null, null, TWO, null, 4, false)));
        write("lines.gltf", GltfFiles.utf8(GltfFiles.json(CARD, null, null, TWO, null, 1, true)));
        write("out.gltf", GltfFiles.utf8(GltfFiles.json(CARD, null, null, TWO, "../../b.bin", 4, true)));
        write("../b.bin", GltfFiles.buffer(CARD, null, null, TWO));
        write("notes.gltf", GltfFiles.utf8("{ not glTF"));
        write("flat.gltf", GltfFiles.utf8(GltfFiles.json(new float[] {0, 0, 0, 1, 0, 0, 0, 0, 1}, null, null,
                new int[] {0, 1, 2}, null, 4, true)));
        write("nouv.gltf", GltfFiles.utf8(GltfFiles.json(CARD, null, null, TWO, null, 4, true)));
        write("blade.png", pngBytes());
        int n = MeshGeometry.MAX_VERTICES + 3;
        float[] many = new float[3 * n];
        int[] seq = new int[n];
        for (int i = 0; i < n; i++) {
            many[3 * i] = i % 5;
            many[3 * i + 1] = i;
            seq[i] = i;
        }
        write("big.gltf", GltfFiles.utf8(GltfFiles.json(many, null, null, seq, null, 4, true)));
        String[][] refused = {
            {"mesh=\"missing.gltf\"", "missing.gltf"},
            {"mesh=\"notes.gltf\"", "not a"},
            {"mesh=\"nopos.gltf\"", "POSITION"},
            {"mesh=\"lines.gltf\"", "only triangle lists"},
            {"mesh=\"out.gltf\"", "leads out of the scene's folder"},
            {"mesh=\"../b.bin\"", "outside the scene's folder"},
            {"mesh=\"big.gltf\"", "at most " + MeshGeometry.MAX_VERTICES},
            {"mesh=\"flat.gltf\"", "no height along +Y"},
            {"mesh=\"nouv.gltf\" texture=\"blade.png\"", "no texture coordinates (TEXCOORD_0)"},
            {"meshMode=\"rigid\"", "no 'mesh'"},
        };
        for (String[] r : refused) {
            Path file = scene(r[0]);
            SceneLoadException e = assertThrows(SceneLoadException.class, () -> SceneFiles.read(file), r[0]);
            SceneProblem p = e.problems().get(0);
            assertEquals(5, p.line(), r[0] + ": " + p);
            assertTrue(p.column() > 1, r[0] + ": " + p);
            assertTrue(p.message().contains("mesh") && p.message().contains(r[1]), r[0] + ": " + p);
            assertTrue(e.getMessage().contains("scene.xml:5:"), r[0] + ": FILE:LINE:COL in " + e.getMessage());
        }
    }

    private static byte[] pngBytes() throws Exception {
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        javax.imageio.ImageIO.write(new java.awt.image.BufferedImage(8, 8, java.awt.image.BufferedImage.TYPE_INT_ARGB),
                "png", out);
        return out.toByteArray();
    }
}
