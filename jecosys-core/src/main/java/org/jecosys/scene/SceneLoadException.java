package org.jecosys.scene;

import java.util.List;

/**
 * The scene loader's only error type: the file was not loaded, and these are the reasons, each
 * with {@code FILE:LINE:COL}. Nothing of a failed file is returned (no half-loaded scene).
 */
public final class SceneLoadException extends Exception {
    private static final long serialVersionUID = 1L;
    private final transient List<SceneProblem> problems;

    /** A failure with at least one problem. */
    public SceneLoadException(List<SceneProblem> problems) {
        super(format(problems));
        if (problems.isEmpty()) {
            throw new IllegalArgumentException("problems must not be empty");
        }
        this.problems = List.copyOf(problems);
    }

    /** A failure with one problem. */
    public SceneLoadException(SceneProblem problem) {
        this(List.of(problem));
    }

    /** The problems, in file order, at least one. */
    public List<SceneProblem> problems() {
        return problems;
    }

    private static String format(List<SceneProblem> problems) {
        StringBuilder sb = new StringBuilder();
        for (SceneProblem p : problems) {
            if (sb.length() > 0) {
                sb.append('\n');
            }
            sb.append(p);
        }
        return sb.toString();
    }
}
