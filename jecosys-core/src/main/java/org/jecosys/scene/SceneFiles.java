package org.jecosys.scene;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermission;
import java.util.Set;
import java.util.function.UnaryOperator;

/**
 * Loads, validates and saves scene files ({@code <scene version="1">}, documented by
 * {@code scenes/jecosys-scene.xsd}). Loading either returns a complete, valid {@link SceneDef} or
 * throws {@link SceneLoadException} listing every problem as {@code FILE:LINE:COL: message}; it
 * never returns a half-loaded scene. Files are read through Jackson XML's hardened parser: no DTDs,
 * no entities, no external access of any kind. Saving is atomic: a temporary file in the same
 * folder, forced to disk, then moved over the target, so a failure leaves the original untouched.
 *
 * <p>All methods may be called from any thread; they share no state. They allocate (this is load
 * time, not frame time).
 */
public final class SceneFiles {
    /** Largest scene file accepted, bytes (8 MiB). */
    public static final long MAX_FILE_BYTES = SceneSchema.MAX_FILE_BYTES;

    private SceneFiles() {
    }

    /**
     * Loads and validates a scene file; relative paths inside it (heightmaps, images) are resolved
     * against its folder and must exist.
     *
     * @param file the scene file; its name as given appears in every problem
     * @return the complete scene
     * @throws SceneLoadException if the file cannot be read, is not a valid scene, names an image that
     *                            is missing, too large ({@link org.jecosys.terrain.ImageFiles#MAX_SIDE})
     *                            or corrupt, or needs more memory than this JVM's heap allows
     */
    public static SceneDef load(Path file) throws SceneLoadException {
        String name = file.toString();
        byte[] bytes;
        try {
            if (Files.isDirectory(file)) {
                throw fail(name, "is a directory, not a scene file");
            }
            long size = Files.size(file);
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
        Path parent = file.toAbsolutePath().getParent();
        return parse(bytes, name, parent);
    }

    /**
     * Parses and validates scene XML held in memory.
     *
     * @param bytes    the file's bytes, UTF-8
     * @param fileName the name used in problems
     * @param baseDir  folder that relative paths resolve against and must exist in, or null to skip
     *                 the existence checks
     * @return the complete scene
     * @throws SceneLoadException if the bytes are not a valid scene, or the scene needs more memory
     *                            than this JVM's heap allows (plants, components, pose tables, grids
     *                            and, with a baseDir, images, estimated before anything is built)
     */
    public static SceneDef parse(byte[] bytes, String fileName, Path baseDir) throws SceneLoadException {
        if (bytes.length > MAX_FILE_BYTES) {
            throw fail(fileName, "file is " + bytes.length + " bytes; scene files are limited to " + MAX_FILE_BYTES
                    + " bytes (8 MiB)");
        }
        String text = decode(bytes, fileName);
        if (text.isBlank()) {
            throw new SceneLoadException(new SceneProblem(fileName, 1, 1,
                    "file is empty; expected <scene version=\"1\"> (see scenes/jecosys-scene.xsd)"));
        }
        XmlNode root = new XmlReader(fileName, text).read();
        SceneValidator validator = new SceneValidator(fileName);
        Values values = validator.validateRoot(root);
        if (values == null || !validator.problems().isEmpty()) {
            throw new SceneLoadException(validator.problems());
        }
        SceneBinder binder = new SceneBinder(validator, baseDir);
        SceneDef scene = binder.bind(values);
        if (scene == null || !validator.problems().isEmpty()) {
            throw new SceneLoadException(validator.problems());
        }
        // accepted means runnable: refuse what cannot fit in this JVM's heap, before anything is built
        if (!new SceneBudget(validator, Runtime.getRuntime().maxMemory()).check(scene, values, binder.images)) {
            throw new SceneLoadException(validator.problems());
        }
        return scene;
    }

    /**
     * The scene as XML text, exactly as {@link #save} writes it.
     *
     * @param scene the scene
     * @return a {@code <scene version="1">} document; {@link #load} reads it back to an equal scene
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
        Path abs = followLinks(target);
        if (Files.exists(abs) && !Files.isRegularFile(abs)) {
            throw new IOException("cannot save " + target + ": " + (target.equals(abs) ? "it" : abs)
                    + " is not a regular file (" + (Files.isDirectory(abs) ? "a folder" : "a device, pipe or socket")
                    + "); choose a file name");
        }
        Path dir = abs.getParent();
        removeStaleTemporaries(dir, abs.getFileName().toString());
        Set<PosixFilePermission> mode = null;
        try {
            if (Files.exists(abs)) {
                mode = Files.getPosixFilePermissions(abs);
            }
        } catch (UnsupportedOperationException | IOException e) {
            mode = null; // not a POSIX file system, or unreadable attributes: the new file gets the defaults
        }
        Path tmp;
        try {
            tmp = createTemporary(dir, abs.getFileName().toString());
        } catch (IOException e) {
            throw new IOException("cannot save " + target + ": cannot create a file in " + dir + " (" + e + ")", e);
        }
        boolean moved = false;
        try {
            try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING);
                 OutputStream out = wrap.apply(Channels.newOutputStream(ch))) {
                out.write(bytes);
                out.flush();
                ch.force(true);
            }
            if (mode != null) {
                Files.setPosixFilePermissions(tmp, mode);
            }
            try {
                Files.move(tmp, abs, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                throw new IOException("cannot save " + target + ": the file system cannot replace files atomically", e);
            }
            moved = true;
            forceDirectory(dir);
        } catch (IOException | RuntimeException e) {
            throw new IOException("cannot save " + target + ": " + e.getMessage(), e);
        } finally {
            if (!moved) {
                Files.deleteIfExists(tmp);
            }
        }
    }

    /** Most symbolic links followed from a save's target. */
    private static final int MAX_LINKS = 40;
    /** A temporary file left by a live process is stale after this long anyway, milliseconds. */
    static final long STALE_TEMPORARY_MILLIS = 60L * 60 * 1000;

    /** The absolute path a save writes: {@code target} with every symbolic link followed (the last may dangle). */
    private static Path followLinks(Path target) throws IOException {
        Path p = target.toAbsolutePath();
        for (int i = 0; Files.isSymbolicLink(p); i++) {
            if (i == MAX_LINKS) {
                throw new IOException("cannot save " + target + ": more than " + MAX_LINKS + " symbolic links");
            }
            Path link = Files.readSymbolicLink(p);
            p = p.getParent().resolve(link).normalize();
        }
        return p;
    }

    /** {@code .NAME.PID.RANDOM.tmp} in {@code dir}, created empty with the default permissions. */
    private static Path createTemporary(Path dir, String name) throws IOException {
        long pid = ProcessHandle.current().pid();
        for (int attempt = 0; ; attempt++) {
            Path tmp = dir.resolve("." + name + "." + pid + "." + Long.toUnsignedString(RANDOM.nextLong(), 36) + ".tmp");
            try {
                Files.newByteChannel(tmp, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE).close();
                return tmp;
            } catch (java.nio.file.FileAlreadyExistsException e) {
                if (attempt == 10) {
                    throw e;
                }
            }
        }
    }

    private static final java.security.SecureRandom RANDOM = new java.security.SecureRandom();

    /**
     * Deletes temporary files of earlier saves of {@code name} in {@code dir} ({@code .NAME.DIGITS.*tmp})
     * whose process no longer runs or that are older than {@link #STALE_TEMPORARY_MILLIS}; errors are
     * ignored (another save may be removing them too).
     */
    private static void removeStaleTemporaries(Path dir, String name) {
        String prefix = "." + name + ".";
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir, p -> {
            String f = p.getFileName().toString();
            return f.startsWith(prefix) && f.endsWith(".tmp") && f.length() > prefix.length() + 4;
        })) {
            long now = System.currentTimeMillis();
            for (Path p : files) {
                String rest = p.getFileName().toString().substring(prefix.length());
                int dot = rest.indexOf('.');
                String digits = rest.substring(0, Math.max(dot, 0));
                if (digits.isEmpty() || !digits.chars().allMatch(Character::isDigit) || digits.length() > 20) {
                    continue;
                }
                // before 0.1.0 the number was random (File.createTempFile), not a process id: such a
                // file names no live process and is removed too
                long pid = new java.math.BigInteger(digits).bitLength() > 62 ? -1 : Long.parseLong(digits);
                boolean gone = pid < 0 || ProcessHandle.of(pid).map(h -> !h.isAlive()).orElse(true);
                try {
                    if (!Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
                        continue;
                    }
                    if (gone || now - Files.getLastModifiedTime(p).toMillis() > STALE_TEMPORARY_MILLIS) {
                        Files.deleteIfExists(p);
                    }
                } catch (IOException ignored) {
                    // removed by someone else, or not ours to remove
                }
            }
        } catch (IOException | RuntimeException ignored) {
            // the folder cannot be listed: the save itself will report what is wrong
        }
    }

    /** Makes the rename durable; some platforms cannot open folders, which is harmless. */
    private static void forceDirectory(Path dir) {
        try (FileChannel ch = FileChannel.open(dir, StandardOpenOption.READ)) {
            ch.force(true);
        } catch (IOException ignored) {
            // not supported on this platform; the file itself is already on disk
        }
    }

    private static String decode(byte[] bytes, String fileName) throws SceneLoadException {
        int start = bytes.length >= 3 && (bytes[0] & 0xff) == 0xEF && (bytes[1] & 0xff) == 0xBB
                && (bytes[2] & 0xff) == 0xBF ? 3 : 0;
        CharsetDecoder dec = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes, start, bytes.length - start);
        try {
            CharBuffer cb = dec.decode(in);
            return cb.toString();
        } catch (CharacterCodingException e) {
            int bad = firstInvalid(bytes, start);
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
    }

    private static int firstInvalid(byte[] bytes, int start) {
        CharsetDecoder dec = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes, start, bytes.length - start);
        CharBuffer out = CharBuffer.allocate(bytes.length + 1);
        dec.decode(in, out, true);
        return in.position();
    }

    private static SceneLoadException fail(String file, String message) {
        return new SceneLoadException(new SceneProblem(file, 0, 0, message));
    }
}
