package org.jecosys.render;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * Runs a main class in a child JVM on the test's own class path, with a time limit: for programs that
 * own their process (an engine's application loop, {@code System.exit}). Its standard output and
 * error go to one file, read when it has ended.
 */
public final class ChildJvm {
    private ChildJvm() {
    }

    /**
     * What a child JVM did.
     *
     * @param exitCode its exit status
     * @param output   its standard output and error, interleaved
     * @param seconds  how long it ran, wall clock
     */
    public record Result(int exitCode, String output, double seconds) {
    }

    /**
     * Runs {@code mainClass} with {@code args} and waits for it; a child that outlives
     * {@code timeoutSeconds} is killed and the test fails with what it printed.
     *
     * @param mainClass      the class to run
     * @param args           its arguments
     * @param environment    variables added to the test's environment (e.g. {@code DISPLAY})
     * @param timeoutSeconds the time limit
     * @return the result
     * @throws IOException          when the child cannot be started or its output read
     * @throws InterruptedException when the test is interrupted (the child is killed)
     */
    public static Result run(String mainClass, List<String> args, Map<String, String> environment,
                             long timeoutSeconds) throws IOException, InterruptedException {
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        List<String> command = new ArrayList<>();
        command.add(java.toString());
        command.add("-Xmx1g");
        command.add("-Djava.awt.headless=true");
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add(mainClass);
        command.addAll(args);
        Path out = Files.createTempFile("child-jvm-", ".log");
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(out.toFile());
        pb.environment().putAll(environment);
        long t0 = System.nanoTime();
        Process p = pb.start();
        try {
            if (!p.waitFor(timeoutSeconds, TimeUnit.SECONDS)) {
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
                throw new AssertionError(mainClass + " " + String.join(" ", args) + " did not end within "
                        + timeoutSeconds + " s and was killed; it printed:\n"
                        + Files.readString(out, StandardCharsets.UTF_8));
            }
            return new Result(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8),
                    (System.nanoTime() - t0) / 1e9);
        } finally {
            if (p.isAlive()) {
                p.destroyForcibly(); // the test was interrupted or failed
            }
            Files.deleteIfExists(out);
        }
    }
}
