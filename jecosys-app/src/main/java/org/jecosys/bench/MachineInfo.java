package org.jecosys.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** What a benchmark ran on: CPU model, cores, memory, OS, JVM, and the GL renderer when known. */
public record MachineInfo(String cpu, int cores, long maxHeapBytes, String os, String jvm, String glRenderer) {
    /** This machine; {@code glRenderer} is the GL_RENDERER string of a context, or null. */
    public static MachineInfo current(String glRenderer) {
        String cpu = "unknown";
        try {
            List<String> lines = Files.readAllLines(Path.of("/proc/cpuinfo"));
            for (String l : lines) {
                if (l.startsWith("model name")) {
                    cpu = l.substring(l.indexOf(':') + 1).strip();
                    break;
                }
            }
        } catch (IOException | RuntimeException e) {
            cpu = System.getProperty("os.arch");
        }
        String os = System.getProperty("os.name") + " " + System.getProperty("os.version") + " ("
                + System.getProperty("os.arch") + ")";
        String jvm = System.getProperty("java.vm.name") + " " + System.getProperty("java.runtime.version") + " ("
                + System.getProperty("java.vendor") + ")";
        return new MachineInfo(cpu, Runtime.getRuntime().availableProcessors(), Runtime.getRuntime().maxMemory(), os,
                jvm, glRenderer);
    }

    /** As a JSON-ready map. */
    public Map<String, Object> toMap() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("cpu", cpu);
        m.put("cores", cores);
        m.put("maxHeapMiB", maxHeapBytes / (1024 * 1024));
        m.put("os", os);
        m.put("jvm", jvm);
        m.put("glRenderer", glRenderer);
        return m;
    }

    /** As Markdown lines. */
    public String toMarkdown() {
        return "- CPU: " + cpu + ", " + cores + " cores available to the JVM\n"
                + "- JVM: " + jvm + ", max heap " + maxHeapBytes / (1024 * 1024) + " MiB\n"
                + "- OS: " + os + "\n"
                + "- GL renderer: " + (glRenderer == null ? "not used in this run" : glRenderer) + "\n";
    }
}
