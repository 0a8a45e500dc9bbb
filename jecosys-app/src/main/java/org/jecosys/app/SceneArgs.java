package org.jecosys.app;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.SceneLoadException;
import org.jecosys.scene.SceneProblem;
import org.jecosys.terrain.ImageSource;

/** Resolves and loads the scene named on a command line, printing problems as FILE:LINE:COL. */
final class SceneArgs {
    /** The default scene, relative to the working folder or to the installation ({@code jecosys.home}). */
    static final String DEFAULT_SCENE = "scenes/meadow.xml";

    private SceneArgs() {
    }

    /** A path as given if it exists, else relative to {@code -Djecosys.home} (set by the launcher). */
    static Path resolve(String given) {
        Path p = Path.of(given);
        if (Files.exists(p) || p.isAbsolute()) {
            return p;
        }
        String home = System.getProperty("jecosys.home");
        if (home != null && Files.exists(Path.of(home).resolve(given))) {
            return Path.of(home).resolve(given);
        }
        return p;
    }

    /**
     * Loads the scene with its images read once from {@code images}, or prints every problem to
     * {@code err} and returns null.
     */
    static Scene load(Path file, ImageSource images, PrintWriter err) {
        try {
            return SceneFiles.read(file, images);
        } catch (SceneLoadException e) {
            for (SceneProblem p : e.problems()) {
                err.println(p);
            }
            err.flush();
            return null;
        }
    }
}
