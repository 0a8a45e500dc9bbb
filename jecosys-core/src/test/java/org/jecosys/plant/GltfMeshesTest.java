package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The glTF reader: what it reads from .gltf (data URI and external buffers) and .glb, and each refusal. */
class GltfMeshesTest {
    static final float[] QUAD = {-0.5f, 0, 0, 0.5f, 0, 0, 0.5f, 1, 0, -0.5f, 1, 0};
    static final float[] UV = {0, 1, 1, 1, 1, 0, 0, 0};
    static final int[] TWO = {0, 1, 2, 0, 2, 3};

    private static PlantTextures.Files files(Map<String, byte[]> m) {
        return p -> {
            byte[] b = m.get(p);
            if (b == null) {
                throw new IOException("image '" + p + "': no such file");
            }
            return b;
        };
    }

    @Test
    void readsADataUriGltfWithUvsAndComputesNormals() throws IOException {
        Map<String, byte[]> m = Map.of("card.gltf", GltfFiles.utf8(GltfFiles.json(QUAD, null, UV, TWO, null, 4, true)));
        MeshGeometry g = GltfMeshes.read("card.gltf", files(m));
        assertEquals(4, g.vertexCount());
        assertEquals(2, g.triangleCount());
        assertTrue(g.hasUvs());
        assertEquals(1f, g.uv(2, 0), 0f);
        assertEquals(1f, g.position(2, 1), 0f);
        assertEquals(1f, Math.abs(g.normal(0, 2)), 1e-6f, "a quad in the XY plane faces along Z");
        assertEquals(0f, g.bound(1, false), 0f);
        assertEquals(1f, g.bound(1, true), 0f);
    }

    @Test
    void readsAnExternalBufferNextToTheFileInASubfolder() throws IOException {
        Map<String, byte[]> m = new HashMap<>();
        m.put("meshes/leaf.gltf", GltfFiles.utf8(GltfFiles.json(QUAD, null, null, TWO, "leaf%20data.bin", 4, true)));
        m.put("meshes/leaf data.bin", GltfFiles.buffer(QUAD, null, null, TWO));
        MeshGeometry g = GltfMeshes.read("meshes/leaf.gltf", files(m));
        assertEquals(4, g.vertexCount());
        assertFalse(g.hasUvs());
    }

    @Test
    void readsABinaryGlb() throws IOException {
        MeshGeometry g = GltfMeshes.read("head.glb", files(Map.of("head.glb", GltfWriter.glb(new MeshGeometry(QUAD, null, UV, TWO)))));
        assertEquals(4, g.vertexCount());
        assertEquals(2, g.triangleCount());
        assertEquals(0.5f, g.position(1, 0), 0f);
    }

    @Test
    void refusals() {
        Map<String, byte[]> m = new HashMap<>();
        m.put("garbage.gltf", GltfFiles.utf8("this is not JSON"));
        m.put("nopos.gltf", GltfFiles.utf8(GltfFiles.json(QUAD, null, null, TWO, null, 4, false)));
        m.put("strip.gltf", GltfFiles.utf8(GltfFiles.json(QUAD, null, null, TWO, null, 5, true)));
        m.put("out.gltf", GltfFiles.utf8(GltfFiles.json(QUAD, null, null, TWO, "../secret.bin", 4, true)));
        m.put("abs.gltf", GltfFiles.utf8(GltfFiles.json(QUAD, null, null, TWO, "/etc/passwd", 4, true)));
        m.put("url.gltf", GltfFiles.utf8(GltfFiles.json(QUAD, null, null, TWO, "http://example.com/b.bin", 4, true)));
        m.put("gone.gltf", GltfFiles.utf8(GltfFiles.json(QUAD, null, null, TWO, "gone.bin", 4, true)));
        int n = MeshGeometry.MAX_VERTICES + 3;
        float[] many = new float[3 * n];
        for (int i = 0; i < n; i++) {
            many[3 * i] = i % 7;
            many[3 * i + 1] = i / 7f;
        }
        int[] tri = new int[n];
        for (int i = 0; i < n; i++) {
            tri[i] = i;
        }
        m.put("big.gltf", GltfFiles.utf8(GltfFiles.json(many, null, null, tri, null, 4, true)));
        String[][] cases = {
            {"missing.gltf", "no such file"},
            {"garbage.gltf", "not a"},
            {"nopos.gltf", "without the POSITION attribute"},
            {"strip.gltf", "mode 5 (triangle strip); only triangle lists"},
            {"out.gltf", "leads out of the scene's folder"},
            {"abs.gltf", "absolute path"},
            {"url.gltf", "is a URL"},
            {"gone.gltf", "buffer 'gone.bin': image 'gone.bin': no such file"},
            {"big.gltf", n + " vertices; a component's mesh has at most " + MeshGeometry.MAX_VERTICES},
        };
        for (String[] c : cases) {
            IOException e = assertThrows(IOException.class, () -> GltfMeshes.read(c[0], files(m)), c[0]);
            assertTrue(e.getMessage().contains(c[1]), c[0] + ": " + e.getMessage());
            assertTrue(e.getMessage().contains(c[0]), c[0] + " named: " + e.getMessage());
        }
    }
}
