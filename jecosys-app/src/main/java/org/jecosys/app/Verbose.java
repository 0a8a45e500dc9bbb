package org.jecosys.app;

import picocli.CommandLine.Option;

/** The {@code --verbose} flag shared by every command: show stack traces of failures. */
final class Verbose {
    @Option(names = "--verbose", description = "Print stack traces of failures.")
    boolean verbose;
}
