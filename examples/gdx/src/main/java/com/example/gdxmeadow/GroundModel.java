package com.example.gdxmeadow;

import com.badlogic.gdx.graphics.Color;
import com.badlogic.gdx.graphics.GL20;
import com.badlogic.gdx.graphics.VertexAttributes.Usage;
import com.badlogic.gdx.graphics.g3d.Material;
import com.badlogic.gdx.graphics.g3d.Model;
import com.badlogic.gdx.graphics.g3d.attributes.ColorAttribute;
import com.badlogic.gdx.graphics.g3d.utils.MeshPartBuilder;
import com.badlogic.gdx.graphics.g3d.utils.MeshPartBuilder.VertexInfo;
import com.badlogic.gdx.graphics.g3d.utils.ModelBuilder;
import org.jecosys.terrain.Heightfield;

/** The game's own ground: a libGDX model of the scene's heightfield, so the plants stand on it. */
final class GroundModel {
    /** The ground's diffuse colour: dry brown soil. */
    static final Color SOIL = new Color(0.50f, 0.36f, 0.22f, 1f);

    private GroundModel() {
    }

    /**
     * A lit triangle grid over the heightfield (at most 128 cells a side). Render thread; allocates.
     *
     * @param terrain the scene's heightfield (metres, Y up)
     * @return the model; the caller disposes it
     */
    static Model of(Heightfield terrain) {
        int res = terrain.resolution();
        int step = Math.max(1, (res - 1 + 127) / 128);
        int n = (res - 1) / step + 1;
        ModelBuilder mb = new ModelBuilder();
        mb.begin();
        MeshPartBuilder b = mb.part("ground", GL20.GL_TRIANGLES, Usage.Position | Usage.Normal,
                new Material(ColorAttribute.createDiffuse(SOIL)));
        b.ensureCapacity(n * n, 6 * (n - 1) * (n - 1));
        float[] normals = terrain.copyNormals(new float[3 * res * res]);
        VertexInfo v = new VertexInfo();
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int vi = Math.min(i * step, res - 1);
                int vj = Math.min(j * step, res - 1);
                int k = 3 * (vj * res + vi);
                float x = (float) (terrain.minX() + vi * terrain.cellX());
                float z = (float) (terrain.minZ() + vj * terrain.cellZ());
                b.vertex(v.setPos(x, terrain.vertexHeight(vi, vj), z).setNor(normals[k], normals[k + 1], normals[k + 2]));
            }
        }
        for (int j = 0; j + 1 < n; j++) {
            for (int i = 0; i + 1 < n; i++) {
                short a = (short) (j * n + i);
                short below = (short) ((j + 1) * n + i);
                // counter-clockwise seen from above (+Y): ModelBatch culls back faces
                b.triangle(a, below, (short) (below + 1));
                b.triangle(a, (short) (below + 1), (short) (a + 1));
            }
        }
        return mb.end();
    }
}
