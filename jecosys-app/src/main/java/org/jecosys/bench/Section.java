package org.jecosys.bench;

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
}
