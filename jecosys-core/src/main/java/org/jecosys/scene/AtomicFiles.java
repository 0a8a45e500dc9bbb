package org.jecosys.scene;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermission;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.jecosys.math.Require;

/**
 * Writes a file so that it is either whole or not there: the content goes to a temporary file
 * ({@code .NAME.PID.RANDOM.tmp}) in the target's folder, is forced to disk, and is then moved over
 * the target in one step. On any failure, or if the process is killed midway, the target keeps its
 * previous content (or stays absent) and only the temporary file can remain; temporaries of this
 * target left by processes that are gone are removed by the next write. An existing target keeps its
 * permissions (POSIX mode); a symbolic link is followed, so the file it points to is replaced and the
 * link stays (a scene edited through a link updates the file the link names); a target that exists
 * but is not a regular file (a folder, a device such as {@code /dev/null}, a pipe) is refused. Scene
 * saves are written this way; a program's outputs (frames, reports, dumps) go through
 * {@link OutputFiles}, which writes the same way but never through a link. Any thread; allocates
 * (file time, not frame time).
 */
public final class AtomicFiles {
    /** Most symbolic links followed from a target. */
    private static final int MAX_LINKS = 40;
    /** A temporary file left by a live process is stale after this long anyway, milliseconds. */
    static final long STALE_TEMPORARY_MILLIS = 60L * 60 * 1000;
    private static final SecureRandom RANDOM = new SecureRandom();

    private AtomicFiles() {
    }

    /** Writes a file's content; the stream is buffered by the caller as it needs. */
    @FunctionalInterface
    public interface Content {
        /**
         * Writes the whole content.
         *
         * @param out the temporary file's stream; do not close it
         * @throws IOException when writing fails (the target is then left as it was)
         */
        void writeTo(OutputStream out) throws IOException;
    }

    /**
     * Writes {@code target} atomically (see the class comment).
     *
     * @param target  the file to write (replaced if it exists)
     * @param verb    what the caller does, for messages: "save" gives "cannot save FILE: why"
     * @param content writes the content, streamed: nothing needs to be held in memory
     * @throws IOException naming the target when the write failed or the target is not a regular file
     */
    public static void write(Path target, String verb, Content content) throws IOException {
        Require.nonNull("target", target);
        Require.nonNull("verb", verb);
        Require.nonNull("content", content);
        Path abs = followLinks(target, verb);
        if (Files.exists(abs) && !Files.isRegularFile(abs)) {
            throw new IOException("cannot " + verb + " " + target + ": " + (target.equals(abs) ? "it" : abs)
                    + " is not a regular file (" + (Files.isDirectory(abs) ? "a folder" : "a device, pipe or socket")
                    + "); choose a file name");
        }
        Path dir = abs.getParent();
        String name = abs.getFileName().toString();
        removeStaleTemporaries(temporariesIn(dir), name);
        replace(target, abs, verb, streamed(content), () -> null);
    }

    /** Writes the content of a temporary file, given by its path. */
    @FunctionalInterface
    interface TemporaryWriter {
        void writeTo(Path temporary) throws IOException;
    }

    /** A last check made just before the move: a reason to refuse the target, or null. */
    @FunctionalInterface
    interface LastCheck {
        String problem();
    }

    /** {@code content} written into the temporary file through one channel. */
    static TemporaryWriter streamed(Content content) {
        return tmp -> {
            try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING)) {
                OutputStream out = Channels.newOutputStream(ch);
                content.writeTo(out);
                out.flush();
            }
        };
    }

    /**
     * The shared core: writes a temporary file beside {@code abs} with {@code writer}, forces it to
     * disk, gives it the mode of the file it replaces, asks {@code last} once more, and moves it over
     * {@code abs}; on any failure the temporary file is removed and the target left as it was.
     *
     * @param shown  the target as the caller named it, for messages
     * @param abs    the absolute path that is replaced (links already resolved or refused)
     * @param verb   for messages: "cannot VERB SHOWN: why"
     * @param writer writes the temporary file
     * @param last   refuses the target just before the move (it may have changed since the first check)
     */
    static void replace(Path shown, Path abs, String verb, TemporaryWriter writer, LastCheck last) throws IOException {
        Path dir = abs.getParent();
        Set<PosixFilePermission> mode = null;
        try {
            if (Files.isRegularFile(abs)) {
                mode = Files.getPosixFilePermissions(abs);
            }
        } catch (UnsupportedOperationException | IOException e) {
            mode = null; // not a POSIX file system, or unreadable attributes: the new file gets the defaults
        }
        Path tmp;
        try {
            tmp = createTemporary(dir, abs.getFileName().toString());
        } catch (IOException e) {
            throw new IOException("cannot " + verb + " " + shown + ": cannot create a file in " + dir + " (" + e + ")", e);
        }
        boolean moved = false;
        try {
            writer.writeTo(tmp);
            try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE)) {
                ch.force(true);
            }
            if (mode != null) {
                Files.setPosixFilePermissions(tmp, mode);
            }
            String refused = last.problem();
            if (refused != null) {
                throw new IOException(refused);
            }
            try {
                Files.move(tmp, abs, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                throw new IOException("the file system cannot replace files atomically", e);
            }
            moved = true;
            forceDirectory(dir);
        } catch (IOException | RuntimeException e) {
            throw new IOException("cannot " + verb + " " + shown + ": " + reason(e), e);
        } finally {
            if (!moved) {
                Files.deleteIfExists(tmp);
            }
        }
    }

    /** A short reason for an I/O failure: the file system's own words where it gives them. */
    static String reason(Exception e) {
        if (e instanceof java.nio.file.NoSuchFileException) {
            return "no such folder";
        }
        if (e instanceof java.nio.file.AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof java.nio.file.FileSystemException fse && fse.getReason() != null) {
            return fse.getReason();
        }
        return e.getMessage() == null ? e.toString() : e.getMessage();
    }

    /** The absolute path a write replaces: {@code target} with every symbolic link followed (the last may dangle). */
    private static Path followLinks(Path target, String verb) throws IOException {
        Path p = target.toAbsolutePath();
        for (int i = 0; Files.isSymbolicLink(p); i++) {
            if (i == MAX_LINKS) {
                throw new IOException("cannot " + verb + " " + target + ": more than " + MAX_LINKS + " symbolic links");
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

    /**
     * The files in {@code dir} that may be temporaries of earlier writes ({@code .*.tmp}, not
     * followed); empty when the folder cannot be listed (the write itself will report what is wrong).
     */
    static List<Path> temporariesIn(Path dir) {
        List<Path> found = new ArrayList<>();
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir, p -> {
            String f = p.getFileName().toString();
            return f.startsWith(".") && f.endsWith(".tmp");
        })) {
            for (Path p : files) {
                found.add(p);
            }
        } catch (IOException | RuntimeException ignored) {
            found.clear(); // the folder cannot be listed: the write itself will report what is wrong
        }
        return found;
    }

    /**
     * Deletes, among {@code candidates}, the temporary files of earlier writes of {@code name}
     * ({@code .NAME.DIGITS.*tmp}) whose process no longer runs or that are older than
     * {@link #STALE_TEMPORARY_MILLIS}, and drops them from the list; errors are ignored (another write
     * may be removing them too).
     */
    static void removeStaleTemporaries(List<Path> candidates, String name) {
        String prefix = "." + name + ".";
        long now = System.currentTimeMillis();
        for (java.util.Iterator<Path> it = candidates.iterator(); it.hasNext(); ) {
            Path p = it.next();
            String f = p.getFileName().toString();
            if (!f.startsWith(prefix) || !f.endsWith(".tmp") || f.length() <= prefix.length() + 4) {
                continue;
            }
            String rest = f.substring(prefix.length());
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
                    it.remove();
                }
            } catch (IOException ignored) {
                // removed by someone else, or not ours to remove
            }
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
}
