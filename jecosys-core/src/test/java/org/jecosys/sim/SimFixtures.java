package org.jecosys.sim;

import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;

/**
 * Shared small scene for the simulation tests, built once per JVM: a frozen copy of the paper's C1
 * (src/test/resources/org/jecosys/sim/c1-fixture.xml), so that tuning scenes/c1.xml never changes
 * the golden state hashes.
 */
final class SimFixtures {
    /** Small chunks, so that C1's 1460 components make several. */
    static final int CHUNK = 200;
    private static SceneDef scene;
    private static World world;

    private SimFixtures() {
    }

    static synchronized SceneDef scene() throws Exception {
        if (scene == null) {
            scene = SceneFiles.parse(Path.of("jecosys-core/src/test/resources/org/jecosys/sim/c1-fixture.xml"));
        }
        return scene;
    }

    static synchronized World world() throws Exception {
        if (world == null) {
            world = World.build(scene().simulationDef(), Path.of("scenes"), 2, Progress.NONE);
        }
        return world;
    }

    static Simulation c1(int workers) throws Exception {
        return Simulation.of(world(), scene().simulationDef(), workers, CHUNK);
    }

    private static SceneDef turbulentScene;
    private static World turbulentWorld;

    /** C1's plants in a turbulent, travelling wind with a vortex, and plants varying in response. */
    static synchronized Simulation turbulent(int workers) throws Exception {
        if (turbulentScene == null) {
            turbulentScene = SceneFiles.parse(Path.of("jecosys-core/src/test/resources/org/jecosys/sim/"
                    + "turbulent-fixture.xml"));
            turbulentWorld = World.build(turbulentScene.simulationDef(), Path.of("scenes"), 2, Progress.NONE);
        }
        return Simulation.of(turbulentWorld, turbulentScene.simulationDef(), workers, CHUNK);
    }

    /** The scene's start camera. */
    static ViewCamera camera() throws Exception {
        return ViewCamera.of(scene().camera(), world().terrain().heightfield().height(0, 14), 16.0 / 9);
    }
}
