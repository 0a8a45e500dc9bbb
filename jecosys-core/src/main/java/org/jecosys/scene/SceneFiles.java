package org.jecosys.scene;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.function.UnaryOperator;
import org.jecosys.math.Require;
import org.jecosys.terrain.ImageSource;

/**
 * Reads, validates and saves scene files ({@code <scene version="1">}, documented by
 * {@code scenes/jecosys-scene.xsd}). One verb per result: {@code parse} turns text into a
 * {@link SceneDef}, the definition alone (to edit, save or build from code); {@code read} gives a
 * {@link Scene} ready to simulate, the definition with the image bytes it was checked with
 * ({@link Scenes#simulation(Scene, int, org.jecosys.math.Progress)}). Either returns a complete,
 * valid result or throws {@link SceneLoadException} listing every problem as
 * {@code FILE:LINE:COL: message}; neither returns a half-loaded scene. Files are read through Jackson XML's hardened parser: no DTDs,
 * no entities, no external access of any kind. Saving is atomic ({@link AtomicFiles}): a temporary
 * file in the same folder, forced to disk, then moved over the target, so a failure leaves the
 * original untouched.
 *
 * <p>All methods may be called from any thread; they share no state. They allocate (this is load
 * time, not frame time).
 */
public final class SceneFiles {
    /** Largest scene file accepted, bytes (8 MiB). */
    public static final long MAX_FILE_BYTES = SceneSchema.MAX_FILE_BYTES;
    /**
     * Most elements in one scene file (300,000): above the most the schema's counts allow, so only
     * files that could never be valid are refused by it; reading stops at the element that crosses it.
     * Reading is also bounded by the heap: a file whose elements would not fit in this JVM's heap is
     * refused, located, where they stop fitting.
     */
    public static final int MAX_ELEMENTS = XmlReader.MAX_ELEMENTS;
    /** Most attributes in one scene file, all elements together (700,000), likewise. */
    public static final int MAX_ATTRIBUTES = XmlReader.MAX_ATTRIBUTES;

    private SceneFiles() {
    }

    /**
     * Parses and validates a scene file into its definition; relative paths inside it (heightmaps,
     * images) are resolved against its folder, must exist and must lie in its folder tree
     * ({@link ImageSource#folder}). The images are checked as {@link #read(Path)} checks them, but not
     * kept: for a scene to simulate, {@link #read(Path)} is the one that keeps the bytes it checked.
     *
     * @param file the scene file; its name as given appears in every problem
     * @return the complete definition
     * @throws SceneLoadException if the file cannot be read, is not a valid scene, has more than
     *                            {@link #MAX_ELEMENTS} elements or {@link #MAX_ATTRIBUTES} attributes,
     *                            names an image that is missing, outside its folder, too large
     *                            ({@link org.jecosys.terrain.ImageFiles#MAX_SIDE}) or corrupt, or needs
     *                            more memory to read or to build than this JVM's heap allows
     */
    public static SceneDef parse(Path file) throws SceneLoadException {
        return read(file).def();
    }

    /**
     * Reads a scene file into a {@link Scene} ready to simulate: parsed and validated like
     * {@link #parse(Path)}, with the bytes of the images it names kept as they were checked
     * ({@link Scene#images()}), so that building it reads no file again. Images must lie in the
     * file's folder tree.
     *
     * @param file the scene file; its name as given appears in every problem
     * @return the scene and its checked images
     * @throws SceneLoadException as {@link #parse(Path)}
     */
    public static Scene read(Path file) throws SceneLoadException {
        Require.nonNull("file", file);
        return read(file, ImageSource.folder(Scenes.baseDir(file)));
    }

    /**
     * Reads a scene file like {@link #read(Path)}, with its images from {@code images}: for example
     * {@link ImageSource#anywhere} for a scene the user trusts to name images outside its folder.
     * Paths that are not regular files (folders, pipes, devices) are refused before they are opened.
     *
     * @param file   the scene file; its name as given appears in every problem
     * @param images where the images it names are read from, once each
     * @return the scene and its checked images
     * @throws SceneLoadException as {@link #parse(Path)}
     */
    public static Scene read(Path file, ImageSource images) throws SceneLoadException {
        Require.nonNull("file", file);
        Require.nonNull("images", images);
        String name = file.toString();
        byte[] bytes;
        try {
            // refuse what is not a regular file before opening it: opening a FIFO blocks until a
            // writer comes, and a device can be read forever
            BasicFileAttributes attrs = Files.readAttributes(file, BasicFileAttributes.class);
            if (attrs.isDirectory()) {
                throw fail(name, "is a directory, not a scene file");
            }
            if (!attrs.isRegularFile()) {
                throw fail(name, "is not a regular file but " + otherKind(file) + "; scene files are regular files");
            }
            long size = attrs.size();
            if (size > MAX_FILE_BYTES) {
                throw fail(name, "file is " + size + " bytes; scene files are limited to " + MAX_FILE_BYTES
                        + " bytes (8 MiB)");
            }
            try (InputStream in = Files.newInputStream(file)) {
                bytes = in.readNBytes((int) MAX_FILE_BYTES + 1);
            }
        } catch (NoSuchFileException e) {
            throw fail(name, "no such file");
        } catch (AccessDeniedException e) {
            throw fail(name, "permission denied");
        } catch (IOException e) {
            throw fail(name, "cannot read: " + e.getMessage());
        }
        return bind(bytes, name, images);
    }

    /**
     * Reads a scene ready to simulate from a stream (an engine's asset, a classpath resource, a network
     * download), with the images it names read from {@code images} (a game's resolver over its own
     * assets, {@link ImageSource#folder}, or {@link ImageSource#NONE} for a scene that names none).
     * Reads at most {@link #MAX_FILE_BYTES} + 1 bytes; does not close the stream.
     *
     * @param in     the scene's XML, UTF-8
     * @param name   the name every problem is reported under (e.g. the asset's path)
     * @param images where the images it names are read from, once each
     * @return the scene and its checked images
     * @throws SceneLoadException when the stream cannot be read or is not a valid scene, an image
     *                            cannot be read or is too large or corrupt, or the scene needs more
     *                            memory than this JVM's heap allows
     */
    public static Scene read(InputStream in, String name, ImageSource images) throws SceneLoadException {
        Require.nonNull("in", in);
        Require.nonNull("name", name);
        Require.nonNull("images", images);
        byte[] bytes;
        try {
            bytes = in.readNBytes((int) MAX_FILE_BYTES + 1);
        } catch (IOException e) {
            throw fail(name, "cannot read: " + e.getMessage());
        }
        return bind(bytes, name, images);
    }

    /**
     * Parses and validates scene XML held in memory into its definition.
     *
     * @param bytes    the file's bytes, UTF-8
     * @param fileName the name used in problems
     * @param baseDir  folder that relative paths resolve against and whose tree the images must lie
     *                 in, or null to skip the image checks
     * @return the complete definition
     * @throws SceneLoadException if the bytes are not a valid scene, or the scene needs more memory
     *                            than this JVM's heap allows (plants, components, pose tables, grids
     *                            and, with a baseDir, images, estimated before anything is built)
     */
    public static SceneDef parse(byte[] bytes, String fileName, Path baseDir) throws SceneLoadException {
        return bind(bytes, fileName, baseDir == null ? null : ImageSource.folder(baseDir)).def();
    }

    /** Parses, validates, budgets and binds the checked images; {@code images} null skips the image checks. */
    private static Scene bind(byte[] bytes, String fileName, ImageSource images) throws SceneLoadException {
        if (bytes.length > MAX_FILE_BYTES) {
            throw fail(fileName, "file is " + bytes.length + " bytes; scene files are limited to " + MAX_FILE_BYTES
                    + " bytes (8 MiB)");
        }
        String text = decode(bytes, fileName);
        if (text.isBlank()) {
            throw new SceneLoadException(new SceneProblem(fileName, 1, 1,
                    "file is empty; expected <scene version=\"1\"> (see scenes/jecosys-scene.xsd)"));
        }
        // bounded in elements and in memory at this JVM's heap: refused where it crosses, never run out of memory
        XmlNode root = new XmlReader(fileName, text, bytes.length, Runtime.getRuntime().maxMemory()).read();
        SceneValidator validator = new SceneValidator(fileName);
        Values values = validator.validateRoot(root);
        if (values == null || !validator.problems().isEmpty()) {
            throw new SceneLoadException(validator.problems());
        }
        SceneBinder binder = new SceneBinder(validator, images);
        SceneDef scene = binder.bind(values);
        if (scene == null || !validator.problems().isEmpty()) {
            throw new SceneLoadException(validator.problems());
        }
        // accepted means runnable: refuse what cannot fit in this JVM's heap, before anything is built
        if (!new SceneBudget(validator, Runtime.getRuntime().maxMemory()).check(scene, values, binder.images)) {
            throw new SceneLoadException(validator.problems());
        }
        return new Scene(scene, fileName, binder.checked.isEmpty() ? ImageSource.NONE : ImageSource.of(binder.checked));
    }

    /**
     * The scene as XML text, exactly as {@link #save} writes it.
     *
     * @param scene the scene
     * @return a {@code <scene version="1">} document; {@link #parse(Path)} reads it back to an equal scene
     */
    public static String toXml(SceneDef scene) {
        return SceneWriter.toXml(scene);
    }

    /**
     * Saves a scene atomically: the bytes go to a temporary file in the target's folder, are forced
     * to disk, and the temporary file is then moved over the target in one step. On any failure the
     * target keeps its previous content and the temporary file is removed. An existing target keeps
     * its permissions (POSIX mode); a symbolic link is followed, so the file it points to is replaced
     * and the link stays; a target that exists but is not a regular file (a folder, a device such as
     * {@code /dev/null}, a pipe) is refused. Temporary files of earlier saves of this target whose
     * process is gone (killed during a save) are removed. Any thread; allocates.
     *
     * @param target the scene file to write (replaced if it exists)
     * @param scene  the scene
     * @throws IOException naming the target when the save failed or the target is not a regular file
     */
    public static void save(Path target, SceneDef scene) throws IOException {
        save(target, scene, UnaryOperator.identity());
    }

    /** {@link #save(Path, SceneDef)} with the output stream wrapped, for failure-injection tests. */
    static void save(Path target, SceneDef scene, UnaryOperator<OutputStream> wrap) throws IOException {
        byte[] bytes = toXml(scene).getBytes(StandardCharsets.UTF_8);
        AtomicFiles.write(target, "save", out -> {
            OutputStream o = wrap.apply(out);
            o.write(bytes);
            o.flush();
        });
    }

    /**
     * The text of a UTF-8 file, a leading byte order mark dropped. Checked in small chunks first, so
     * decoding takes the text's own string and nothing the size of the file besides.
     */
    private static String decode(byte[] bytes, String fileName) throws SceneLoadException {
        int start = bytes.length >= 3 && (bytes[0] & 0xff) == 0xEF && (bytes[1] & 0xff) == 0xBB
                && (bytes[2] & 0xff) == 0xBF ? 3 : 0;
        int bad = firstInvalid(bytes, start);
        if (bad < 0) {
            return new String(bytes, start, bytes.length - start, StandardCharsets.UTF_8);
        }
        int line = 1;
        int lineStart = 0;
        for (int i = 0; i < bad; i++) {
            if (bytes[i] == '\n') {
                line++;
                lineStart = i + 1;
            }
        }
        throw new SceneLoadException(new SceneProblem(fileName, line, bad - lineStart + 1,
                "not valid UTF-8 (byte offset " + bad + "); scene files are UTF-8 text"));
    }

    /** The byte offset of the first sequence that is not UTF-8, or -1 when there is none. */
    private static int firstInvalid(byte[] bytes, int start) {
        CharsetDecoder dec = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes, start, bytes.length - start);
        CharBuffer out = CharBuffer.allocate(8192);
        while (true) {
            CoderResult r = dec.decode(in, out, true);
            if (r.isError()) {
                return in.position();
            }
            if (r.isUnderflow()) {
                return -1;
            }
            out.clear(); // overflow: the chunk is checked, its characters are not needed
        }
    }

    /** What a path that is neither a regular file nor a folder is, from its POSIX mode where there is one. */
    private static String otherKind(Path file) {
        int type = -1;
        try {
            if (Files.getAttribute(file, "unix:mode") instanceof Integer mode) {
                type = mode & 0170000;
            }
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException | SecurityException e) {
            // no POSIX mode here: say what it may be
        }
        return switch (type) {
            case 0010000 -> "a named pipe (FIFO)";
            case 0020000 -> "a character device";
            case 0060000 -> "a block device";
            case 0140000 -> "a socket";
            default -> "a pipe, device or socket";
        };
    }

    /** A problem about the file itself: located by its path only (line 0, printed without 0:0). */
    private static SceneLoadException fail(String file, String message) {
        return new SceneLoadException(new SceneProblem(file, 0, 0, message));
    }
}
