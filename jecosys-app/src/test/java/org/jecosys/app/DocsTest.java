package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The README is a front page and the documentation holds together: README.md at most 220 lines;
 * every relative link of README.md, CHANGELOG.md and docs/*.md names a file or folder that exists
 * (and, with a {@code #fragment} into a Markdown file, a heading there); the pages the README
 * promises exist, and each engine guide gives Maven and Gradle. Tests run in the repository's root.
 */
class DocsTest {
    /** [label](target) and ![alt](target), target without spaces; code fences are skipped. */
    private static final Pattern LINK = Pattern.compile("!?\\[[^\\]]*\\]\\(([^)\\s]+)\\)");

    @Test
    void theReadmeIsAFrontPage() throws IOException {
        List<String> lines = Files.readAllLines(Path.of("README.md"), StandardCharsets.UTF_8);
        assertTrue(lines.size() <= 220, "README.md has " + lines.size() + " lines; at most 220 (the rest goes to docs/)");
        String text = String.join("\n", lines);
        for (String must : new String[] {"./jecosys", "mvn -B verify", "SceneRenderer", "docs/cli.md",
                "docs/viewer.md", "docs/scene-format.md", "docs/lwjgl.md", "docs/libgdx.md", "docs/jme.md",
                "docs/performance.md"}) {
            assertTrue(text.contains(must), "README.md names " + must);
        }
    }

    @Test
    void everyPageItPromisesExistsAndEachEngineGuideGivesMavenAndGradle() throws IOException {
        for (String page : new String[] {"cli", "viewer", "scene-format", "embedding", "lwjgl", "libgdx", "jme",
                "performance", "building", "ARCHITECTURE"}) {
            assertTrue(Files.isRegularFile(Path.of("docs", page + ".md")), "docs/" + page + ".md");
        }
        for (String guide : new String[] {"libgdx", "jme"}) {
            String text = Files.readString(Path.of("docs", guide + ".md"), StandardCharsets.UTF_8);
            assertTrue(text.contains("## Maven") && text.contains("```xml"), "docs/" + guide + ".md: a Maven section");
            assertTrue(text.contains("## Gradle") && text.contains("```groovy"), "docs/" + guide + ".md: a Gradle section");
        }
    }

    @Test
    void everyRelativeLinkResolves() throws IOException {
        List<Path> pages = new ArrayList<>();
        pages.add(Path.of("README.md"));
        if (Files.exists(Path.of("CHANGELOG.md"))) {
            pages.add(Path.of("CHANGELOG.md"));
        }
        try (Stream<Path> docs = Files.list(Path.of("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(pages::add);
        }
        List<String> broken = new ArrayList<>();
        int checked = 0;
        for (Path page : pages) {
            for (String target : links(page)) {
                if (target.matches("^[a-zA-Z][a-zA-Z0-9+.-]*:.*")) {
                    continue; // https:, mailto: ...
                }
                checked++;
                String file = target;
                String fragment = null;
                int hash = target.indexOf('#');
                if (hash >= 0) {
                    file = target.substring(0, hash);
                    fragment = target.substring(hash + 1);
                }
                Path resolved = file.isEmpty() ? page : page.toAbsolutePath().getParent().resolve(file).normalize();
                if (!Files.exists(resolved)) {
                    broken.add(page + ": " + target + " (no such file)");
                } else if (fragment != null && resolved.toString().endsWith(".md")
                        && !anchors(resolved).contains(fragment)) {
                    broken.add(page + ": " + target + " (no such heading)");
                }
            }
        }
        assertTrue(checked > 30, "links checked: " + checked);
        assertTrue(broken.isEmpty(), "broken links:\n" + String.join("\n", broken));
    }

    /** The link targets of a Markdown page, outside code fences. */
    private static List<String> links(Path page) throws IOException {
        List<String> out = new ArrayList<>();
        boolean fence = false;
        for (String line : Files.readAllLines(page, StandardCharsets.UTF_8)) {
            if (line.startsWith("```")) {
                fence = !fence;
                continue;
            }
            if (fence) {
                continue;
            }
            Matcher m = LINK.matcher(line);
            while (m.find()) {
                out.add(m.group(1));
            }
        }
        return out;
    }

    /** GitHub's heading anchors of a Markdown page: lower case, punctuation dropped, spaces to hyphens. */
    private static Set<String> anchors(Path page) throws IOException {
        Set<String> out = new HashSet<>();
        for (String line : Files.readAllLines(page, StandardCharsets.UTF_8)) {
            if (line.matches("^#{1,6} .*")) {
                String title = line.replaceFirst("^#{1,6} ", "").trim().toLowerCase(Locale.ROOT);
                out.add(title.replaceAll("[^\\p{L}\\p{N} _-]", "").replace(' ', '-'));
            }
        }
        return out;
    }
}
