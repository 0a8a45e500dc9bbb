package org.jecosys.scene;

/**
 * One problem found in a scene file: where it is and what is wrong. Immutable; any thread.
 *
 * @param file    the file name as given by the caller
 * @param line    1-based line, or 0 when the problem is about the file itself (not a regular file,
 *                too large, unreadable) and has no place inside it
 * @param column  1-based column, or 0 when the line is 0
 * @param message what is wrong and what is allowed
 */
public record SceneProblem(String file, int line, int column, String message) {
    /**
     * {@code FILE:LINE:COL: message}, the format every command prints; a problem about the file
     * itself (line 0) is {@code FILE: message}, located by its path only.
     */
    @Override
    public String toString() {
        return line < 1 ? file + ": " + message : file + ":" + line + ":" + column + ": " + message;
    }
}
