package org.jecosys.terrain;

import java.io.IOException;
import java.io.InputStream;
import java.nio.channels.Channels;
import java.nio.channels.SeekableByteChannel;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;

/** {@link ImageSource#folder} and {@link ImageSource#anywhere}: image files on disk. */
final class FolderImages implements ImageSource {
    /** How a message tells the user to allow images outside the folder. */
    static final String ALLOW = "allowed with the command line's --allow-outside-images or ImageSource.anywhere";

    private final Path dir;
    private final boolean anywhere;

    FolderImages(Path dir, boolean anywhere) {
        this.dir = dir.toAbsolutePath().normalize();
        this.anywhere = anywhere;
    }

    @Override
    public byte[] read(String path) throws IOException {
        if (path == null || path.isEmpty()) {
            throw new IOException("an image path must not be empty");
        }
        Path given;
        try {
            given = Path.of(path);
        } catch (InvalidPathException e) {
            throw new IOException("'" + path + "' is not a valid path");
        }
        if (given.isAbsolute() && !anywhere) {
            throw new IOException("image '" + path + "' is an absolute path; images must lie in the scene's folder "
                    + dir + " (" + ALLOW + ")");
        }
        Path file = dir.resolve(given).normalize();
        Path real;
        try {
            real = file.toRealPath();
        } catch (NoSuchFileException e) {
            throw new IOException("file '" + path + "' not found (looked at " + file + ")");
        } catch (AccessDeniedException e) {
            throw new IOException("image '" + path + "': permission denied (" + file + ")");
        }
        if (!anywhere) {
            Path root;
            try {
                root = dir.toRealPath();
            } catch (IOException e) {
                throw new IOException("image '" + path + "': the scene's folder " + dir + " cannot be read (" + e + ")");
            }
            if (!real.startsWith(root)) {
                throw new IOException("image '" + path + "' resolves to " + real + ", outside the scene's folder "
                        + root + " (" + ALLOW + ")");
            }
        }
        return readFile(path, real);
    }

    /**
     * Reads a regular file whole, at most {@link ImageSource#MAX_BYTES}: a pipe, device or folder is
     * refused before it is opened, and the final link is not followed again at open.
     */
    static byte[] readFile(String name, Path real) throws IOException {
        BasicFileAttributes a = Files.readAttributes(real, BasicFileAttributes.class);
        if (!a.isRegularFile()) {
            throw new IOException("image '" + name + "' (" + real + ") is not a regular file ("
                    + (a.isDirectory() ? "a folder" : "a pipe, device or socket") + ")");
        }
        if (a.size() > MAX_BYTES) {
            throw new IOException("image '" + name + "' is " + a.size() + " bytes; image files are limited to "
                    + MAX_BYTES + " bytes (ImageSource.MAX_BYTES)");
        }
        try (SeekableByteChannel ch = Files.newByteChannel(real, StandardOpenOption.READ, LinkOption.NOFOLLOW_LINKS);
             InputStream in = Channels.newInputStream(ch)) {
            byte[] b = in.readNBytes((int) MAX_BYTES + 1);
            if (b.length > MAX_BYTES) {
                throw new IOException("image '" + name + "' grew past " + MAX_BYTES + " bytes while it was read");
            }
            return b;
        } catch (AccessDeniedException e) {
            throw new IOException("image '" + name + "': permission denied (" + real + ")");
        }
    }
}
