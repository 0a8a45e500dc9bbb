package org.jecosys.bench;

import java.util.List;

/** One part of the benchmark suite: it measures, then adds tables and charts to the report. */
public interface Section {
    /** A short name for the progress line. */
    String name();

    /**
     * Runs the section.
     *
     * @param mode   how long it may take
     * @param report where tables, raw numbers and charts go
     * @throws Exception on any failure; the suite reports it and carries on with the next section
     */
    void run(Mode mode, Report report) throws Exception;

    /**
     * The chart files this section may write into {@code charts/} ({@link Report#saveChart}), so that
     * the command line can check their paths before the run. Any thread; allocates.
     *
     * @return file names, e.g. {@code table1.png}; none by default
     */
    default List<String> charts() {
        return List.of();
    }
}
