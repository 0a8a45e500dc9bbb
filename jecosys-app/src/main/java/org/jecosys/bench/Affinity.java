package org.jecosys.bench;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.lwjgl.system.JNI;
import org.lwjgl.system.Library;
import org.lwjgl.system.MemoryUtil;
import org.lwjgl.system.SharedLibrary;

/**
 * Pins threads to one core each, on Linux, through {@code sched_setaffinity} (called with LWJGL's
 * native-call helpers, found in the C library at run time), for the bench's pinned walk: a game engine
 * pins its workers the same way. A thread is found by its name in {@code /proc/self/task/N/comm} (the
 * kernel keeps the first 15 characters of a Java thread's name). Elsewhere, or when the call fails,
 * nothing is pinned and the methods say so. Bench only; allocates.
 */
final class Affinity {
    private static final int MASK_BYTES = 128;
    /**
     * The cores the process may run on, read when this class is first used (before anything is pinned:
     * {@code Runtime.availableProcessors()} counts the calling thread's cores, so it cannot tell once the
     * caller is pinned); null when unavailable.
     */
    private static final byte[] ORIGINAL = original();

    private Affinity() {
    }

    /** {@return whether pinning can work here: Linux, and the C library has {@code sched_setaffinity}} */
    static boolean available() {
        return function() != 0 && ORIGINAL != null;
    }

    private static byte[] original() {
        long f = function("sched_getaffinity");
        if (f == 0) {
            return null;
        }
        ByteBuffer mask = MemoryUtil.memCalloc(MASK_BYTES);
        try {
            if (JNI.invokePPI(0, (long) MASK_BYTES, MemoryUtil.memAddress(mask), f) != 0) {
                return null;
            }
            byte[] b = new byte[MASK_BYTES];
            mask.get(0, b);
            return b;
        } finally {
            MemoryUtil.memFree(mask);
        }
    }

    private static long function() {
        return function("sched_setaffinity");
    }

    private static long function(String name) {
        if (!System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux")) {
            return 0;
        }
        try {
            SharedLibrary libc = Library.loadNative(Affinity.class, "org.lwjgl", "libc.so.6");
            return libc.getFunctionAddress(name);
        } catch (RuntimeException | LinkageError e) {
            return 0;
        }
    }

    /**
     * Pins the calling thread to {@code cpu}; -1 lets it run on the process's cores again.
     *
     * @return whether it was pinned
     */
    static boolean pinCaller(int cpu) {
        return pin(0, cpu);
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
        long f = function();
        if (f == 0 || cpu < -1 || cpu >= MASK_BYTES * 8) {
            return false;
        }
        ByteBuffer mask = MemoryUtil.memCalloc(MASK_BYTES);
        try {
            if (cpu >= 0) {
                mask.put(cpu / 8, (byte) (1 << (cpu % 8)));
            } else if (ORIGINAL != null) { // the cores the process had
                mask.put(0, ORIGINAL);
            } else {
                return false;
            }
            return JNI.invokePPI(tid, (long) MASK_BYTES, MemoryUtil.memAddress(mask), f) == 0;
        } finally {
            MemoryUtil.memFree(mask);
        }
    }
}
