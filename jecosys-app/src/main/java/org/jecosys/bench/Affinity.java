package org.jecosys.bench;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * Pins threads to one core each, on Linux, for the bench's pinned walk (a game engine pins its workers
 * the same way), with the system's {@code taskset -p -c CORES TID}: no native code in the bench. A
 * thread is found by its name in {@code /proc/self/task/N/comm} (the kernel keeps the first 15
 * characters of a Java thread's name), the calling thread by {@code /proc/thread-self}. The cores the
 * process may use are read when this class is first used, before anything is pinned, to let threads go
 * again ({@code Runtime.availableProcessors()} counts the calling thread's cores, so it cannot tell once
 * the caller is pinned). Elsewhere, or without {@code taskset}, nothing is pinned and the methods say
 * so. Bench only; allocates, starts a process per thread.
 */
final class Affinity {
    private static final Path TASKSET = Path.of("/usr/bin/taskset");
    /** The process's cores as {@code taskset} lists them ("0-1"), read before anything is pinned; null: none. */
    private static final String ORIGINAL = original();

    private Affinity() {
    }

    private static String original() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (line.startsWith("Cpus_allowed_list:")) {
                    return line.substring(line.indexOf(':') + 1).strip();
                }
            }
        } catch (IOException | RuntimeException e) {
            return null;
        }
        return null;
    }

    /** {@return whether pinning can work here: Linux's /proc and {@code taskset}} */
    static boolean available() {
        return ORIGINAL != null && Files.isExecutable(TASKSET) && Files.isDirectory(Path.of("/proc/self/task"));
    }

    /**
     * Pins the calling thread to {@code cpu}; -1 lets it run on the process's cores again.
     *
     * @return whether it was pinned
     */
    static boolean pinCaller(int cpu) {
        try {
            String link = Files.readSymbolicLink(Path.of("/proc/thread-self")).toString(); // "PID/task/TID"
            return pin(Integer.parseInt(link.substring(link.lastIndexOf('/') + 1)), cpu);
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    /**
     * Pins every live thread of this process whose name starts with {@code prefix} to {@code cpu}; -1
     * lets them run on the process's cores again.
     *
     * @return how many were pinned
     */
    static int pinNamed(String prefix, int cpu) {
        String kernelPrefix = prefix.length() > 15 ? prefix.substring(0, 15) : prefix;
        int n = 0;
        try (DirectoryStream<Path> tasks = Files.newDirectoryStream(Path.of("/proc/self/task"))) {
            for (Path task : tasks) {
                String comm;
                try {
                    comm = Files.readString(task.resolve("comm")).strip();
                } catch (IOException e) {
                    continue; // the thread ended
                }
                if (comm.startsWith(kernelPrefix) && pin(Integer.parseInt(task.getFileName().toString()), cpu)) {
                    n++;
                }
            }
        } catch (IOException | RuntimeException e) {
            return n;
        }
        return n;
    }

    private static boolean pin(int tid, int cpu) {
        if (!available() || cpu < -1) {
            return false;
        }
        String cores = cpu >= 0 ? Integer.toString(cpu) : ORIGINAL;
        try {
            Process p = new ProcessBuilder(TASKSET.toString(), "-p", "-c", cores, Integer.toString(tid))
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            if (!p.waitFor(10, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                return false;
            }
            return p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }
}
