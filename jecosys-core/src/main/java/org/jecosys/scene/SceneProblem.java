package org.jecosys.scene;

/**
 * One problem found in a scene file: where it is and what is wrong. Immutable; any thread.
 *
 * @param file    the file name as given by the caller
 * @param line    1-based line, or 0 when unknown (e.g. an empty file)
 * @param column  1-based column, or 0 when unknown
 * @param message what is wrong and what is allowed
 */
public record SceneProblem(String file, int line, int column, String message) {
    /** {@code FILE:LINE:COL: message}, the format every command prints. */
    @Override
    public String toString() {
        return file + ":" + line + ":" + column + ": " + message;
    }
}
