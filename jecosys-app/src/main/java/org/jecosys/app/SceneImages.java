package org.jecosys.app;

import java.nio.file.Path;
import org.jecosys.scene.Scenes;
import org.jecosys.terrain.ImageSource;
import picocli.CommandLine.Option;

/**
 * The {@code --allow-outside-images} flag of the commands that load a scene: by default the images a
 * scene names must lie in its folder's tree (after links), so a scene from someone else cannot read
 * other files of the user's; the flag lifts that for scenes the user trusts.
 */
final class SceneImages {
    @Option(names = "--allow-outside-images", description = "Let the scene read images outside its folder "
            + "(absolute paths, '..', links out of it). Off by default: only for scene files you trust.")
    boolean allowOutside;

    /** {@return where the images of scene {@code file} are read from} */
    ImageSource of(Path file) {
        Path dir = Scenes.baseDir(file);
        return allowOutside ? ImageSource.anywhere(dir) : ImageSource.folder(dir);
    }

    /** {@return where the images of scene {@code file} are read from, each read recorded as an input of {@code plan}} */
    ImageSource of(Path file, OutputPlan plan) {
        return plan.images(of(file), Scenes.baseDir(file));
    }
}
