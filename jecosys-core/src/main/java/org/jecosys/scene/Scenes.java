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
        Require.nonNull("file", file);
        SceneDef def = SceneFiles.load(file);
        Simulation sim = Simulation.create(def.simulationDef(), baseDir(file), progress);
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
