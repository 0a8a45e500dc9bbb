package org.jecosys.scene;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.sim.Simulation;

/**
 * Run in a child JVM at -Xmx512m by {@link ImagesReliabilityTest}: loads a scene whose heightmap is
 * small, replaces the heightmap by an 8192 x 8192 image, then builds the scene twice: from the bytes
 * checked at load ({@link Scenes#simulation(Scene, int, Progress)}), and through the API that reads the
 * folder again ({@code Simulation.create(def, dir, ...)}). Prints one line per build; exits 3 on an
 * OutOfMemoryError.
 */
public final class SwappedImageMain {
    private SwappedImageMain() {
    }

    public static void main(String[] args) throws Exception {
        Path file = Path.of(args[0]);
        Scene scene = SceneFiles.read(file);
        Path heightmap = Scenes.baseDir(file).resolve(scene.def().terrain().heightmap());
        Files.write(heightmap, Pngs.grey(8192, 8192, 255)); // swapped between load and build
        try {
            try (Simulation sim = Scenes.simulation(scene, 1, Progress.NONE)) {
                System.out.println("checked bytes: built, height " + sim.world().terrain().heightfield().height(0, 0));
            }
            try (Simulation sim = Simulation.create(scene.def().simulationDef(), Scenes.baseDir(file), 1, Progress.NONE)) {
                System.out.println("folder again: built, height " + sim.world().terrain().heightfield().height(0, 0));
            } catch (IOException e) {
                System.out.println("folder again: refused: " + e.getMessage());
            }
        } catch (OutOfMemoryError e) {
            System.out.println("OutOfMemoryError");
            System.exit(3);
        }
    }
}
