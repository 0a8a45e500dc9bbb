package org.jecosys.app;

import java.nio.file.Path;
import org.jecosys.scene.AtomicFiles;

/**
 * Run in a child JVM by {@link CliReliabilityTest}: starts an atomic write of {@code args[0]} (the way
 * {@code simulate --dump} writes), writes a megabyte, says so on stdout, and waits to be killed.
 */
public final class KilledWriteMain {
    private KilledWriteMain() {
    }

    public static void main(String[] args) throws Exception {
        AtomicFiles.write(Path.of(args[0]), "write", out -> {
            out.write(new byte[1 << 20]);
            out.flush();
            System.out.println("writing");
            System.out.flush();
            try {
                Thread.sleep(600_000);
            } catch (InterruptedException e) {
                throw new java.io.InterruptedIOException("interrupted");
            }
        });
    }
}
