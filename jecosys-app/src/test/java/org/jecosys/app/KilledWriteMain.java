package org.jecosys.app;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.scene.AtomicFiles;
import org.jecosys.scene.OutputFiles;

/**
 * Run in a child JVM by {@link CliReliabilityTest}: starts a write of {@code args[0]}, writes a
 * megabyte, says so on stdout, and waits to be killed. {@code args[1]} picks the writer: {@code atomic}
 * ({@link AtomicFiles}, as scene saves write), {@code output} ({@link OutputFiles} from a stream, as
 * {@code --dump}, {@code --json}, {@code --gif} and the bench's reports are written) or
 * {@code output-file} ({@link OutputFiles} by the temporary file's path, as frames and maps are written).
 */
public final class KilledWriteMain {
    private KilledWriteMain() {
    }

    public static void main(String[] args) throws Exception {
        Path target = Path.of(args[0]);
        String writer = args.length > 1 ? args[1] : "atomic";
        switch (writer) {
            case "atomic" -> AtomicFiles.write(target, "write", KilledWriteMain::writeAndWait);
            case "output" -> new OutputFiles().write(target, KilledWriteMain::writeAndWait);
            case "output-file" -> new OutputFiles().writeFile(target, temporary -> {
                try (OutputStream out = Files.newOutputStream(temporary)) {
                    writeAndWait(out);
                }
            });
            default -> throw new IllegalArgumentException("writer: atomic, output or output-file, got " + writer);
        }
    }

    private static void writeAndWait(OutputStream out) throws IOException {
        out.write(new byte[1 << 20]);
        out.flush();
        System.out.println("writing");
        System.out.flush();
        try {
            Thread.sleep(600_000);
        } catch (InterruptedException e) {
            throw new java.io.InterruptedIOException("interrupted");
        }
    }
}
