package org.jecosys.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.jecosys.bench.BenchSuite;
import org.jecosys.bench.Mode;
import org.jecosys.bench.Report;
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
    @Option(names = "--quick", description = "A short run (about 40 s on 2 cores; the full run takes about 5 minutes).")
    boolean quick;
    @Option(names = "--out", paramLabel = "DIR", defaultValue = "bench-results",
            description = "Output folder (default: ${DEFAULT-VALUE}).")
    Path out;

    @Override
    public Integer call() throws IOException {
        Path scenes = SceneArgs.resolve("scenes");
        Report report = BenchSuite.standard(scenes).run(quick ? Mode.QUICK : Mode.FULL, out, System.err);
        var o = spec.commandLine().getOut();
        o.println("wrote " + out.resolve("tables.md") + ", " + out.resolve("results.json") + " and "
                + out.resolve("charts"));
        o.flush();
        if (!report.failures().isEmpty()) {
            spec.commandLine().getErr().println("bench: " + report.failures().size() + " section(s) failed: "
                    + report.failures());
            return ExitCodes.FAILURE;
        }
        return ExitCodes.OK;
    }
}
