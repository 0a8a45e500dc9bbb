package org.jecosys.app;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.jecosys.scene.OutputFiles;
import org.jecosys.terrain.ImageSource;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;

/**
 * Every file one command will write, checked together before any work starts, so that a run of
 * minutes never ends in "cannot write" and never replaces what is not its own output. A problem is
 * bad input (exit 2) whose message names the flag, the path and what is allowed:
 * <ul>
 * <li>each target by {@link OutputFiles#problem}'s rules: a free name or a regular file, never a
 * symbolic link, folder, device, pipe or socket, never in a read-only folder; the files a command
 * writes into a folder (frames, maps, reports) are each checked, by one listing of the folder;</li>
 * <li>no two outputs of the run are the same file ({@code --dump X --json X}, a {@code --gif}
 * named like a frame);</li>
 * <li>no output is a file the run reads: the scene file (by real path and by file identity, so a
 * hard link counts too) and, once the scene is loaded, the images it read ({@link #images},
 * {@link #checkImages}).</li>
 * </ul>
 * Nothing is created by the checks: {@link #createFolders} makes the missing folders once the scene
 * was accepted. The files themselves are written by {@link OutputFiles}, which asks the same
 * questions again. The command's thread; allocates.
 */
final class OutputPlan {
    /** Files a command writes into one folder: frames, maps, reports. */
    private record Group(String flag, Path given, Path dir, Set<String> names, boolean subfolder) {
    }

    /** A file the user named with a flag. */
    private record Named(String flag, Path given) {
    }

    /** A file the run reads, and what it is to the run. */
    private record Input(Path file, String what) {
    }

    /** An output in messages: a file the user named ({@code file} null) or one the command writes into a folder. */
    private record Who(String flag, Path given, Path file) {
        /** How a message about this output starts: "--dump X: " or "--out D: D/frame-00001.png ". */
        String prefix() {
            return flag + " " + given + ": " + (file == null ? "" : file + " ");
        }

        /** How another message names it: "--dump X" or "D/frame-00001.png, which --out writes". */
        String describe() {
            return file == null ? flag + " " + given : file + ", which " + flag + " writes";
        }
    }

    private final CommandLine cl;
    private final List<Group> groups = new ArrayList<>();
    private final List<Named> named = new ArrayList<>();
    private final List<Input> inputs = new ArrayList<>();
    /** Outputs by folder (real path, as far as it exists) and name: what to call each in a message. */
    private final Map<Path, Map<String, Who>> byPath = new HashMap<>();
    /** Outputs that exist, by file identity (device and inode). */
    private final Map<Object, Who> byIdentity = new HashMap<>();
    private final List<Path> imagesRead = new ArrayList<>();

    OutputPlan(CommandLine cl) {
        this.cl = cl;
    }

    /**
     * A file the run reads; no output may be it.
     *
     * @param what e.g. "the scene file this run reads"
     */
    OutputPlan input(Path file, String what) {
        inputs.add(new Input(file, what));
        return this;
    }

    /** A file the user named with {@code flag}; nothing to check when {@code file} is null (not given). */
    OutputPlan file(String flag, Path file) {
        if (file != null) {
            named.add(new Named(flag, file));
        }
        return this;
    }

    /** Files the command writes into the folder the user named with {@code flag} (made if missing). */
    OutputPlan filesIn(String flag, Path dir, Collection<String> names) {
        groups.add(new Group(flag, dir, dir, new LinkedHashSet<>(names), false));
        return this;
    }

    /**
     * Files the command writes into a folder of its own, {@code sub} inside the folder the user named
     * with {@code flag} (the bench's {@code charts}): that folder may not be a symbolic link either.
     */
    OutputPlan filesInSubfolder(String flag, Path dir, String sub, Collection<String> names) {
        groups.add(new Group(flag, dir, dir.resolve(sub), new LinkedHashSet<>(names), true));
        return this;
    }

    /**
     * Checks every output (see the class comment).
     *
     * @throws ParameterException naming the flag and the path, at the first problem
     */
    void check() {
        for (Group g : groups) {
            checkGroup(g);
        }
        for (Named n : named) {
            String problem = OutputFiles.problem(n.given());
            if (problem != null) {
                throw refused(n.flag() + " " + n.given() + ": " + problem + "; choose another file name");
            }
            Path abs = n.given().toAbsolutePath();
            Who me = new Who(n.flag(), n.given(), null);
            Who other = claim(canonical(abs.getParent()), abs.getFileName().toString(), me);
            if (other != null) {
                throw refused(me.prefix() + "is the same file as " + other.describe() + "; give each output its "
                        + "own file");
            }
            identify(abs, me);
        }
        for (Input in : inputs) {
            checkInput(in);
        }
    }

    /**
     * {@code images} with every image it reads recorded as an input of the run, relative paths
     * against {@code base} (the scene's folder).
     */
    ImageSource images(ImageSource images, Path base) {
        return path -> {
            byte[] bytes = images.read(path);
            imagesRead.add(base.resolve(path));
            return bytes;
        };
    }

    /**
     * After the scene was loaded through {@link #images}: no output may be an image it read.
     *
     * @throws ParameterException naming the flag, the path and the image
     */
    void checkImages() {
        for (Path image : imagesRead) {
            checkInput(new Input(image, "an image the scene reads (" + image + ")"));
        }
    }

    /**
     * Makes the missing folders of the outputs (as {@code mkdir -p}): call it once the scene was
     * accepted, never before.
     *
     * @throws ParameterException naming the flag and the folder that could not be made
     */
    void createFolders() {
        for (Group g : groups) {
            createFolder(g.flag() + " " + g.given(), g.subfolder() ? g.given() : g.dir());
        }
        for (Named n : named) {
            createFolder(n.flag() + " " + n.given(), n.given().toAbsolutePath().getParent());
        }
    }

    private void createFolder(String who, Path dir) {
        try {
            Files.createDirectories(dir);
        } catch (IOException e) {
            throw refused(who + ": cannot make the folder " + dir + " (" + e.getMessage() + ")");
        }
    }

    private void checkGroup(Group g) {
        String me = g.flag() + " " + g.given() + ": " + (g.subfolder() ? g.dir() + " " : "");
        if (g.subfolder() && Files.isSymbolicLink(g.dir())) {
            throw refused(me + "is a symbolic link; files are never written through a link: remove it or "
                    + "choose another folder");
        }
        String folder = OutputFiles.folderProblem(g.dir());
        if (folder != null) {
            throw refused(me + folder + "; choose a folder you can write into");
        }
        Path dir = canonical(g.dir());
        for (String name : g.names()) {
            Who who = new Who(g.flag(), g.given(), g.dir().resolve(name));
            Who other = claim(dir, name, who);
            if (other != null) {
                throw refused(who.prefix() + "is also " + other.describe() + "; give each output its own file");
            }
        }
        if (!Files.isDirectory(g.dir())) {
            return; // nothing in it yet
        }
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(g.dir())) {
            for (Path entry : entries) {
                if (!g.names().contains(entry.getFileName().toString())) {
                    continue;
                }
                Who who = new Who(g.flag(), g.given(), entry);
                String problem = OutputFiles.problem(entry);
                if (problem != null) {
                    throw refused(who.prefix() + problem + "; remove it or choose another folder");
                }
                identify(entry, who);
            }
        } catch (IOException e) {
            throw refused(me + "cannot be listed (" + e.getMessage() + "); choose a folder you can read and write");
        }
    }

    /** Records an output at (folder, name); returns the output already there, or null. */
    private Who claim(Path dir, String name, Who me) {
        return byPath.computeIfAbsent(dir, d -> new HashMap<>()).putIfAbsent(name, me);
    }

    /** Records the identity of an output that exists (not following a link: links were refused). */
    private void identify(Path file, Who me) {
        try {
            Object key = Files.readAttributes(file, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS).fileKey();
            if (key != null) {
                byIdentity.putIfAbsent(key, me);
            }
        } catch (IOException e) {
            // a free name: it cannot be an input
        }
    }

    private void checkInput(Input in) {
        Who hit;
        try {
            Object key = Files.readAttributes(in.file(), BasicFileAttributes.class).fileKey();
            hit = key == null ? null : byIdentity.get(key);
        } catch (IOException e) {
            return; // an input that does not exist is not read by this run: nothing to protect
        }
        if (hit == null) {
            Path real = canonical(in.file());
            Map<String, Who> there = real.getParent() == null ? null : byPath.get(real.getParent());
            hit = there == null ? null : there.get(real.getFileName().toString());
        }
        if (hit != null) {
            throw refused(hit.prefix() + "is " + in.what() + "; outputs never replace an input: choose another "
                    + (hit.file() == null ? "file name" : "folder"));
        }
    }

    private ParameterException refused(String message) {
        return new ParameterException(cl, message);
    }

    /** {@code p} absolute, with every link of its existing part resolved and the missing rest appended. */
    static Path canonical(Path p) {
        Path abs = p.toAbsolutePath().normalize();
        Path tail = null;
        for (Path cur = abs; cur != null; cur = cur.getParent()) {
            try {
                Path real = cur.toRealPath();
                return tail == null ? real : real.resolve(tail);
            } catch (IOException e) {
                Path name = cur.getFileName();
                if (name == null) {
                    break;
                }
                tail = tail == null ? name : name.resolve(tail);
            }
        }
        return abs;
    }
}
