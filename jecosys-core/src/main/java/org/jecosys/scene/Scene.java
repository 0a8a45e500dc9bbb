package org.jecosys.scene;

import org.jecosys.math.Require;
import org.jecosys.terrain.ImageSource;

/**
 * A scene loaded and checked: its definition and the images it names, held as the very bytes that
 * were checked (size, memory budget, decodability) when it was loaded, so that building it never
 * reads a file again (a file replaced on disk in between cannot matter). Made by
 * {@link SceneFiles#read(java.nio.file.Path)} and its stream and resolver variants; built by
 * {@link Scenes#simulation(Scene, int, org.jecosys.math.Progress)} or
 * {@code Simulation.create(scene.def().simulationDef(), scene.images(), ...)}. Immutable; any thread.
 *
 * @param def    the scene's definition
 * @param name   the name its problems were reported under (the file's path as given, or the
 *               stream's name)
 * @param images the images the scene names, by the path it writes (empty when it names none)
 */
public record Scene(SceneDef def, String name, ImageSource images) {
    /**
     * Checks the components.
     *
     * @param def    not null
     * @param name   not null
     * @param images not null
     */
    public Scene {
        Require.nonNull("def", def);
        Require.nonNull("name", name);
        Require.nonNull("images", images);
    }
}
