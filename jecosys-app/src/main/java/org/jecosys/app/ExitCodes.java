package org.jecosys.app;

/** The exit codes of every {@code jecosys} command. */
final class ExitCodes {
    /** Success. */
    static final int OK = 0;
    /** A runtime failure (I/O, GL, out of memory). */
    static final int FAILURE = 1;
    /** Bad input: a flag or a scene file (picocli's usage-error code too). */
    static final int BAD_INPUT = 2;

    private ExitCodes() {
    }
}
