package org.jecosys.terrain;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import org.jecosys.math.Require;

/**
 * Where the images a scene names come from (heightmaps, IMAGE resource maps, paper §4.3): given the
 * path exactly as the scene writes it, the whole file's bytes. Each image is read once; the bytes
 * that were checked (size, memory budget, decodability) are the bytes that are decoded, so a file
 * swapped on disk in between cannot matter.
 *
 * <ul>
 * <li>{@link #folder(Path)}: files in a folder's tree (a scene file's folder); a path that leads
 * out of it (through {@code ..}, an absolute path or a symbolic link) is refused. The default
 * everywhere a folder is given.</li>
 * <li>{@link #anywhere(Path)}: relative paths against a folder, absolute paths and links followed
 * wherever they lead: for scenes the user trusts (the command line's
 * {@code --allow-outside-images}).</li>
 * <li>{@link #of(Map)}: bytes held in memory, e.g. the images a loaded scene was checked with, or a
 * game's assets.</li>
 * <li>A game implements {@link #read} over its own assets (a libGDX {@code FileHandle}, a jME
 * {@code AssetManager}).</li>
 * </ul>
 * Implementations are called at load and build time from any one thread at a time; they allocate.
 */
@FunctionalInterface
public interface ImageSource {
    /** Largest image file read, bytes (256 MiB: an 8192 x 8192 16-bit grey image stored without compression). */
    long MAX_BYTES = 256L << 20;

    /** No images: every read fails, naming the path. For scenes that name none. */
    ImageSource NONE = path -> {
        throw new IOException("image '" + path + "': no image source was given for this scene");
    };

    /**
     * Reads the whole image file the scene names {@code path}.
     *
     * @param path the path as the scene writes it (relative to the scene, or absolute)
     * @return the file's bytes, at most {@link #MAX_BYTES}; the caller does not modify them
     * @throws IOException whose message names the path and why it cannot be read: missing, not a
     *                     regular file, outside the allowed folder, too large
     */
    byte[] read(String path) throws IOException;

    /**
     * A path as a scene writes it, made plain for a source over a game's assets (a libGDX
     * {@code FileHandle}'s siblings, a jME asset folder): relative, '/' separators, no '.' or '..'
     * segments, and never leading out of the scene's folder. Any thread; allocates.
     *
     * @param path as the scene writes it
     * @return the path made plain, e.g. {@code "img/ramp.png"} for {@code "./img/../img//ramp.png"}
     * @throws IOException naming the path, when it is absolute, empty, names the folder itself or leads
     *                     out of it
     */
    static String inFolder(String path) throws IOException {
        String p = Require.nonNull("path", path).replace('\\', '/');
        if (p.isEmpty() || p.startsWith("/") || (p.length() > 1 && p.charAt(1) == ':')) {
            throw new IOException("image '" + path + "': not a path relative to the scene's folder");
        }
        StringBuilder out = new StringBuilder(p.length());
        int depth = 0;
        for (String part : p.split("/")) {
            if (part.isEmpty() || part.equals(".")) {
                continue;
            }
            if (part.equals("..")) {
                if (depth == 0) {
                    throw new IOException("image '" + path + "': leads out of the scene's folder");
                }
                out.setLength(Math.max(out.lastIndexOf("/"), 0));
                depth--;
                continue;
            }
            if (out.length() > 0) {
                out.append('/');
            }
            out.append(part);
            depth++;
        }
        if (depth == 0) {
            throw new IOException("image '" + path + "': names the scene's folder, not a file");
        }
        return out.toString();
    }

    /**
     * Images inside {@code dir}'s folder tree only: relative paths resolve against {@code dir}, and
     * the result, after every symbolic link is followed, must lie inside {@code dir} (itself with links
     * followed). Absolute paths, {@code ..} out of the folder and links out of it are refused with the
     * reason. Pipes, devices and folders are refused before they are opened.
     *
     * @param dir the folder, usually the scene file's
     * @return a confined source
     */
    static ImageSource folder(Path dir) {
        return new FolderImages(Require.nonNull("dir", dir), false);
    }

    /**
     * Images anywhere: relative paths against {@code dir}, absolute paths and symbolic links as they
     * are. Only for scene files the user trusts; pipes, devices and folders are still refused.
     *
     * @param dir the folder relative paths resolve against
     * @return an unconfined source
     */
    static ImageSource anywhere(Path dir) {
        return new FolderImages(Require.nonNull("dir", dir), true);
    }

    /**
     * Images held in memory, keyed by the path the scene writes.
     *
     * @param images path to bytes; copied (the map, not the arrays)
     * @return a source that reads from the map and refuses any other path
     */
    static ImageSource of(Map<String, byte[]> images) {
        Map<String, byte[]> copy = new HashMap<>(Require.nonNull("images", images));
        return path -> {
            byte[] b = copy.get(path);
            if (b == null) {
                throw new IOException("image '" + path + "': not among the images held for this scene " + copy.keySet());
            }
            return b;
        };
    }
}
