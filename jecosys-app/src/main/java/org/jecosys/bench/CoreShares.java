package org.jecosys.bench;

import java.io.File;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.StandardOpenOption;

/**
 * What else ran in this process while a step ran, on Linux: the time on a core of the JVM's and the
 * library's other threads, by kind (the JIT compilers, the collector and safepoints, the tile workers,
 * other JVM threads), read from each thread's {@code /proc/self/task/<tid>/schedstat} before and after
 * the step; and of the step's own threads (the stepping thread, named {@code java} or {@code main} by the
 * kernel, and the animation pool's, {@code jecosys-world-}) the time they waited in the kernel's run
 * queue. On a machine with two cores a
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
    /**
     * The slot of {@link #read}'s array after the kinds: the step's own threads' time waiting in the
     * kernel's run queue (runnable, not on a core) so far, ns.
     */
    static final int WAITED = KINDS;
    /** The length of {@link #read}'s array. */
    static final int SLOTS = KINDS + 1;
    /** Each kind's name in a note. */
    static final String[] NAMES = {"the JIT compilers", "the collector and safepoints", "the tile workers",
            "other JVM threads"};
    private static final File TASKS = new File("/proc/self/task");
    private FileChannel[] files = new FileChannel[0];
    private int[] kinds = new int[0];
    private long[] last = new long[0];
    private final ByteBuffer buf = ByteBuffer.allocateDirect(128);

    /** {@return whether this system has per-thread schedstat (Linux)} */
    static boolean available() {
        return TASKS.isDirectory() && new File("/proc/thread-self/schedstat").canRead();
    }

    /**
     * The kind of a thread named {@code comm} by the kernel (its first 15 characters), or {@link #WAITED}
     * for the step's own threads.
     */
    static int kind(String comm) {
        if (comm.equals("java") || comm.equals("main") || comm.startsWith("jecosys-world-")) {
            return WAITED;
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
        FileChannel[] f = new FileChannel[tasks.length];
        int[] k = new int[tasks.length];
        int n = 0;
        for (File task : tasks) {
            try {
                String comm = new String(Files.readAllBytes(new File(task, "comm").toPath()),
                        StandardCharsets.UTF_8).trim();
                f[n] = FileChannel.open(new File(task, "schedstat").toPath(), StandardOpenOption.READ);
                k[n] = kind(comm);
                n++;
            } catch (IOException gone) {
                // the thread ended meanwhile
            }
        }
        files = java.util.Arrays.copyOf(f, n);
        kinds = java.util.Arrays.copyOf(k, n);
        last = new long[n];
        for (int i = 0; i < n; i++) {
            last[i] = nanos(i);
        }
    }

    /**
     * Adds up into {@code out} (length {@link #SLOTS}) the time on a core so far, ns, of the threads of
     * each kind, and the step's threads' time waiting in the run queue ({@link #WAITED}); a thread that
     * ended keeps its last reading. No allocation.
     */
    void read(long[] out) {
        java.util.Arrays.fill(out, 0);
        for (int i = 0; i < files.length; i++) {
            long ns = nanos(i);
            if (ns >= 0) {
                last[i] = ns;
            }
            out[kinds[i]] += last[i];
        }
    }

    /**
     * Thread {@code i}'s schedstat field for its slot: the first (ns on a core) for the kinds, the second
     * (ns waiting in the run queue) for the step's threads; -1 when it cannot be read.
     */
    private long nanos(int i) {
        try {
            buf.clear();
            int len = files[i].read(buf, 0);
            return field(buf, Math.max(0, len), kinds[i] == WAITED ? 1 : 0);
        } catch (IOException gone) {
            return -1;
        }
    }

    /**
     * The {@code index}th (from 0) of the space-separated decimal numbers in the first {@code len} bytes
     * of {@code text} (schedstat's line: ns on a core, ns waiting in the run queue, time slices), or -1
     * when it is missing. No allocation.
     */
    static long field(ByteBuffer text, int len, int index) {
        int p = 0;
        for (int skip = 0; skip < index; skip++) {
            while (p < len && text.get(p) != ' ') {
                p++;
            }
            p++;
        }
        long v = 0;
        int start = p;
        for (; p < len && text.get(p) >= '0' && text.get(p) <= '9'; p++) {
            v = v * 10 + (text.get(p) - '0');
        }
        return p > start ? v : -1;
    }

    @Override
    public void close() {
        for (FileChannel f : files) {
            try {
                f.close();
            } catch (IOException ignored) {
                // a /proc file: nothing to flush
            }
        }
        files = new FileChannel[0];
        kinds = new int[0];
        last = new long[0];
    }

    /**
     * What ran beside the slow steps (over 1.5 times the median wall time), each counted when it reached
     * the threshold during the step.
     *
     * @param slow            how many steps were slow
     * @param slowWith        per kind, the slow steps beside which it ran
     * @param allWith         per kind, all the steps beside which it ran
     * @param slowNone        slow steps beside which no kind ran and no collector's pause fell
     * @param allNone         all such steps
     * @param slowNoneWaited  of {@code slowNone}, those whose own threads waited in the run queue
     */
    record Attribution(long slow, long[] slowWith, long[] allWith, long slowNone, long allNone, long slowNoneWaited) {
    }

    /**
     * Attributes the slow steps: {@code ns[slot][step]} the time of each of {@link #read}'s slots during
     * each step, {@code inPause[step]} whether a collector's pause overlapped it, {@code minNs} the
     * threshold. Allocates the result.
     */
    static Attribution attribute(double[] wallMs, long[][] ns, boolean[] inPause, long minNs) {
        double median = Stats.median(wallMs);
        long slow = 0;
        long[] slowWith = new long[KINDS];
        long[] allWith = new long[KINDS];
        long slowNone = 0;
        long allNone = 0;
        long slowNoneWaited = 0;
        for (int i = 0; i < wallMs.length; i++) {
            boolean isSlow = wallMs[i] > SlowSteps.FACTOR * median;
            boolean any = inPause[i];
            for (int k = 0; k < KINDS; k++) {
                if (ns[k][i] >= minNs) {
                    any = true;
                    allWith[k]++;
                    slowWith[k] += isSlow ? 1 : 0;
                }
            }
            slow += isSlow ? 1 : 0;
            if (!any) {
                allNone++;
                if (isSlow) {
                    slowNone++;
                    slowNoneWaited += ns[WAITED][i] >= minNs ? 1 : 0;
                }
            }
        }
        return new Attribution(slow, slowWith, allWith, slowNone, allNone, slowNoneWaited);
    }

    /** A note's sentences for {@code a} over {@code steps} steps, {@code minMs} the threshold. */
    static String note(Attribution a, int steps, double minMs) {
        StringBuilder b = new StringBuilder(String.format(java.util.Locale.ROOT, "While the %d slow steps ran,"
                + " other threads of the process were on a core for %.0f ms or more (schedstat; in brackets the"
                + " share of all %d steps with the same):", a.slow(), minMs, steps));
        for (int k = 0; k < KINDS; k++) {
            b.append(String.format(java.util.Locale.ROOT, " %s in %d (%.1f%%)%s", NAMES[k], a.slowWith()[k],
                    100.0 * a.allWith()[k] / steps, k + 1 < KINDS ? "," : ";"));
        }
        b.append(String.format(java.util.Locale.ROOT, " none of these nor a collector's pause in %d (%.1f%%). In %d"
                + " of those the step's own threads waited %.0f ms or more in the kernel's run queue (runnable"
                + " with no core: another process, or the two on one core); in the other %d they did not wait"
                + " there, and their time went to the host (a virtual CPU slowed or parked, which the guest"
                + " does not see) or to waking.", a.slowNone(), 100.0 * a.allNone() / steps, a.slowNoneWaited(),
                minMs, a.slowNone() - a.slowNoneWaited()));
        return b.toString();
    }
}
