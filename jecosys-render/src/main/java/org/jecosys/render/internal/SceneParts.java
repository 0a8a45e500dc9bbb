package org.jecosys.render.internal;

import org.jecosys.render.SceneRenderer;
import org.jecosys.render.ground.CoverBlades;
import org.jecosys.render.ground.TerrainRenderer;
import org.jecosys.render.overlay.FieldOverlay;
import org.jecosys.render.plant.PlantRenderer;

/**
 * Internal: the renderers a {@link SceneRenderer} composes, for the application's benchmark and the
 * tests (the API shows statistics, not parts). {@code SceneRenderer} grants the access once, when its
 * class is initialised, so these work for any renderer there is. Render thread, like the renderer.
 */
public final class SceneParts {
    /** What {@link SceneRenderer} hands over; implemented by the renderer itself. */
    public interface Access {
        /**
         * @param r the renderer
         * @return its plant renderer
         */
        PlantRenderer plants(SceneRenderer r);

        /**
         * @param r the renderer
         * @return its terrain renderer
         */
        TerrainRenderer terrain(SceneRenderer r);

        /**
         * @param r the renderer
         * @return its near ground-cover renderer
         */
        CoverBlades cover(SceneRenderer r);

        /**
         * @param r the renderer
         * @return its force-field overlay renderer
         */
        FieldOverlay overlay(SceneRenderer r);
    }

    private static volatile Access access;

    private SceneParts() {
    }

    /**
     * Called once by {@link SceneRenderer}'s class initialiser.
     *
     * @param a the renderer's access
     * @throws IllegalStateException on a second call
     */
    public static synchronized void grant(Access a) {
        if (access != null) {
            throw new IllegalStateException("SceneRenderer's access is granted once");
        }
        access = a;
    }

    /**
     * @param r the renderer
     * @return its plant renderer (its batches hold the per-frame counters)
     */
    public static PlantRenderer plants(SceneRenderer r) {
        return access(r).plants(r);
    }

    /**
     * @param r the renderer
     * @return its terrain renderer
     */
    public static TerrainRenderer terrain(SceneRenderer r) {
        return access(r).terrain(r);
    }

    /**
     * @param r the renderer
     * @return its near ground-cover renderer (tiles and blades of the last frame)
     */
    public static CoverBlades cover(SceneRenderer r) {
        return access(r).cover(r);
    }

    /**
     * @param r the renderer
     * @return its overlay renderer
     */
    public static FieldOverlay overlay(SceneRenderer r) {
        return access(r).overlay(r);
    }

    private static Access access(SceneRenderer r) {
        if (r == null) {
            throw new NullPointerException("renderer");
        }
        return access;
    }
}
