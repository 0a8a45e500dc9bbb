package org.jecosys.math;

/**
 * Receives progress of a long generation step (terrain, distribution, pose tables). Called on the
 * thread doing the work; implementations must be cheap. The application shows a console bar.
 */
@FunctionalInterface
public interface Progress {
    /** A listener that ignores everything. */
    Progress NONE = (step, done, total) -> { };

    /**
     * Reports that {@code done} of {@code total} units of {@code step} are finished.
     *
     * @param step  a short name of the step, e.g. "terrain"
     * @param done  units finished, in [0, total]
     * @param total units in all, &gt; 0
     */
    void report(String step, long done, long total);
}
