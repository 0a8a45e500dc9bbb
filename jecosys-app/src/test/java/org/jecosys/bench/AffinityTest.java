package org.jecosys.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * The bench's thread pinning ({@link Affinity}), where the machine allows it (Linux, taskset): a thread
 * pinned to a core may run on that core only, and let go it may run on the process's cores again, the
 * same ones as before (a restore that counted the pinned thread's cores would leave everything it
 * starts later on one core); a thread is found by its name. The cores are read from the kernel
 * ({@code /proc/thread-self/status}), not from {@code Runtime.availableProcessors()}, which the JVM may
 * cache for a moment.
 */
class AffinityTest {
    private static String cores() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/thread-self/status"))) {
                if (line.startsWith("Cpus_allowed_list:")) {
                    return line.substring(line.indexOf(':') + 1).strip();
                }
            }
        } catch (IOException e) {
            return "unreadable: " + e;
        }
        return "none";
    }

    @Test
    void aPinnedThreadRunsOnOneCoreAndLetGoOnTheProcesssCoresAgain() throws Exception {
        assumeTrue(Affinity.available(), "pinning needs Linux and taskset");
        String[] seen = new String[3];
        boolean[] pinned = new boolean[2];
        Thread t = new Thread(() -> {
            seen[0] = cores();
            pinned[0] = Affinity.pinCaller(0);
            seen[1] = cores();
            pinned[1] = Affinity.pinCaller(-1);
            seen[2] = cores();
        }, "affinity-test");
        t.start();
        t.join();
        assertTrue(pinned[0] && pinned[1], "the thread was pinned and let go");
        assertEquals("0", seen[1], "cores while pinned");
        assertEquals(seen[0], seen[2], "cores once let go: those it had before");
    }

    @Test
    void aThreadIsFoundByItsName() throws Exception {
        assumeTrue(Affinity.available(), "pinning needs Linux and taskset");
        Object lock = new Object();
        String[] seen = new String[1];
        Thread t = new Thread(() -> {
            synchronized (lock) {
                try {
                    lock.wait(10_000);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                seen[0] = cores();
            }
        }, "affinity-named-thread");
        t.start();
        while (t.getState() != Thread.State.TIMED_WAITING) {
            Thread.onSpinWait();
        }
        assertEquals(1, Affinity.pinNamed("affinity-named-thread", 0), "threads pinned by name");
        synchronized (lock) {
            lock.notifyAll();
        }
        t.join();
        assertEquals("0", seen[0], "cores of the named thread after it was pinned");
    }
}
