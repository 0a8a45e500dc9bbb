package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Issue 42, "no stall in a frame", as an audit of the renderer's sources: every GL entry point that makes
 * the CPU wait for the GPU (finishing, reading pixels, buffers or textures back, a query's result, a
 * fence wait, mapping a buffer) appears only where it is meant to wait and is never reached from a
 * frame: the read-back of a picture ({@code Pixels}, the caller's), {@code GlContext.finish} (the
 * caller's), the bench's work counter ({@code GpuWork}, documented as waiting), the component records'
 * read-back for tests ({@code ComponentResolver.readRecords}), and the pass timer, whose query results
 * are read only after {@code GL_QUERY_RESULT_AVAILABLE} says so and whose {@code glFinish} is the
 * software rasteriser's diagnostic, and the upload ring ({@code GlUploadRing}), which maps its buffer once at
 * construction and polls a region's fence with a zero timeout (waiting, counted, only when the GPU is
 * more than two frames behind). A new call anywhere else fails this test with its file and line.
 */
class BlockingCallsTest {
    private static final Pattern BLOCKING = Pattern.compile("\\b(glFinish|glReadPixels|glGetQueryObject\\w*|"
            + "glGetBufferSubData|glMapBuffer\\w*|glClientWaitSync|glWaitSync|glGetTexImage|glGetCompressedTexImage|"
            + "glGetTextureImage|glGetNamedBufferSubData)\\s*\\(");
    /** Where a waiting call is meant, by file, with the calls allowed there. */
    private static final Map<String, String> ALLOWED = Map.of(
            "gl/Pixels.java", "glReadPixels",
            "GlContext.java", "glFinish",
            "GpuWork.java", "glGetQueryObjectui64",
            "plant/ComponentResolver.java", "glGetBufferSubData",
            "GpuPassTimer.java", "glFinish glGetQueryObjectui64v",
            "gl/GlUploadRing.java", "glMapBufferRange glClientWaitSync");

    @Test
    void onlyTheCallsMeantToWaitWait() throws IOException {
        Path root = Path.of("jecosys-render/src/main/java/org/jecosys/render");
        List<String> found = new ArrayList<>();
        int allowed = 0;
        try (Stream<Path> files = Files.walk(root)) {
            for (Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".java"))::iterator) {
                String rel = root.relativize(f).toString().replace('\\', '/');
                List<String> lines = Files.readAllLines(f);
                for (int i = 0; i < lines.size(); i++) {
                    String line = lines.get(i).strip();
                    if (line.startsWith("*") || line.startsWith("//") || line.startsWith("/*")) {
                        continue;
                    }
                    Matcher m = BLOCKING.matcher(line);
                    while (m.find()) {
                        String meant = ALLOWED.get(rel);
                        if (meant != null && List.of(meant.split(" ")).contains(m.group(1))) {
                            allowed++;
                        } else {
                            found.add(rel + ":" + (i + 1) + ": " + m.group(1));
                        }
                    }
                }
            }
        }
        assertTrue(allowed >= 5, "the audit finds the calls it allows: " + allowed);
        assertEquals(List.of(), found, "calls that wait for the GPU outside the places meant for it");
    }
}
