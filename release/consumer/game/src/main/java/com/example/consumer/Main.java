package com.example.consumer;

import java.io.InputStream;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.SceneRenderer;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.terrain.ImageSource;

/**
 * What a game does with a released JEcoSys, without a window: reads the scene it ships as a class-path
 * resource, builds its simulation, steps it one second and checks that the plants moved. It also
 * loads {@link SceneRenderer} (as {@link PlantView} uses it) and says where both jars came from.
 *
 * <p>Optional system properties, set by release/check.sh: {@code jecosys.expectedVersion}, the
 * version both jars must carry in their manifest, and {@code jecosys.expectedRepository}, the folder
 * both jars must lie in (the check's fresh local repository). Exits with 1 when a check fails.
 */
public final class Main {
    private static final int STEPS = 60;

    private Main() {
    }

    public static void main(String[] args) throws Exception {
        Scene scene;
        try (InputStream in = Main.class.getResourceAsStream("/patch.xml")) {
            if (in == null) {
                throw new IllegalStateException("patch.xml is not on the class path");
            }
            scene = SceneFiles.read(in, "patch.xml", ImageSource.NONE);
        }
        // the game's camera: 1.5 m up at the patch's edge, looking over it
        ViewCamera camera = new ViewCamera();
        camera.setPosition(0, 1.5, -7);
        camera.setOrientation(Math.PI, -0.2);
        camera.setLens(Math.toRadians(50), 16.0 / 9, 0.1, 200);
        try (Simulation sim = Scenes.simulation(scene, 2, Progress.NONE)) {
            long before = sim.inspect().stateHash();
            for (int i = 0; i < STEPS; i++) {
                sim.stepFixed(camera);
            }
            Frame frame = sim.latestFrame();
            System.out.printf("consumer: %s, %d plants, %d components, %d steps (%.2f s), state hash %016x%n",
                    scene.def().name(), sim.plantCount(), sim.componentCount(), sim.inspect().steps(),
                    sim.inspect().time(), sim.inspect().stateHash());
            check(sim.plantCount() > 0, "the scene has plants");
            check(sim.inspect().steps() == STEPS, "the simulation ran " + STEPS + " fixed steps");
            check(frame != null, "a frame was published");
            check(sim.inspect().stateHash() != before, "the wind moved the plants");
        }
        checkJar("jecosys-core", Simulation.class);
        checkJar("jecosys-render", SceneRenderer.class);
        System.out.println("consumer: ok");
    }

    private static void checkJar(String module, Class<?> type) throws URISyntaxException {
        String version = type.getPackage().getImplementationVersion();
        URL jar = type.getProtectionDomain().getCodeSource().getLocation();
        System.out.println("consumer: " + module + " " + version + " from " + jar);
        String expectedVersion = System.getProperty("jecosys.expectedVersion");
        if (expectedVersion != null) {
            check(expectedVersion.equals(version), module + " is version " + expectedVersion + ", not " + version);
        }
        String expectedRepository = System.getProperty("jecosys.expectedRepository");
        if (expectedRepository != null) {
            check(Path.of(jar.toURI()).startsWith(Path.of(expectedRepository)), module + " comes from " + expectedRepository);
        }
    }

    private static void check(boolean ok, String what) {
        if (!ok) {
            System.err.println("consumer: FAILED: " + what);
            System.exit(1);
        }
    }
}
