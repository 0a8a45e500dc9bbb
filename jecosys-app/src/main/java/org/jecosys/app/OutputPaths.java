package org.jecosys.app;

import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;

/**
 * Checks of output paths given on the command line, made before any work starts, so that a run of
 * minutes never ends in "cannot write". A problem is bad input (exit 2) naming the flag and path.
 */
final class OutputPaths {
    private OutputPaths() {
    }

    /**
     * A file the command will write: not a folder, writable; a missing folder for it is checked like
     * {@link #folder} and made now (as {@code mkdir -p} would), so the write at the end finds it.
     * Nothing to check when {@code file} is null (an optional flag not given).
     */
    static void file(CommandLine cl, String flag, Path file) {
        if (file == null) {
            return; // the flag was not given
        }
        Path abs = file.toAbsolutePath().normalize();
        if (Files.isDirectory(abs)) {
            throw new ParameterException(cl, flag + " " + file + ": is a folder; give a file name");
        }
        if (Files.exists(abs)) {
            if (!Files.isWritable(abs)) {
                throw new ParameterException(cl, flag + " " + file + ": cannot write it (permission denied)");
            }
            return;
        }
        Path parent = abs.getParent();
        if (parent == null) {
            throw new ParameterException(cl, flag + " " + file + ": cannot write it");
        }
        if (!Files.exists(parent)) {
            folder(cl, flag, parent);
            try {
                Files.createDirectories(parent);
            } catch (java.io.IOException e) {
                throw new ParameterException(cl, flag + " " + file + ": cannot create its folder " + parent + ": "
                        + e.getMessage());
            }
        }
        if (!Files.isDirectory(parent)) {
            throw new ParameterException(cl, flag + " " + file + ": cannot write it: " + parent + " is not a folder");
        }
        if (!Files.isWritable(parent)) {
            throw new ParameterException(cl, flag + " " + file + ": cannot create files in " + parent
                    + " (permission denied)");
        }
    }

    /** A folder the command will create if missing and write files into. */
    static void folder(CommandLine cl, String flag, Path dir) {
        Path abs = dir.toAbsolutePath().normalize();
        if (Files.exists(abs)) {
            if (!Files.isDirectory(abs)) {
                throw new ParameterException(cl, flag + " " + dir + ": is a file, not a folder");
            }
            if (!Files.isWritable(abs)) {
                throw new ParameterException(cl, flag + " " + dir + ": cannot write into it (permission denied)");
            }
            return;
        }
        Path p = abs.getParent();
        while (p != null && !Files.exists(p)) {
            p = p.getParent();
        }
        if (p == null) {
            throw new ParameterException(cl, flag + " " + dir + ": cannot create it");
        }
        if (!Files.isDirectory(p)) {
            throw new ParameterException(cl, flag + " " + dir + ": cannot create it: " + p + " is a file");
        }
        if (!Files.isWritable(p)) {
            throw new ParameterException(cl, flag + " " + dir + ": cannot create it in " + p + " (permission denied)");
        }
    }
}
