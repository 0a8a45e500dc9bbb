package org.jecosys.render;

import org.jecosys.render.ground.CoverBlades;
import org.jecosys.render.ground.TerrainRenderer;
import org.jecosys.render.internal.SceneParts;
import org.jecosys.render.overlay.FieldOverlay;
import org.jecosys.render.plant.PlantRenderer;

/**
 * The access to a {@link SceneRenderer}'s parts that it grants {@link SceneParts} once, when its class
 * is initialised (for the application's benchmark and the tests): each part as the renderer's own
 * package-private accessor returns it. Render thread, like the renderer; no allocation.
 */
final class ScenePartsAccess implements SceneParts.Access {
    @Override
    public PlantRenderer plants(SceneRenderer r) {
        return r.plants();
    }

    @Override
    public TerrainRenderer terrain(SceneRenderer r) {
        return r.terrain();
    }

    @Override
    public CoverBlades cover(SceneRenderer r) {
        return r.cover();
    }

    @Override
    public FieldOverlay overlay(SceneRenderer r) {
        return r.overlay();
    }
}
