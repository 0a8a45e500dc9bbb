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
    /** The files the bench writes into its folder, beside {@code charts/}. */
    static final java.util.List<String> REPORT_FILES = java.util.List.of("tables.md", "results.json");

    @Spec
    CommandSpec spec;
    @Mixin
    Verbose verbose;
    @Option(names = "--quick", description = "A short run (about 40 s on 2 cores; the full run takes about 5 minutes).")
    boolean quick;
    @Option(names = "--out", paramLabel = "DIR", defaultValue = "bench-results",
            description = "Output folder (default: ${DEFAULT-VALUE}); tables.md, results.json and charts/*.png "
                    + "in it are replaced, never through a link.")
    Path out;
    @Option(names = "--only", paramLabel = "WORD", description = "Run only the sections whose name contains WORD "
            + "(case-insensitive), e.g. --only \"render scale\".")
    String only;
    @Option(names = "--quality", paramLabel = "LEVEL", converter = QualityConverter.class,
            description = "For the render-scale section: " + QualityConverter.DESCRIPTION)
    org.jecosys.sim.DrawQuality quality;

    @Override
    public Integer call() throws IOException {
        Path scenes = SceneArgs.resolve("scenes");
        BenchSuite suite = BenchSuite.standard(scenes, quality);
        if (only != null) {
            java.util.List<String> names = new java.util.ArrayList<>();
            suite.sections().forEach(sec -> names.add(sec.name()));
            suite.sections().removeIf(sec -> !sec.name().toLowerCase(java.util.Locale.ROOT)
                    .contains(only.toLowerCase(java.util.Locale.ROOT)));
            if (suite.sections().isEmpty()) {
                spec.commandLine().getErr().println("bench: --only '" + only + "' matches no section; the sections "
                        + "are: " + String.join("; ", names));
                return ExitCodes.BAD_INPUT;
            }
        }
        OutputPlan plan = new OutputPlan(spec.commandLine())
                .filesIn("--out", out, REPORT_FILES)
                .filesInSubfolder("--out", out, "charts", suite.charts());
        try (java.util.stream.Stream<Path> files = java.nio.file.Files.list(scenes)) {
            files.filter(p -> p.getFileName().toString().endsWith(".xml"))
                    .forEach(p -> plan.input(p, "a scene file the bench reads"));
        } catch (IOException e) {
            // no scenes folder: the sections that need one fail and say so
        }
        plan.check();
        Report report = suite.run(quick ? Mode.QUICK : Mode.FULL, out, System.err);
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
