package org.jecosys.scene;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.PosixFileAttributes;
import java.nio.file.attribute.PosixFilePermission;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.jecosys.math.Require;

/**
 * The writer of a program's output files (rendered frames, animations, reports, dumps, charts): each
 * is written as {@link AtomicFiles} writes (a temporary file beside the target, forced to disk, then
 * moved over it in one step, so a failed or killed write leaves the old file whole, or none), and
 * only onto a free name or a regular file:
 * <ul>
 * <li>a target that is a <b>symbolic link</b> is refused: it is never followed, and neither the link
 * nor the file it names is touched (the folders above the target may be links, as {@code /tmp} is
 * on some systems);</li>
 * <li>a target that is a <b>folder, device, pipe or socket</b> is refused before anything opens it,
 * so a write never blocks on a pipe and never turns a device into a file;</li>
 * <li>a target in a <b>read-only folder</b>, or a read-only file, is refused. Read-only means not
 * writable by this process ({@link Files#isWritable}) or without its owner's write permission
 * (POSIX): the second rule holds for root too, whom permission bits do not stop, so a folder its
 * owner made read-only is left alone by everyone.</li>
 * </ul>
 * {@link #problem(Path)} and {@link #folderProblem(Path)} are the same rules as questions, for a
 * program that checks its outputs before it starts working; {@link #write} asks {@link #problem}
 * again before the temporary file is made, and just before the move asks once more whether the
 * target has become a link, folder, device, pipe or socket. Missing folders above a target
 * are made when it is written (as {@code mkdir -p}). Temporaries left in a folder by writers that
 * are gone are listed once per folder and writer, and removed as their target is written: a
 * hundred thousand frames in one folder cost one listing, not one each.
 * <p>Any thread; one writer may be shared. Allocates (file time, not frame time).
 */
public final class OutputFiles {
    /** Temporaries found in each folder written so far, removed as their targets are written. */
    private final Map<Path, List<Path>> temporaries = new ConcurrentHashMap<>();

    /** A writer with nothing listed yet. Any thread; allocates. */
    public OutputFiles() {
    }

    /** Writes a file's content given its path: for encoders that only write to a named file. */
    @FunctionalInterface
    public interface FileContent {
        /**
         * Writes the whole content into {@code temporary}.
         *
         * @param temporary an empty regular file this writer just made beside the target; write it (it
         *                  may be replaced by a new file of the same name), do not move or delete it
         * @throws IOException when writing fails (the target is then left as it was)
         */
        void writeTo(Path temporary) throws IOException;
    }

    /**
     * Writes {@code target} from a stream (see the class comment). Any thread; allocates.
     *
     * @param target  the file to write: a free name or a regular file (replaced)
     * @param content writes the content, streamed: nothing needs to be held in memory
     * @throws IOException "cannot write TARGET: why" when the target is refused or the write fails;
     *                     the target is then left as it was
     */
    public void write(Path target, AtomicFiles.Content content) throws IOException {
        Require.nonNull("content", content);
        replace(target, AtomicFiles.streamed(content));
    }

    /**
     * Writes {@code target} with an encoder that writes to a named file (an image library's
     * {@code write(path)}), through a temporary file (see the class comment). Any thread; allocates.
     *
     * @param target  the file to write: a free name or a regular file (replaced)
     * @param content writes the temporary file by its path
     * @throws IOException "cannot write TARGET: why" when the target is refused or the write fails;
     *                     the target is then left as it was
     */
    public void writeFile(Path target, FileContent content) throws IOException {
        Require.nonNull("content", content);
        replace(target, content::writeTo);
    }

    private void replace(Path target, AtomicFiles.TemporaryWriter writer) throws IOException {
        Require.nonNull("target", target);
        Path abs = target.toAbsolutePath();
        String refused = problem(abs);
        if (refused != null) {
            throw new IOException("cannot write " + target + ": " + refused);
        }
        Path dir = abs.getParent();
        try {
            Files.createDirectories(dir);
        } catch (IOException e) {
            throw new IOException("cannot write " + target + ": cannot create its folder " + dir + ": "
                    + AtomicFiles.reason(e), e);
        }
        List<Path> found = temporaries.computeIfAbsent(dir, AtomicFiles::temporariesIn);
        synchronized (found) {
            AtomicFiles.removeStaleTemporaries(found, abs.getFileName().toString());
        }
        AtomicFiles.replace(target, abs, "write", writer, () -> targetProblem(abs));
    }

    /**
     * Why {@code target} may not be written as an output, or null when it may: it is a symbolic link,
     * a folder, a device, pipe or socket, a read-only file, or its folder is read-only, not a folder or
     * cannot be made (see the class comment). Reads attributes only, never opens the target. Any
     * thread; allocates.
     *
     * @param target the file a program will write
     * @return e.g. "is a pipe (FIFO), not a regular file", or null; the phrase follows the path
     */
    public static String problem(Path target) {
        Path abs = Require.nonNull("target", target).toAbsolutePath();
        String own = targetProblem(abs);
        if (own != null) {
            return own;
        }
        Path dir = abs.getParent();
        if (dir == null) {
            return "names no file";
        }
        String folder = folderProblem(dir);
        return folder == null ? null : "is in " + dir + ", which " + folder;
    }

    /**
     * Why files may not be written into {@code dir}, or null when they may: it exists and is not a
     * folder, or it is read-only, or it is missing and cannot be made (a file above it, a read-only
     * folder above it). A link to a folder counts as the folder. Any thread; allocates.
     *
     * @param dir the folder a program will write into (made if missing)
     * @return e.g. "is read-only (no write permission for its owner)", or null; the phrase follows
     *         the path
     */
    public static String folderProblem(Path dir) {
        Path abs = Require.nonNull("dir", dir).toAbsolutePath();
        if (Files.isDirectory(abs)) {
            return readOnly(abs);
        }
        if (Files.exists(abs)) {
            return "is " + kind(abs, true) + ", not a folder";
        }
        Path p = abs.getParent();
        while (p != null && !Files.exists(p)) {
            p = p.getParent();
        }
        if (p == null) {
            return "cannot be made: no folder above it exists";
        }
        if (!Files.isDirectory(p)) {
            return "cannot be made: " + p + " is " + kind(p, true) + ", not a folder";
        }
        String ro = readOnly(p);
        return ro == null ? null : "cannot be made: " + p + " " + ro;
    }

    /** The target's own problem (not its folder's), never following a link. */
    private static String targetProblem(Path abs) {
        BasicFileAttributes a;
        try {
            a = Files.readAttributes(abs, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
        } catch (NoSuchFileException e) {
            return null; // a free name
        } catch (IOException e) {
            Path dir = abs.getParent();
            // a file where a folder should be ("Not a directory"): the folder's check says what is wrong
            return dir != null && !Files.isDirectory(dir) ? null : "cannot be examined (" + AtomicFiles.reason(e) + ")";
        }
        if (a.isSymbolicLink()) {
            String to;
            try {
                to = " to " + Files.readSymbolicLink(abs);
            } catch (IOException | UnsupportedOperationException e) {
                to = "";
            }
            return "is a symbolic link" + to + "; outputs are never written through a link";
        }
        if (a.isDirectory()) {
            return "is a folder, not a file";
        }
        if (!a.isRegularFile()) {
            return "is " + kind(abs, false) + ", not a regular file";
        }
        return readOnly(abs);
    }

    /** "is read-only (...)" when {@code p} (a file or folder) may not be written, else null. */
    private static String readOnly(Path p) {
        if (!Files.isWritable(p)) {
            return "is not writable (permission denied)";
        }
        try {
            PosixFileAttributes a = Files.readAttributes(p, PosixFileAttributes.class);
            if (!a.permissions().contains(PosixFilePermission.OWNER_WRITE)) {
                return "is read-only (no write permission for its owner)";
            }
        } catch (UnsupportedOperationException | IOException e) {
            return null; // not a POSIX file system: Files.isWritable said yes
        }
        return null;
    }

    /** What a file is, by its type bits: "a pipe (FIFO)", "a character device", ..., "a file". */
    private static String kind(Path p, boolean followLinks) {
        LinkOption[] opts = followLinks ? new LinkOption[0] : new LinkOption[] {LinkOption.NOFOLLOW_LINKS};
        try {
            int type = ((Integer) Files.getAttribute(p, "unix:mode", opts)) & 0170000;
            return switch (type) {
                case 0010000 -> "a pipe (FIFO)";
                case 0020000 -> "a character device";
                case 0060000 -> "a block device";
                case 0140000 -> "a socket";
                case 0040000 -> "a folder";
                case 0120000 -> "a symbolic link";
                default -> "a file";
            };
        } catch (UnsupportedOperationException | IllegalArgumentException | ClassCastException | IOException e) {
            return Files.isRegularFile(p, opts) ? "a file" : "a device, pipe or socket";
        }
    }
}
