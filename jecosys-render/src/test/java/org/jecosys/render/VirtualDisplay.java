package org.jecosys.render;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * A virtual X display (Xvfb) for tests of programs that need a window: the engine examples, whose
 * engines open GLFW windows on X11. {@link #start} runs {@code Xvfb -displayfd 1 -screen 0 WxHx24
 * -nolisten tcp}, which takes the first free display number itself and prints it once it accepts
 * connections; {@link #close} stops it. One per test class ({@code @BeforeAll} / {@code @AfterAll}).
 * Fails with the reason and the install command when Xvfb is not installed.
 */
public final class VirtualDisplay implements AutoCloseable {
    private static final long START_SECONDS = 20;
    private final Process process;
    private final String name;
    private final Path log;

    private VirtualDisplay(Process process, String name, Path log) {
        this.process = process;
        this.name = name;
        this.log = log;
    }

    /**
     * Starts a virtual display of one screen.
     *
     * @param width  screen width, pixels
     * @param height screen height, pixels
     * @return the display, accepting connections
     * @throws IllegalStateException when Xvfb is missing, or does not start within 20 s
     * @throws IOException           when it cannot be run
     */
    public static VirtualDisplay start(int width, int height) throws IOException {
        Path xvfb = find();
        Path log = Files.createTempFile("xvfb-", ".log");
        Process p = new ProcessBuilder(xvfb.toString(), "-displayfd", "1", "-screen", "0",
                width + "x" + height + "x24", "-nolisten", "tcp")
                .redirectError(log.toFile())
                .start();
        CompletableFuture<String> number = CompletableFuture.supplyAsync(() -> {
            // not closed here: Xvfb keeps its standard output, which it is stopped with
            BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.US_ASCII));
            try {
                return r.readLine(); // the display number, once Xvfb listens
            } catch (IOException e) {
                return null;
            }
        });
        String n;
        try {
            n = number.get(START_SECONDS, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            n = null;
        } catch (ExecutionException | TimeoutException e) {
            n = null;
        }
        if (n == null || !n.trim().matches("\\d+")) {
            p.destroyForcibly();
            throw new IllegalStateException("Xvfb did not start within " + START_SECONDS + " s: "
                    + Files.readString(log, StandardCharsets.UTF_8).strip());
        }
        return new VirtualDisplay(p, ":" + n.trim(), log);
    }

    private static Path find() {
        String path = System.getenv("PATH");
        if (path != null) {
            for (String dir : path.split(java.io.File.pathSeparator)) {
                Path f = Path.of(dir, "Xvfb");
                if (Files.isExecutable(f)) {
                    return f;
                }
            }
        }
        Path usual = Path.of("/usr/bin/Xvfb");
        if (Files.isExecutable(usual)) {
            return usual;
        }
        throw new IllegalStateException("Xvfb is not installed (these tests open engine windows on a virtual X "
                + "display): install Debian's xvfb package (apt-get install xvfb), as .ci/run does");
    }

    /** {@return the value for {@code DISPLAY}, e.g. ":1"} */
    public String name() {
        return name;
    }

    /** Stops the display and waits for it (at most 10 s; then it is killed). */
    @Override
    public void close() {
        process.destroy();
        try {
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
        }
        try {
            Files.deleteIfExists(log);
        } catch (IOException ignored) {
            // a temporary file
        }
    }
}
