package org.jecosys.bench;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.jecosys.scene.OutputFiles;

/**
 * The benchmark report being built: tables (Markdown and JSON), raw series, charts and failures,
 * written as {@code tables.md}, {@code results.json} and {@code charts/*.png} in one folder, each
 * through {@link OutputFiles} (atomic; never through a link, never onto a pipe or device; the
 * {@code charts} folder may not be a link either). Folders are made when the first file is written.
 * Used by one thread.
 */
public final class Report {
    private final Path dir;
    private final Mode mode;
    private final List<Table> tables = new ArrayList<>();
    private final Map<String, Object> raw = new LinkedHashMap<>();
    private final List<String> charts = new ArrayList<>();
    private final List<String> skippedCharts = new ArrayList<>();
    private final List<String> failures = new ArrayList<>();
    private final Set<String> declaredCharts;
    private final OutputFiles files = new OutputFiles();
    private String glRenderer;

    /**
     * A report into {@code dir} that may draw any chart. Allocates.
     *
     * @param dir  the folder of tables.md, results.json and charts/ (made when first written)
     * @param mode the run's length, for the report's text
     */
    public Report(Path dir, Mode mode) {
        this(dir, mode, null);
    }

    /**
     * A report into {@code dir} that draws only the charts declared (the sections' {@link Section#charts}),
     * the files the command line checked before the run. Allocates.
     *
     * @param dir    the folder of tables.md, results.json and charts/ (made when first written)
     * @param mode   the run's length, for the report's text
     * @param charts the chart file names allowed; null for any
     */
    public Report(Path dir, Mode mode, Collection<String> charts) {
        this.dir = dir;
        this.mode = mode;
        this.declaredCharts = charts == null ? null : Set.copyOf(charts);
    }

    /**
     * The folder charts go into, made if missing.
     *
     * @return {@code DIR/charts}
     * @throws IOException when it is a symbolic link (files are never written through a link) or cannot be made
     */
    public Path chartDir() throws IOException {
        Path charts = dir.resolve("charts");
        if (Files.isSymbolicLink(charts)) {
            throw new IOException("cannot write charts into " + charts + ": it is a symbolic link; files are never "
                    + "written through a link");
        }
        return Files.createDirectories(charts);
    }

    public void add(Table t) {
        tables.add(t);
    }

    /** Raw numbers under a key in results.json. */
    public void raw(String key, Object value) {
        raw.put(key, value);
    }

    /** Records a chart written to {@code charts/name}. */
    public void chart(String name) {
        charts.add(name);
    }

    /** Writes one chart into a PNG file. */
    @FunctionalInterface
    public interface ChartWriter {
        /**
         * Draws the chart as PNG into {@code png}.
         *
         * @param png the stream to write (held in memory, then written to the chart's file); do not close it
         * @throws IOException when it cannot be written
         */
        void write(OutputStream png) throws IOException;
    }

    /**
     * Draws chart {@code charts/name} and records it; on a machine without fonts (a headless server:
     * Java's AWT finds no fontconfig or no font) the chart is skipped instead, and the report says once
     * which packages provide fonts. The section's numbers are kept either way. Allocates.
     *
     * @param name   the chart's file name
     * @param writer draws it
     * @throws IOException when the file cannot be written for another reason
     */
    public void saveChart(String name, ChartWriter writer) throws IOException {
        if (declaredCharts != null && !declaredCharts.contains(name)) {
            throw new IllegalArgumentException("chart " + name + " is not among the charts its section declares "
                    + declaredCharts + " (Section.charts): declare it so that its path is checked before the run");
        }
        ByteArrayOutputStream png = new ByteArrayOutputStream(1 << 16);
        try {
            writer.write(png);
        } catch (RuntimeException | Error e) {
            if (!isFontProblem(e)) {
                throw e;
            }
            if (skippedCharts.isEmpty()) {
                System.err.println("bench: charts skipped: " + NO_FONTS);
            }
            skippedCharts.add(name);
            return;
        }
        files.write(chartDir().resolve(name), png::writeTo);
        charts.add(name);
    }

    /** What a machine without fonts lacks, and where to get it. */
    static final String NO_FONTS = "this machine has no fonts for Java's AWT (install fontconfig and a font, "
            + "e.g. on Debian/Ubuntu: apt-get install fontconfig fonts-dejavu-core); every number is in the tables";

    /** {@return the charts skipped because the machine has no fonts} */
    public List<String> skippedCharts() {
        return skippedCharts;
    }

    /**
     * {@return whether a failure to draw a chart comes from missing fonts (fontconfig, the font
     * manager or a font file), anywhere in its chain of causes}
     *
     * @param e the failure
     */
    static boolean isFontProblem(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            String m = String.valueOf(t.getMessage()).toLowerCase(java.util.Locale.ROOT);
            if (m.contains("fontconfig") || m.contains("font")) {
                return true;
            }
            for (StackTraceElement f : t.getStackTrace()) {
                String c = f.getClassName();
                if (c.startsWith("sun.font.") || c.startsWith("sun.awt.FontConfiguration")
                        || c.startsWith("sun.awt.X11FontManager") || c.startsWith("java.awt.Font")) {
                    return true;
                }
            }
        }
        return false;
    }

    public void failure(String section, Throwable t) {
        failures.add(section + ": " + (t.getMessage() == null ? t.toString() : t.getMessage()));
    }

    /** The GL_RENDERER of the rendering runs, for the machine description. */
    public void glRenderer(String renderer) {
        this.glRenderer = renderer;
    }

    public List<Table> tables() {
        return tables;
    }

    public List<String> failures() {
        return failures;
    }

    /**
     * Writes tables.md and results.json (see the class comment).
     *
     * @param seconds the run's length, for the report's text
     * @throws IOException naming the file that could not be written (it is then left as it was)
     */
    public void write(double seconds) throws IOException {
        MachineInfo machine = MachineInfo.current(glRenderer);
        StringBuilder md = new StringBuilder("# JEcoSys benchmark report\n\n");
        md.append("Paper: Endo, Morimoto, Fabris, CGI 2005, section 5.2 (Pentium III 900 MHz, Java 3D). ")
                .append(mode == Mode.FULL ? "Full run" : mode == Mode.QUICK ? "Quick run (--quick)" : "Smoke run (structure only)").append(", ")
                .append(String.format(java.util.Locale.ROOT, "%.0f", seconds)).append(" s.\n\n");
        md.append("## Machine\n\n").append(machine.toMarkdown()).append('\n');
        md.append("## Tables\n\n");
        for (Table t : tables) {
            md.append(t.toMarkdown());
        }
        if (!charts.isEmpty()) {
            md.append("## Charts\n\n");
            for (String c : charts) {
                md.append("![").append(c).append("](charts/").append(c).append(")\n\n");
            }
        }
        if (!skippedCharts.isEmpty()) {
            md.append("Charts not drawn (").append(String.join(", ", skippedCharts)).append("): ").append(NO_FONTS)
                    .append(".\n\n");
        }
        if (!failures.isEmpty()) {
            md.append("## Sections that failed\n\n");
            for (String f : failures) {
                md.append("- ").append(f).append('\n');
            }
        }
        byte[] tablesMd = md.toString().getBytes(StandardCharsets.UTF_8);
        files.write(dir.resolve("tables.md"), o -> o.write(tablesMd));
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("mode", mode.name().toLowerCase(java.util.Locale.ROOT));
        json.put("seconds", seconds);
        json.put("machine", machine.toMap());
        Map<String, Object> t = new LinkedHashMap<>();
        for (Table table : tables) {
            t.put(table.id(), table.toMap());
        }
        json.put("tables", t);
        json.put("raw", raw);
        json.put("charts", charts);
        json.put("failures", failures);
        byte[] results = Json.write(json).getBytes(StandardCharsets.UTF_8);
        files.write(dir.resolve("results.json"), o -> o.write(results));
    }
}
