package com.example.jmemeadow;

import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer.Type;
import com.jme3.util.BufferUtils;
import org.jecosys.terrain.Heightfield;

/** The game's own ground: a jME mesh of the scene's heightfield, so the plants stand on it. */
final class GroundMesh {
    private GroundMesh() {
    }

    /**
     * A triangle grid over the heightfield with its normals (at most 256 cells a side). Allocates.
     *
     * @param terrain the scene's heightfield (metres, Y up)
     * @return the mesh
     */
    static Mesh of(Heightfield terrain) {
        int res = terrain.resolution();
        int step = Math.max(1, (res - 1 + 255) / 256);
        int n = (res - 1) / step + 1;
        float[] normals = terrain.copyNormals(new float[3 * res * res]);
        float[] pos = new float[3 * n * n];
        float[] nor = new float[3 * n * n];
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int vi = Math.min(i * step, res - 1);
                int vj = Math.min(j * step, res - 1);
                int k = 3 * (j * n + i);
                int src = 3 * (vj * res + vi);
                pos[k] = (float) (terrain.minX() + vi * terrain.cellX());
                pos[k + 1] = terrain.vertexHeight(vi, vj);
                pos[k + 2] = (float) (terrain.minZ() + vj * terrain.cellZ());
                nor[k] = normals[src];
                nor[k + 1] = normals[src + 1];
                nor[k + 2] = normals[src + 2];
            }
        }
        int[] index = new int[6 * (n - 1) * (n - 1)];
        int t = 0;
        for (int j = 0; j + 1 < n; j++) {
            for (int i = 0; i + 1 < n; i++) {
                int a = j * n + i;
                int below = a + n;
                // counter-clockwise seen from above (+Y): jME culls back faces
                index[t++] = a;
                index[t++] = below;
                index[t++] = below + 1;
                index[t++] = a;
                index[t++] = below + 1;
                index[t++] = a + 1;
            }
        }
        Mesh mesh = new Mesh();
        mesh.setBuffer(Type.Position, 3, BufferUtils.createFloatBuffer(pos));
        mesh.setBuffer(Type.Normal, 3, BufferUtils.createFloatBuffer(nor));
        mesh.setBuffer(Type.Index, 3, BufferUtils.createIntBuffer(index));
        mesh.updateBound();
        return mesh;
    }
}
