package org.jecosys.bench;

import java.io.File;
import java.io.IOException;
import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;

/**
 * What else ran in this process while a step ran, on Linux: the time on a core of the JVM's and the
 * library's other threads, by kind (the JIT compilers, the collector and safepoints, the tile workers,
 * other JVM threads), read from each thread's {@code /proc/self/task/<tid>/schedstat} before and after
 * the step. The step's own threads (the stepping thread, named {@code java} or {@code main} by the
 * kernel, and the animation pool's, {@code jecosys-world-}) are left out. On a machine with two cores a
 * step that needs both loses a core to whatever of these runs meanwhile; what none of them explains has
 * its reason outside the process (the host, other processes, the kernel placing both step threads on
 * one core). Bench only; one thread. {@link #read} allocates
 * nothing; {@link #rescan} (threads come and go: the JIT starts compilers on demand) allocates.
 */
final class CoreShares implements AutoCloseable {
    static final int COMPILER = 0;
    static final int COLLECTOR = 1;
    static final int TILES = 2;
    static final int OTHER = 3;
    static final int KINDS = 4;
    /** Each kind's name in a note. */
    static final String[] NAMES = {"the JIT compilers", "the collector and safepoints", "the tile workers",
            "other JVM threads"};
    private static final File TASKS = new File("/proc/self/task");
    private RandomAccessFile[] files = new RandomAccessFile[0];
    private int[] kinds = new int[0];
    private long[] last = new long[0];
    private final byte[] buf = new byte[128];

    /** {@return whether this system has per-thread schedstat (Linux)} */
    static boolean available() {
        return TASKS.isDirectory() && new File("/proc/thread-self/schedstat").canRead();
    }

    /**
     * The kind of a thread named {@code comm} by the kernel (its first 15 characters), or -1 for the
     * step's own threads.
     */
    static int kind(String comm) {
        if (comm.equals("java") || comm.equals("main") || comm.startsWith("jecosys-world-")) {
            return -1;
        }
        if (comm.startsWith("C1 CompilerThre") || comm.startsWith("C2 CompilerThre")) {
            return COMPILER;
        }
        if (comm.startsWith("GC Thread") || comm.startsWith("G1 ") || comm.equals("VM Thread")
                || comm.startsWith("Z") || comm.startsWith("Parallel")) {
            return COLLECTOR;
        }
        if (comm.startsWith("jecosys-tiles")) {
            return TILES;
        }
        return OTHER;
    }

    /** Lists this process's threads again (outside a timed step: it allocates and reads many files). */
    void rescan() {
        close();
        File[] tasks = TASKS.listFiles();
        if (tasks == null) {
            return;
        }
        RandomAccessFile[] f = new RandomAccessFile[tasks.length];
        int[] k = new int[tasks.length];
        int n = 0;
        for (File task : tasks) {
            try {
                String comm = new String(Files.readAllBytes(new File(task, "comm").toPath()),
                        StandardCharsets.UTF_8).trim();
                int kind = kind(comm);
                if (kind >= 0) {
                    f[n] = new RandomAccessFile(new File(task, "schedstat"), "r");
                    k[n] = kind;
                    n++;
                }
            } catch (IOException gone) {
                // the thread ended meanwhile
            }
        }
        files = java.util.Arrays.copyOf(f, n);
        kinds = java.util.Arrays.copyOf(k, n);
        last = new long[n];
        for (int i = 0; i < n; i++) {
            last[i] = runNanos(i);
        }
    }

    /**
     * Adds up the time on a core so far, ns, of the threads of each kind into {@code out} (length
     * {@link #KINDS}); a thread that ended keeps its last reading. No allocation.
     */
    void read(long[] out) {
        java.util.Arrays.fill(out, 0);
        for (int i = 0; i < files.length; i++) {
            long ns = runNanos(i);
            if (ns >= 0) {
                last[i] = ns;
            }
            out[kinds[i]] += last[i];
        }
    }

    /** The first field of thread {@code i}'s schedstat (ns on a core), or -1 when it cannot be read. */
    private long runNanos(int i) {
        try {
            RandomAccessFile f = files[i];
            f.seek(0);
            int len = f.read(buf);
            long v = 0;
            int p = 0;
            for (; p < len && buf[p] >= '0' && buf[p] <= '9'; p++) {
                v = v * 10 + (buf[p] - '0');
            }
            return p > 0 ? v : -1;
        } catch (IOException gone) {
            return -1;
        }
    }

    @Override
    public void close() {
        for (RandomAccessFile f : files) {
            try {
                f.close();
            } catch (IOException ignored) {
                // a /proc file: nothing to flush
            }
        }
        files = new RandomAccessFile[0];
        kinds = new int[0];
        last = new long[0];
    }

    /**
     * Of the steps over 1.5 times the median wall time: how many had each kind run at least
     * {@code minNs} meanwhile, and how many had none of them and no collector's pause; then the same
     * counts over all steps. {@code ns[kind][step]}; {@code inPause[step]}. Allocates the result:
     * {slow[KINDS], slowNone, all[KINDS], allNone, slowCount}.
     */
    static long[] attribute(double[] wallMs, long[][] ns, boolean[] inPause, long minNs) {
        double median = Stats.median(wallMs);
        long[] r = new long[2 * KINDS + 3];
        for (int i = 0; i < wallMs.length; i++) {
            boolean slow = wallMs[i] > 1.5 * median;
            boolean any = inPause[i];
            for (int k = 0; k < KINDS; k++) {
                if (ns[k][i] >= minNs) {
                    any = true;
                    r[KINDS + 1 + k]++;
                    if (slow) {
                        r[k]++;
                    }
                }
            }
            if (!any) {
                r[2 * KINDS + 1]++;
                if (slow) {
                    r[KINDS]++;
                }
            }
            if (slow) {
                r[2 * KINDS + 2]++;
            }
        }
        return r;
    }

    /** A note's sentence for {@link #attribute}'s result over {@code steps} steps, {@code minMs} the threshold. */
    static String note(long[] a, int steps, double minMs) {
        StringBuilder b = new StringBuilder(String.format(java.util.Locale.ROOT, "While the %d slow steps ran,"
                + " other threads of the process were on a core for %.0f ms or more (schedstat; in brackets the"
                + " share of all %d steps with the same):", a[2 * KINDS + 2], minMs, steps));
        for (int k = 0; k < KINDS; k++) {
            b.append(String.format(java.util.Locale.ROOT, " %s in %d (%.1f%%)%s", NAMES[k], a[k],
                    100.0 * a[KINDS + 1 + k] / steps, k + 1 < KINDS ? "," : ";"));
        }
        b.append(String.format(java.util.Locale.ROOT, " none of these nor a collector's pause in %d (%.1f%%): there"
                + " the step's threads waited for a core for a reason outside the process (the host, other"
                + " processes, the kernel placing both on one core).", a[KINDS],
                100.0 * a[2 * KINDS + 1] / steps));
        return b.toString();
    }
}
