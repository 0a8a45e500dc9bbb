package org.jecosys.field;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** DESIGN.md: wind may import only math (and JOML); field only wind and math; math nothing of ours. */
class DependencyRuleTest {

    private static List<String> violations(String pkg, List<String> allowed) throws IOException {
        Path dir = Path.of("src", "main", "java", "org", "jecosys", pkg);
        List<String> bad = new ArrayList<>();
        try (Stream<Path> files = Files.list(dir)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".java")).toList()) {
                for (String line : Files.readAllLines(f)) {
                    String l = line.trim();
                    if (l.contains("org.lwjgl") || l.contains("com.fasterxml")) {
                        bad.add(f + ": " + l);
                    }
                    if (l.startsWith("import org.jecosys.")) {
                        String target = l.substring("import org.jecosys.".length()).split("\\.")[0];
                        if (!target.equals(pkg) && !allowed.contains(target)) {
                            bad.add(f + ": " + l);
                        }
                    }
                }
            }
        }
        return bad;
    }

    @Test
    void packagesImportOnlyDownward() throws IOException {
        List<String> bad = new ArrayList<>();
        bad.addAll(violations("wind", List.of("math")));
        bad.addAll(violations("field", List.of("wind", "math")));
        bad.addAll(violations("math", List.of()));
        assertTrue(bad.isEmpty(), String.join("\n", bad));
    }
}
