package org.jecosys.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.terrain.ResourceMapDef;
import org.jecosys.terrain.TerrainDef;

/**
 * Where and whether the viewer saves a scene, so that no file is lost: Save writes the open file,
 * Save As a new one; the write itself is {@link SceneFiles#save}'s (a temporary file in the target's
 * folder, forced to disk, moved over the target in one step). Before writing, {@link #plan} says
 * whether the user must confirm first, and why:
 * <ul>
 * <li>the target is a <em>shipped</em> scene: a file under the project's {@code scenes/} folder,
 *     which is part of JEcoSys (Save As elsewhere keeps it as it is);</li>
 * <li>the target exists and is not the open file (Save As over another file);</li>
 * <li>the open file changed on disk since it was opened or last saved (another program wrote it).</li>
 * </ul>
 * After a write the saved file becomes the open file. Relative paths inside the scene (heightmap,
 * map images) are rewritten for the new folder when Save As moves the scene to another one. No GL,
 * GLFW or ImGui here, so tests drive it headless. Render thread (one thread); allocates.
 */
final class SceneSaver {
    /**
     * What a save would do.
     *
     * @param target   the absolute, normalised file to write
     * @param confirm  whether the user must confirm first
     * @param question the reasons to confirm, one sentence each ("" when none)
     */
    record Plan(Path target, boolean confirm, String question) {
    }

    private final Path shipped;
    private Path file;
    private FileTime written;

    /**
     * A saver for the scene opened from {@code file}.
     *
     * @param file    the open scene file
     * @param shipped the project's {@code scenes/} folder (the shipped scenes), or null when unknown
     */
    SceneSaver(Path file, Path shipped) {
        this.file = file.toAbsolutePath().normalize();
        this.shipped = shipped == null ? null : real(shipped.toAbsolutePath().normalize());
        this.written = modified(this.file);
    }

    /**
     * The shipped scenes' folder: {@code scenes/} of the installation ({@code -Djecosys.home}, set by
     * the launcher), else of the working folder.
     *
     * @return the folder (it may not exist)
     */
    static Path shippedFolder() {
        String home = System.getProperty("jecosys.home");
        return (home == null ? Path.of("") : Path.of(home)).resolve("scenes").toAbsolutePath().normalize();
    }

    /** {@return the open scene file (absolute)} */
    Path file() {
        return file;
    }

    /**
     * Whether {@code target} is a shipped scene: under the shipped folder (symbolic links resolved).
     *
     * @param target a file path
     * @return true when saving there would change a scene that is part of the project
     */
    boolean isShipped(Path target) {
        if (shipped == null) {
            return false;
        }
        Path abs = target.toAbsolutePath().normalize();
        Path parent = abs.getParent();
        Path where = parent == null ? abs : real(parent).resolve(abs.getFileName());
        return where.startsWith(shipped);
    }

    /**
     * Plans a save to the open file (Save).
     *
     * @return the plan
     */
    Plan plan() {
        return plan(file);
    }

    /**
     * Plans a save to {@code target} (Save As, or Save when it is the open file).
     *
     * @param target the file to write
     * @return the plan: write at once, or confirm first and why
     * @throws IllegalArgumentException naming the target when it cannot be a scene file: a folder, in
     *                                  a folder that does not exist, or not named {@code *.xml}
     */
    Plan plan(Path target) {
        Path abs = target.toAbsolutePath().normalize();
        if (Files.isDirectory(abs)) {
            throw new IllegalArgumentException(target + " is a folder; give a file name ending in .xml");
        }
        Path parent = abs.getParent();
        if (parent == null || !Files.isDirectory(parent)) {
            throw new IllegalArgumentException("the folder " + parent + " of " + target + " does not exist");
        }
        if (!abs.getFileName().toString().endsWith(".xml")) {
            throw new IllegalArgumentException(target + ": scene files are named *.xml");
        }
        boolean same = abs.equals(file);
        boolean exists = Files.exists(abs, LinkOption.NOFOLLOW_LINKS);
        StringBuilder q = new StringBuilder();
        if (isShipped(abs)) {
            q.append(abs.getFileName()).append(exists ? " is a scene shipped with JEcoSys (in " : " would be a new "
                    + "scene among those shipped with JEcoSys (in ").append(shipped)
                    .append("); Save As elsewhere keeps the shipped scenes as they are. ");
        }
        if (exists && !same) {
            q.append(abs).append(" exists and would be replaced. ");
        } else if (same && exists && !modified(abs).equals(written)) {
            q.append(abs.getFileName()).append(" changed on disk since it was opened; saving replaces those changes. ");
        }
        return new Plan(abs, q.length() > 0, q.toString().trim());
    }

    /**
     * Writes the scene atomically to the plan's target ({@link SceneFiles#save}), rewriting relative
     * paths for the target's folder; the target becomes the open file.
     *
     * @param plan  a plan from {@link #plan}, confirmed by the user when it asked
     * @param scene the scene to write
     * @throws IOException naming the target when the write failed (the target is then unchanged)
     */
    void write(Plan plan, SceneDef scene) throws IOException {
        Path target = plan.target();
        SceneFiles.save(target, relocate(scene, file.getParent(), target.getParent()));
        file = target;
        written = modified(target);
    }

    /** The scene with its relative file paths rewritten from folder {@code from} to folder {@code to}. */
    static SceneDef relocate(SceneDef scene, Path from, Path to) {
        if (from == null || to == null || from.equals(to)) {
            return scene;
        }
        TerrainDef t = scene.terrain();
        TerrainDef nt = new TerrainDef(t.sizeX(), t.sizeZ(), t.resolution(), t.heightScale(), t.roughness(), t.seed(),
                move(t.heightmap(), from, to), map(t.water(), from, to), map(t.nutrients(), from, to));
        return new SceneDef(scene.version(), scene.name(), scene.seed(), nt, scene.species(), scene.distributions(),
                scene.placements(), scene.flows(), scene.field(), scene.camera(), scene.animation(), scene.render(),
                scene.world());
    }

    private static ResourceMapDef map(ResourceMapDef m, Path from, Path to) {
        String image = move(m.image(), from, to);
        return image == null || image.equals(m.image()) ? m
                : new ResourceMapDef(m.source(), m.resolution(), m.amount(), m.scale(), image);
    }

    private static String move(String path, Path from, Path to) {
        if (path == null || path.isEmpty() || Path.of(path).isAbsolute()) {
            return path;
        }
        Path abs = from.resolve(path).normalize();
        return to.relativize(abs).toString().replace('\\', '/');
    }

    private static FileTime modified(Path p) {
        try {
            return Files.getLastModifiedTime(p);
        } catch (IOException e) {
            return FileTime.fromMillis(0);
        }
    }

    private static Path real(Path p) {
        try {
            return p.toRealPath();
        } catch (IOException e) {
            return p;
        }
    }
}
