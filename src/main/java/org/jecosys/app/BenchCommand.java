package org.jecosys.app;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code jecosys bench}: the headless benchmarks that reproduce the paper's Tables 1-7. */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = {"Run the benchmarks that reproduce the paper's tables and write tables.md, results.json "
                + "and PNG charts."})
final class BenchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;
    @Mixin
    Verbose verbose;
    @Option(names = "--quick", description = "A short run (about 3 minutes on 2 cores).")
    boolean quick;
    @Option(names = "--out", paramLabel = "DIR", defaultValue = "bench-results",
            description = "Output folder (default: ${DEFAULT-VALUE}).")
    Path out;

    @Override
    public Integer call() {
        return Unavailable.say(spec.commandLine().getErr(), "bench", "the benchmark suite");
    }
}
