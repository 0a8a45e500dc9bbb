package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 40: a glTF leaf bound along the skeleton matches the procedural strip's pose at every pose of
 * the table (the issue asks 1 cm; here within 1 mm, bent and twisted); a rigid mesh rides the tip along the
 * last segment. The placement is {@link ComponentMesh#place}, the CPU twin of the plant shader's.
 */
class MeshBindingTest {
    static final int SEGMENTS = 6;

    @TempDir
    Path dir;

    private static String component(String id, String extra) {
        return "<component id=\"" + id + "\" type=\"leaf\" segments=\"" + SEGMENTS + "\" length=\"0.3\" "
                + "baseWidth=\"0.02\" tipWidth=\"0.008\" curvature=\"30\" twist=\"25\" mass=\"0.0004\" stiffness=\"0.2\" "
                + "lodSegments=\"" + SEGMENTS + "\" " + extra + "/>";
    }

    private World world(String leafExtra) throws Exception {
        Path file = dir.resolve("scene.xml");
        Files.writeString(file, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<scene version=\"1\">\n"
                + "<terrain sizeX=\"4\" sizeZ=\"4\" resolution=\"17\"/>\n"
                + "<species id=\"strip\" poses=\"8\"><lod/>" + component("leaf", "") + "</species>\n"
                + "<species id=\"mesh\" poses=\"8\"><lod/>" + component("leaf", leafExtra) + "</species>\n"
                + "<plant species=\"strip\" x=\"0\" z=\"0\"/><plant species=\"mesh\" x=\"1\" z=\"0\"/>\n</scene>\n",
                StandardCharsets.UTF_8);
        Scene s = SceneFiles.read(file);
        return World.build(s.def().simulationDef(), s.images(), 1, Progress.NONE);
    }

    @Test
    void aBoundLeafFollowsTheStripAtEveryPose() throws Exception {
        // the strip's outline at rest, in mesh units (height 2: the binding scales it to the length, 0.3 m)
        World probe = world("");
        PoseTable strip = probe.plants().species().get(0).component(0).poseTable(0);
        double k = 0.3 / 2;
        float[] pos = new float[3 * 2 * (SEGMENTS + 1)];
        int[] idx = new int[6 * SEGMENTS];
        for (int i = 0; i <= SEGMENTS; i++) {
            int r = strip.offset(0, i);
            double hw = Math.sqrt(sq(strip.get(r + 3)) + sq(strip.get(r + 4)) + sq(strip.get(r + 5)));
            for (int side = 0; side < 2; side++) {
                int v = 2 * i + side;
                pos[3 * v] = (float) ((side == 0 ? -hw : hw) / k);
                pos[3 * v + 1] = (float) (2.0 * i / SEGMENTS);
            }
        }
        for (int i = 0; i < SEGMENTS; i++) {
            int[] q = {2 * i, 2 * i + 1, 2 * i + 3, 2 * i, 2 * i + 3, 2 * i + 2};
            System.arraycopy(q, 0, idx, 6 * i, 6);
        }
        Files.write(dir.resolve("leaf.glb"), GltfWriter.glb(new MeshGeometry(pos, null, null, idx)));
        World w = world("mesh=\"leaf.glb\"");
        PlantComponent stripLeaf = w.plants().species().get(0).component(0);
        PlantComponent meshLeaf = w.plants().species().get(1).component(0);
        PoseTable table = meshLeaf.poseTable(0);
        ComponentMesh mesh = meshLeaf.mesh(0);
        assertTrue(mesh.fromFile(), "the file's mesh at the level that uses all segments");
        float[] out = new float[3];
        double worst = 0;
        double tipTravel = 0;
        for (int pose = 0; pose < table.poses(); pose++) {
            for (int v = 0; v < mesh.vertexCount(); v++) {
                mesh.place(table, pose, v, out);
                int point = Math.round(mesh.meshValue(v, ComponentMesh.MESH_POINT));
                int r = stripLeaf.poseTable(0).offset(pose, point);
                PoseTable st = stripLeaf.poseTable(0);
                double a = mesh.vertexA(v) > 0 ? 1 : -1;
                double d = 0;
                for (int c = 0; c < 3; c++) {
                    d += sq(out[c] - (st.get(r + c) + a * st.get(r + 3 + c)));
                }
                worst = Math.max(worst, Math.sqrt(d));
            }
            int tip = table.offset(pose, SEGMENTS);
            tipTravel = Math.max(tipTravel, Math.abs(table.get(tip) - table.get(table.offset(0, SEGMENTS))));
        }
        System.out.printf("[mesh] bound leaf vs strip over %d poses: worst %.5f m (tip travels %.3f m)%n",
                table.poses(), worst, tipTravel);
        assertTrue(tipTravel > 0.05, "the poses bend the leaf: " + tipTravel);
        // the issue asks 1 cm; the side made normal to the segment under twist moves an edge by 0.3 mm
        assertTrue(worst <= 1e-3, "within 1 mm of the strip at every pose: " + worst);
    }

    @Test
    void aRigidMeshRidesTheTipAlongTheLastSegment() throws Exception {
        float[] pos = {0, 0, 0, 0.5f, 0, 0, 0, 1, 0, 0, 0, 1};
        Files.write(dir.resolve("head.glb"), GltfWriter.glb(new MeshGeometry(pos, null, null, new int[] {0, 1, 2, 0, 2, 3})));
        World w = world("mesh=\"head.glb\" meshMode=\"rigid\" meshScale=\"0.02\"");
        PlantComponent leaf = w.plants().species().get(1).component(0);
        PoseTable t = leaf.poseTable(0);
        ComponentMesh mesh = leaf.mesh(0);
        float[] o = new float[3];
        float[] up = new float[3];
        for (int pose = 0; pose < t.poses(); pose++) {
            mesh.place(t, pose, 0, o);
            mesh.place(t, pose, 2, up);
            int tip = t.offset(pose, SEGMENTS);
            int before = t.offset(pose, SEGMENTS - 1);
            double len = 0;
            double dot = 0;
            double seg = Math.sqrt(sq(t.get(tip) - t.get(before)) + sq(t.get(tip + 1) - t.get(before + 1))
                    + sq(t.get(tip + 2) - t.get(before + 2)));
            for (int c = 0; c < 3; c++) {
                assertEquals(t.get(tip + c), o[c], 1e-6, "the origin on the tip, pose " + pose);
                len += sq(up[c] - o[c]);
                dot += (up[c] - o[c]) * (t.get(tip + c) - t.get(before + c)) / seg;
            }
            assertEquals(0.02, Math.sqrt(len), 1e-6, "+Y scaled to 2 cm");
            assertEquals(0.02, dot, 1e-6, "+Y along the last segment, pose " + pose);
        }
    }

    private static double sq(double x) {
        return x * x;
    }
}
