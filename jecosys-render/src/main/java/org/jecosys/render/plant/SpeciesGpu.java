package org.jecosys.render.plant;

import static org.lwjgl.opengl.GL30C.GL_RGBA32F;

import java.util.ArrayList;
import java.util.List;
import org.jecosys.plant.PlantModel;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.render.gl.Closing;
import org.jecosys.render.gl.GlBufferTexture;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlVertexArray;

/**
 * The GL objects of one plant model that do not depend on where its plants stand: every pose table in
 * one buffer texture ({@link PlantMeshes#poseTexelLayout}) and one mesh per species and level. The
 * renderers of worlds that share the model (an open world's tiles) and take one {@link PlantPrograms}
 * read these instead of uploading their own: a tile's renderer then costs its own plants' data only,
 * and the model's tables sit once in GPU memory however many tiles are live. Render thread; the
 * constructor allocates and deletes what it made when it fails part way; {@link #close()} deletes
 * everything, after every renderer reading it.
 */
final class SpeciesGpu implements AutoCloseable {
    /** The model these objects were made for. */
    final PlantModel model;
    /** First texel of each pose table, [species][component][variant]. */
    final int[][][] poseTexel;
    /** The pose tables' texels in all. */
    final long texels;
    /** The pose tables as one buffer texture. */
    final GlBufferTexture poseTexture;
    /** The mesh of each species and level, [species][level]. */
    private final GlVertexArray[][] meshes;
    private final List<AutoCloseable> owned = new ArrayList<>();

    SpeciesGpu(GlTracker tracker, PlantModel model) {
        this.model = model;
        List<SpeciesModel> models = model.species();
        poseTexel = new int[models.size()][][];
        texels = PlantMeshes.poseTexelLayout(models, poseTexel);
        meshes = new GlVertexArray[models.size()][];
        try {
            poseTexture = own(new GlBufferTexture(tracker, own(PlantMeshes.uploadPoses(tracker, models, texels)),
                    GL_RGBA32F));
            for (int s = 0; s < models.size(); s++) {
                SpeciesModel m = models.get(s);
                int[] layers = PlantMeshes.layers(model.textures(), s, m);
                meshes[s] = new GlVertexArray[m.levels()];
                for (int l = 0; l < m.levels(); l++) {
                    meshes[s][l] = PlantMeshes.uploadMesh(tracker, m, m.mesh(l), layers, owned);
                }
            }
        } catch (RuntimeException | Error e) {
            close();
            throw e;
        }
    }

    private <T extends AutoCloseable> T own(T resource) {
        owned.add(resource);
        return resource;
    }

    /** {@return the mesh of species {@code s} at level {@code level}} No allocation. */
    GlVertexArray mesh(int s, int level) {
        return meshes[s][level];
    }

    /** Deletes the tables and meshes. Render thread; idempotent. */
    @Override
    public void close() {
        Closing.closeReverse(owned);
        owned.clear();
    }
}
