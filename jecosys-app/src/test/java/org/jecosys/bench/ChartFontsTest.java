package org.jecosys.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A chart that cannot be drawn for want of fonts is skipped with one line, never failing its section. */
class ChartFontsTest {
    @Test
    void aFontFailureSkipsTheChartKeepsTheNumbersAndSaysWhichPackagesProvideFonts(@TempDir Path dir) throws Exception {
        Report r = new Report(dir, Mode.SMOKE);
        Table t = new Table("t", "A table", List.of("a", "b")).row("x", 1.0);
        r.add(t);
        // what OpenJDK throws on a server without fontconfig, as the cause of an AWT failure
        r.saveChart("a.png", png -> {
            throw new RuntimeException("chart", new InternalError("Fontconfig head is null, check your fonts or "
                    + "fonts configuration"));
        });
        r.saveChart("b.png", png -> png.write("drawn".getBytes(java.nio.charset.StandardCharsets.UTF_8)));
        assertEquals(List.of("a.png"), r.skippedCharts());
        r.write(1);
        String md = Files.readString(dir.resolve("tables.md"));
        assertTrue(md.contains("Charts not drawn (a.png)"), md);
        assertTrue(md.contains("apt-get install fontconfig fonts-dejavu-core"), md);
        assertTrue(md.contains("A table"), "the numbers are kept");
        assertTrue(md.contains("charts/b.png"), "charts that could be drawn are listed");
    }

    @Test
    void otherFailuresStillFail(@TempDir Path dir) {
        Report r = new Report(dir, Mode.SMOKE);
        assertThrows(IllegalStateException.class, () -> r.saveChart("c.png", png -> {
            throw new IllegalStateException("no data");
        }));
        assertFalse(Report.isFontProblem(new IllegalArgumentException("series 'x' has no values")));
        assertTrue(Report.isFontProblem(new NullPointerException() {
            @Override
            public StackTraceElement[] getStackTrace() {
                return new StackTraceElement[] {new StackTraceElement("sun.font.FontManagerFactory", "getInstance",
                        "FontManagerFactory.java", 1)};
            }
        }));
    }
}
