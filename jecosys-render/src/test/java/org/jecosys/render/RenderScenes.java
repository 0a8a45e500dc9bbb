package org.jecosys.render;

import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.World;

/** Scenes for rendering tests: loaded and built once per test class. */
public final class RenderScenes {
    private RenderScenes() {
    }

    public static SceneDef load(String name) {
        try {
            return SceneFiles.parse(Path.of("scenes", name));
        } catch (Exception e) {
            throw new IllegalStateException("cannot load scenes/" + name, e);
        }
    }

    /**
     * The world of a scene, built once per test JVM and shared by the test classes that draw it (a
     * {@code World} is immutable; the meadow takes seconds to build, and a dozen classes draw it). The
     * last few worlds built are kept.
     */
    public static World build(SceneDef def) {
        synchronized (BUILT) {
            World w = BUILT.get(def);
            if (w != null) {
                return w;
            }
        }
        try {
            World w = World.build(def.simulationDef(), Path.of("scenes"), 2, Progress.NONE);
            synchronized (BUILT) {
                BUILT.put(def, w);
            }
            return w;
        } catch (Exception e) {
            throw new IllegalStateException("cannot build " + def.name(), e);
        }
    }

    /** The worlds built, by their scene: the last {@link #KEPT} (least recently used first out). */
    private static final int KEPT = 3;
    private static final java.util.Map<SceneDef, World> BUILT = new java.util.LinkedHashMap<>(8, 0.75f, true) {
        private static final long serialVersionUID = 1L;

        @Override
        protected boolean removeEldestEntry(java.util.Map.Entry<SceneDef, World> eldest) {
            return size() > KEPT;
        }
    };

    /** The tile placer of an open-world scene ({@code <world>}): its distributions, each mapped to its species. */
    static org.jecosys.world.TilePlacer placer(SceneDef scene) {
        int[] speciesOf = new int[scene.distributions().size()];
        for (int k = 0; k < speciesOf.length; k++) {
            speciesOf[k] = scene.species().indexOf(scene.speciesById(scene.distributions().get(k).species()));
        }
        return scene.world().placer(scene.seed(), scene.distributions(), speciesOf);
    }

    static ViewCamera camera(SceneDef def, World world, int width, int height) {
        double ground = world.terrain().heightfield().height(def.camera().x(), def.camera().z());
        return ViewCamera.of(def.camera(), ground, width / (double) height);
    }

    /** The render settings a scene file asks for (the app's HeadlessRender.settings, for the look tests). */
    static RenderSettings settings(SceneDef def) {
        RenderSettings s = RenderSettings.of(def);
        s.setClear(true);
        s.setTerrain(true);
        return s;
    }
}
