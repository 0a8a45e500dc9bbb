package org.jecosys;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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

/**
 * The package and module rules of docs/ARCHITECTURE.md, checked on the sources: every reference to a
 * package counts, whether it is an import or a fully qualified name in the code (comments and string
 * literals are left out, so a Javadoc link or a message may name any class).
 */
class ArchitectureTest {
    /** Each module's main sources, and the packages that live in it. */
    private static final Map<String, Set<String>> MODULES = Map.of(
            "jecosys-core", Set.of("math", "wind", "plant", "terrain", "world", "field", "anim", "sim", "scene"),
            "jecosys-render", Set.of("render"),
            "jecosys-gdx", Set.of("gdx"),
            "jecosys-jme", Set.of("jme"),
            "jecosys-app", Set.of("bench", "app"));

    /** For each package, the org.jecosys packages it may use (docs/ARCHITECTURE.md, "Packages"). */
    private static final Map<String, Set<String>> ALLOWED = Map.ofEntries(
            Map.entry("math", Set.of()),
            Map.entry("wind", Set.of("math")),
            Map.entry("plant", Set.of("math")),
            Map.entry("terrain", Set.of("plant", "math")),
            // the open world's placement, above terrain (its DistributionDef)
            Map.entry("world", Set.of("terrain", "plant", "math")),
            Map.entry("field", Set.of("wind", "math")),
            Map.entry("anim", Set.of("field", "plant", "math")),
            Map.entry("sim", Set.of("anim", "field", "wind", "plant", "terrain", "world", "math")),
            Map.entry("scene", Set.of("anim", "field", "wind", "plant", "terrain", "world", "math", "sim")),
            Map.entry("render", Set.of("scene", "sim", "anim", "plant", "field", "terrain", "world", "math")),
            // the engine adapters: thin, on top of the library a game uses (no LWJGL of their own)
            Map.entry("gdx", Set.of("render", "scene", "sim", "math", "terrain", "world", "wind", "plant", "field")),
            Map.entry("jme", Set.of("render", "scene", "sim", "math", "terrain", "world", "wind", "plant", "field")),
            Map.entry("bench", Set.of("sim", "scene", "render", "anim", "field", "wind", "plant", "terrain", "world",
                    "math")),
            Map.entry("app", Set.of("render", "bench", "scene", "sim", "anim", "field", "wind", "plant", "terrain",
                    "world", "math")));

    /** A dotted name that starts at a word boundary and is not itself part of a longer dotted name. */
    private static final Pattern QUALIFIED = Pattern.compile(
            "(?<![\\w.])((?:org\\.jecosys|org\\.lwjgl|com\\.fasterxml|imgui|picocli|org\\.knowm|com\\.badlogic|com\\.jme3)"
                    + "(?:\\.\\w+)+)");

    record Use(Path file, String pkg, String used) {
    }

    /** Removes comments, string and character literals and text blocks, keeping line structure. */
    static String codeOnly(String src) {
        StringBuilder out = new StringBuilder(src.length());
        int i = 0;
        int n = src.length();
        while (i < n) {
            char c = src.charAt(i);
            if (c == '/' && i + 1 < n && src.charAt(i + 1) == '/') {
                while (i < n && src.charAt(i) != '\n') {
                    i++;
                }
            } else if (c == '/' && i + 1 < n && src.charAt(i + 1) == '*') {
                int end = src.indexOf("*/", i + 2);
                i = end < 0 ? n : end + 2;
                out.append(' ');
            } else if (src.startsWith("\"\"\"", i)) {
                int end = src.indexOf("\"\"\"", i + 3);
                i = end < 0 ? n : end + 3;
                out.append("\"\"");
            } else if (c == '"' || c == '\'') {
                i++;
                while (i < n && src.charAt(i) != c) {
                    i += src.charAt(i) == '\\' ? 2 : 1;
                }
                i++;
                out.append(c).append(c);
            } else {
                out.append(c);
                i++;
            }
        }
        return out.toString();
    }

    static List<String> qualifiedNames(String src) {
        List<String> found = new ArrayList<>();
        Matcher m = QUALIFIED.matcher(codeOnly(src));
        while (m.find()) {
            found.add(m.group(1));
        }
        return found;
    }

    static List<Use> uses() throws IOException {
        List<Use> out = new ArrayList<>();
        for (Map.Entry<String, Set<String>> module : MODULES.entrySet()) {
            Path root = Path.of(module.getKey(), "src/main/java/org/jecosys");
            assertTrue(Files.isDirectory(root), root + " exists (tests run at the reactor's root)");
            try (Stream<Path> files = Files.walk(root)) {
                for (Path f : files.filter(p -> p.toString().endsWith(".java")).toList()) {
                    String pkg = root.relativize(f).getName(0).toString();
                    assertTrue(module.getValue().contains(pkg), f + ": package " + pkg + " does not belong in "
                            + module.getKey());
                    for (String name : qualifiedNames(Files.readString(f, StandardCharsets.UTF_8))) {
                        out.add(new Use(f, pkg, name));
                    }
                }
            }
        }
        assertFalse(out.isEmpty());
        return out;
    }

    @Test
    void lwjglOnlyInRenderAndApp() throws IOException {
        List<String> bad = new ArrayList<>();
        for (Use u : uses()) {
            if (u.used().startsWith("org.lwjgl") && !u.pkg().equals("render") && !u.pkg().equals("app")) {
                bad.add(u.file() + " uses " + u.used());
            }
        }
        assertEquals(List.of(), bad);
    }

    @Test
    void imguiPicocliAndChartsOnlyInTheApp() throws IOException {
        List<String> bad = new ArrayList<>();
        for (Use u : uses()) {
            boolean appOnly = u.used().startsWith("imgui") || u.used().startsWith("picocli")
                    || u.used().startsWith("org.knowm");
            if (appOnly && !u.pkg().equals("app") && !u.pkg().equals("bench")) {
                bad.add(u.file() + " uses " + u.used());
            }
        }
        assertEquals(List.of(), bad);
    }

    @Test
    void eachEngineOnlyInItsAdapter() throws IOException {
        List<String> bad = new ArrayList<>();
        for (Use u : uses()) {
            if (u.used().startsWith("com.badlogic") && !u.pkg().equals("gdx")
                    || u.used().startsWith("com.jme3") && !u.pkg().equals("jme")) {
                bad.add(u.file() + " uses " + u.used());
            }
        }
        assertEquals(List.of(), bad);
    }

    @Test
    void theAdaptersUseTheirEngines() throws IOException {
        // the scan reaches the adapters' sources (and would see an engine elsewhere)
        List<String> engines = new ArrayList<>();
        for (Use u : uses()) {
            if (u.used().startsWith("com.badlogic.gdx.") || u.used().startsWith("com.jme3.")) {
                engines.add(u.pkg() + ":" + u.used().split("\\.")[1]);
            }
        }
        assertTrue(engines.contains("gdx:badlogic") && engines.contains("jme:jme3"), engines.toString());
    }

    @Test
    void jacksonOnlyInScene() throws IOException {
        List<String> bad = new ArrayList<>();
        for (Use u : uses()) {
            if (u.used().startsWith("com.fasterxml") && !u.pkg().equals("scene")) {
                bad.add(u.file() + " uses " + u.used());
            }
        }
        assertEquals(List.of(), bad);
    }

    /**
     * Inside the render module: its sub-packages are internal and depend on the API package only for
     * its context and settings types, never on the renderer that composes them (except
     * {@code render.internal}, the friend accessor of its parts); {@code render.gl}
     * depends on no other part of the module; no two sub-packages depend on each other both ways.
     */
    @Test
    void renderSubPackagesPointIntoGlAndNeverBackToTheRenderer() throws IOException {
        Set<String> rootTypes = Set.of("GlContext", "RenderSettings", "Lighting", "OverlaySettings", "LwjglVersion",
                "ResolvePath");
        Path base = Path.of("jecosys-render/src/main/java/org/jecosys/render");
        List<String> bad = new ArrayList<>();
        java.util.Map<String, Set<String>> edges = new java.util.TreeMap<>();
        try (Stream<Path> files = Files.walk(base)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".java")).toList()) {
                Path rel = base.relativize(f);
                String sub = rel.getNameCount() > 1 ? rel.getName(0).toString() : "";
                for (String name : qualifiedNames(Files.readString(f, StandardCharsets.UTF_8))) {
                    if (!name.startsWith("org.jecosys.render.")) {
                        continue;
                    }
                    String[] parts = name.substring("org.jecosys.render.".length()).split("\\.");
                    boolean intoRoot = Character.isUpperCase(parts[0].charAt(0));
                    String target = intoRoot ? "" : parts[0];
                    if (sub.isEmpty() || target.equals(sub)) {
                        continue;
                    }
                    edges.computeIfAbsent(sub, k -> new java.util.TreeSet<>()).add(target.isEmpty() ? "render" : target);
                    if (intoRoot && !rootTypes.contains(parts[0]) && !sub.equals("internal")) {
                        bad.add(rel + " uses " + name + " (sub-packages use only " + rootTypes + " of render)");
                    }
                    if (sub.equals("gl") && !(intoRoot && rootTypes.contains(parts[0]))) {
                        bad.add(rel + " uses " + name + " (render.gl uses no other sub-package)");
                    }
                }
            }
        }
        for (var e : edges.entrySet()) {
            for (String t : e.getValue()) {
                if (edges.getOrDefault(t, Set.of()).contains(e.getKey())) {
                    bad.add("render." + e.getKey() + " and render." + t + " depend on each other");
                }
            }
        }
        assertTrue(edges.containsKey("plant") && edges.get("plant").contains("gl"), "the scan sees the module: " + edges);
        assertEquals(List.of(), bad);
    }

    @Test
    void dependenciesPointDownward() throws IOException {
        List<String> bad = new ArrayList<>();
        for (Use u : uses()) {
            if (!u.used().startsWith("org.jecosys.")) {
                continue;
            }
            String target = u.used().substring("org.jecosys.".length()).split("\\.")[0];
            Set<String> allowed = ALLOWED.get(u.pkg());
            assertTrue(allowed != null, "unknown package " + u.pkg());
            if (!target.equals(u.pkg()) && !allowed.contains(target)) {
                bad.add(u.file() + " (" + u.pkg() + ") uses " + u.used());
            }
        }
        assertEquals(List.of(), bad);
    }

    @Test
    void theScanSeesImportsAndFullyQualifiedNamesButNotCommentsOrStrings() {
        String src = "package x;\n"
                + "import org.lwjgl.opengl.GL11;\n"
                + "import static org.jecosys.math.Rng.next;\n"
                + "/** {@link org.jecosys.render.SceneRenderer} */\n"
                + "class A { // org.jecosys.app.Main\n"
                + "  Object o = new org.jecosys.render.gl.GlBuffer(\"org.jecosys.bench.X\", 'c');\n"
                + "  String t = \"\\\"org.jecosys.app.Y\";\n"
                + "  double d = org.jecosys.field.DragLaw.AIR_DENSITY;\n"
                + "  String s = my.org.jecosys.app.Z;\n"
                + "}\n";
        assertEquals(List.of("org.lwjgl.opengl.GL11", "org.jecosys.math.Rng.next", "org.jecosys.render.gl.GlBuffer",
                "org.jecosys.field.DragLaw.AIR_DENSITY"), qualifiedNames(src));
    }
}
