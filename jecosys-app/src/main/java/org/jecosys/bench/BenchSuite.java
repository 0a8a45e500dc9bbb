package org.jecosys.bench;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Runs the benchmark sections that reproduce the paper's tables (section 5.2) and writes the
 * report. Prints one progress line per section to {@code progress}. One thread.
 */
public final class BenchSuite {
    private final List<Section> sections = new ArrayList<>();

    /** The standard suite over the scenes in {@code scenes}. */
    public static BenchSuite standard(Path scenes) {
        return standard(scenes, null);
    }

    /**
     * The standard suite over the scenes in {@code scenes}, the render-scale and render-pass sections
     * drawing at {@code quality} (null: each scene's own thinning); the other sections measure the
     * paper's tables and do not draw.
     */
    public static BenchSuite standard(Path scenes, org.jecosys.sim.DrawQuality quality) {
        BenchSuite s = new BenchSuite();
        s.add(new ModelSection(scenes));
        s.add(new PrecomputeSection(scenes));
        s.add(new FieldScaleSection());
        s.add(new PaperScenesSection(scenes));
        s.add(new ScaleSection(scenes));
        s.add(new RenderScaleSection(scenes, quality));
        s.add(new TextureSection(scenes));
        s.add(new RenderPassSection(scenes, quality));
        s.add(new StreamingSection());
        s.add(new OpenWorldSection(scenes));
        return s;
    }

    public BenchSuite add(Section section) {
        sections.add(section);
        return this;
    }

    public List<Section> sections() {
        return sections;
    }

    /** {@return the chart files the sections may write into {@code charts/}, in order, without repeats} */
    public List<String> charts() {
        java.util.LinkedHashSet<String> names = new java.util.LinkedHashSet<>();
        for (Section s : sections) {
            names.addAll(s.charts());
        }
        return List.copyOf(names);
    }

    /**
     * Runs every section, then writes tables.md, results.json and charts into {@code out}.
     *
     * @return the report (sections that threw are listed in {@link Report#failures()})
     */
    public Report run(Mode mode, Path out, PrintStream progress) throws IOException {
        Report report = new Report(out, mode, charts());
        long start = System.nanoTime();
        for (int i = 0; i < sections.size(); i++) {
            Section s = sections.get(i);
            long t0 = System.nanoTime();
            progress.printf("bench: [%d/%d] %s ...%n", i + 1, sections.size(), s.name());
            try {
                s.run(mode, report);
                progress.printf("bench: [%d/%d] %s done in %.1f s%n", i + 1, sections.size(), s.name(),
                        (System.nanoTime() - t0) / 1e9);
            } catch (Exception | OutOfMemoryError e) {
                report.failure(s.name(), e);
                progress.printf("bench: [%d/%d] %s FAILED: %s%n", i + 1, sections.size(), s.name(), e);
            }
        }
        report.write((System.nanoTime() - start) / 1e9);
        return report;
    }
}
