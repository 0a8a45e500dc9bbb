package org.jecosys.scene;

import java.io.IOException;
import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.math.Require;
import org.jecosys.sim.Simulation;

/**
 * Builds runtime objects from scene files (the sim package cannot read scene files itself).
 * Build time; allocates; any thread.
 */
public final class Scenes {
    private Scenes() {
    }

    /**
     * Loads a scene file and builds its simulation with the scene's worker count; relative image
     * paths resolve against the file's folder.
     *
     * @param file     the scene file
     * @param progress told the progress of each generation step, on the calling thread
     * @return a new simulation; the caller closes it
     * @throws SceneLoadException when the file is not a valid scene
     * @throws IOException        when an image it names cannot be read
     */
    public static Simulation simulation(Path file, Progress progress) throws SceneLoadException, IOException {
        return simulation(SceneFiles.read(Require.nonNull("file", file)), 0, progress);
    }

    /**
     * Builds the simulation of a loaded scene from the images it was checked with (no file is read
     * again), with the scene's LOD transition band.
     *
     * @param scene    a scene from {@link SceneFiles#read(Path)} or its stream variant
     * @param workers  animation workers, in [0, 256]; 0 keeps the scene's setting (whose 0 means the
     *                 available processors)
     * @param progress told the progress of each generation step, on the calling thread
     * @return a new simulation; the caller closes it
     * @throws IOException when an image cannot be decoded
     */
    public static Simulation simulation(Scene scene, int workers, Progress progress) throws IOException {
        Require.nonNull("scene", scene);
        SceneDef def = scene.def();
        Simulation sim = Simulation.create(def.simulationDef(), scene.images(), workers, progress);
        sim.setLodTransition(def.render().lodTransition());
        return sim;
    }

    /**
     * The folder relative paths of {@code file} resolve against.
     *
     * @param file a scene file
     * @return its absolute parent folder, or {@code .} when it has none
     */
    public static Path baseDir(Path file) {
        Path parent = file.toAbsolutePath().getParent();
        return parent == null ? Path.of(".") : parent;
    }
}
