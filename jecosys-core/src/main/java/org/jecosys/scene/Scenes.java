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
     * The open world of a scene with a {@code <world>} ({@link SceneDef#isOpenWorld()}): its species,
     * flows, field and animation, its distributions placed tile by tile on its hills
     * ({@link org.jecosys.world.WorldDef#placer}), tiles within its radius of the views. No tile exists
     * before the first steps. Build time; allocates; any thread.
     *
     * @param scene       a checked scene with a {@code <world>}
     * @param workers     animation workers, in [1, 256]
     * @param tileWorkers threads that build tiles, in [1, 64]
     * @return the open world; the caller closes it
     * @throws IllegalArgumentException when the scene has no {@code <world>} or an argument is out of range
     */
    public static org.jecosys.sim.OpenWorld openWorld(SceneDef scene, int workers, int tileWorkers) {
        return openWorld(scene, workers, tileWorkers, org.jecosys.plant.PlantTextures.NONE);
    }

    /**
     * As {@link #openWorld(SceneDef, int, int)}, with the images a loaded scene names drawn on its
     * components ({@code <component texture>}), read from the very bytes the scene was checked with.
     * Build time; allocates; any thread.
     *
     * @param scene       a loaded scene with a {@code <world>}
     * @param workers     animation workers, in [1, 256]
     * @param tileWorkers threads that build tiles, in [1, 64]
     * @return the open world; the caller closes it
     * @throws IOException              when an image cannot be decoded
     * @throws IllegalArgumentException when the scene has no {@code <world>} or an argument is out of range
     */
    public static org.jecosys.sim.OpenWorld openWorld(Scene scene, int workers, int tileWorkers) throws IOException {
        return openWorld(scene.def(), workers, tileWorkers,
                org.jecosys.plant.PlantTextures.load(scene.def().species(), scene.images()::read));
    }

    private static org.jecosys.sim.OpenWorld openWorld(SceneDef scene, int workers, int tileWorkers,
                                                       org.jecosys.plant.PlantTextures textures) {
        if (!scene.isOpenWorld()) {
            throw new IllegalArgumentException("scene '" + scene.name() + "' has no <world>: it is one square, built "
                    + "whole (Scenes.simulation)");
        }
        int[] speciesOf = new int[scene.distributions().size()];
        for (int k = 0; k < speciesOf.length; k++) {
            speciesOf[k] = scene.species().indexOf(scene.speciesById(scene.distributions().get(k).species()));
        }
        org.jecosys.world.TilePlacer placer = scene.world().placer(scene.seed(), scene.distributions(), speciesOf);
        return org.jecosys.sim.OpenWorld.create(scene.simulationDef(), placer, scene.world().radius(), workers,
                tileWorkers, 4, textures);
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
