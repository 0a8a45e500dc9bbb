package org.jecosys;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** The package rules of DESIGN.md, checked on the sources' import lines. */
class ArchitectureTest {
    private static final Path MAIN = Path.of("src/main/java/org/jecosys");
    private static final Pattern IMPORT = Pattern.compile("^import\\s+(static\\s+)?([\\w.]+)", Pattern.MULTILINE);

    /** For each package, the org.jecosys packages it may import (DESIGN.md, "Packages"). */
    private static final Map<String, Set<String>> ALLOWED = Map.ofEntries(
            Map.entry("math", Set.of()),
            Map.entry("wind", Set.of("math")),
            Map.entry("plant", Set.of("math")),
            Map.entry("terrain", Set.of("plant", "math")),
            Map.entry("field", Set.of("wind", "math")),
            Map.entry("anim", Set.of("field", "plant", "math")),
            Map.entry("sim", Set.of("anim", "field", "wind", "plant", "terrain", "math")),
            Map.entry("scene", Set.of("anim", "field", "wind", "plant", "terrain", "math", "sim")),
            Map.entry("render", Set.of("sim", "plant", "field", "terrain", "math")),
            Map.entry("bench", Set.of("sim", "scene", "render", "anim", "field", "wind", "plant", "terrain", "math")),
            Map.entry("app", Set.of("render", "bench", "scene", "sim", "anim", "field", "wind", "plant", "terrain",
                    "math")));

    record Import(Path file, String pkg, String imported) {
    }

    static List<Import> imports() throws IOException {
        List<Import> out = new ArrayList<>();
        try (Stream<Path> files = Files.walk(MAIN)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".java")).toList()) {
                String pkg = MAIN.relativize(f).getName(0).toString();
                Matcher m = IMPORT.matcher(Files.readString(f, StandardCharsets.UTF_8));
                while (m.find()) {
                    out.add(new Import(f, pkg, m.group(2)));
                }
            }
        }
        return out;
    }

    @Test
    void lwjglOnlyInRenderAndApp() throws IOException {
        List<String> bad = new ArrayList<>();
        for (Import i : imports()) {
            if (i.imported().startsWith("org.lwjgl") || i.imported().startsWith("imgui")) {
                if (!i.pkg().equals("render") && !i.pkg().equals("app")) {
                    bad.add(i.file() + " imports " + i.imported());
                }
            }
        }
        assertEquals(List.of(), bad);
    }

    @Test
    void jacksonOnlyInScene() throws IOException {
        List<String> bad = new ArrayList<>();
        for (Import i : imports()) {
            if (i.imported().startsWith("com.fasterxml") && !i.pkg().equals("scene")) {
                bad.add(i.file() + " imports " + i.imported());
            }
        }
        assertEquals(List.of(), bad);
    }

    @Test
    void dependenciesPointDownward() throws IOException {
        List<String> bad = new ArrayList<>();
        for (Import i : imports()) {
            if (!i.imported().startsWith("org.jecosys.")) {
                continue;
            }
            String target = i.imported().substring("org.jecosys.".length()).split("\\.")[0];
            Set<String> allowed = ALLOWED.get(i.pkg());
            assertTrue(allowed != null, "unknown package " + i.pkg());
            if (!target.equals(i.pkg()) && !allowed.contains(target)) {
                bad.add(i.file() + " (" + i.pkg() + ") imports " + i.imported());
            }
        }
        assertEquals(List.of(), bad);
    }

    @Test
    void theRuleCatchesAViolation() {
        Matcher m = IMPORT.matcher("package x;\nimport org.lwjgl.opengl.GL11;\nimport static org.joml.Math.sin;\n");
        List<String> found = new ArrayList<>();
        while (m.find()) {
            found.add(m.group(2));
        }
        assertEquals(List.of("org.lwjgl.opengl.GL11", "org.joml.Math.sin"), found);
    }
}
