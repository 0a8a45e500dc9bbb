package org.jecosys.scene;

import java.util.List;

/**
 * The scene loader's only error type: the file was not loaded, and these are the reasons, each
 * with {@code FILE:LINE:COL}. Nothing of a failed file is returned (no half-loaded scene).
 */
public final class SceneLoadException extends Exception {
    private static final long serialVersionUID = 1L;
    private final transient List<SceneProblem> problems;

    /**
     * A failure with at least one problem.
     *
     * @param problems the reasons, in file order, not empty (copied)
     * @throws IllegalArgumentException when {@code problems} is empty
     */
    public SceneLoadException(List<SceneProblem> problems) {
        super(format(problems));
        if (problems.isEmpty()) {
            throw new IllegalArgumentException("problems must not be empty");
        }
        this.problems = List.copyOf(problems);
    }

    /**
     * A failure with one problem.
     *
     * @param problem the reason
     */
    public SceneLoadException(SceneProblem problem) {
        this(List.of(problem));
    }

    /** {@return the problems, in file order, at least one (unmodifiable)} */
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
