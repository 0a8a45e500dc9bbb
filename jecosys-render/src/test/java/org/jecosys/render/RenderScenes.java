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

    public static World build(SceneDef def) {
        try {
            return World.build(def.simulationDef(), Path.of("scenes"), 2, Progress.NONE);
        } catch (Exception e) {
            throw new IllegalStateException("cannot build " + def.name(), e);
        }
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
