package org.jecosys.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.Test;

/**
 * The bench's thread pinning ({@link Affinity}), where the machine allows it (Linux): a thread pinned
 * to a core sees one processor, and let go it sees the process's cores again, whatever it saw while
 * pinned (a restore that counted the pinned thread's cores would leave everything it starts later on
 * one core); a named thread is found and pinned.
 */
class AffinityTest {
    @Test
    void aPinnedThreadSeesOneCoreAndLetGoItSeesThemAllAgain() throws Exception {
        assumeTrue(Affinity.available(), "pinning needs Linux's sched_setaffinity");
        int cores = Runtime.getRuntime().availableProcessors();
        int[] seen = new int[3];
        boolean[] pinned = new boolean[1];
        Thread t = new Thread(() -> {
            pinned[0] = Affinity.pinCaller(0);
            seen[0] = Runtime.getRuntime().availableProcessors();
            Affinity.pinCaller(-1);
            seen[1] = Runtime.getRuntime().availableProcessors();
        }, "affinity-test");
        t.start();
        t.join();
        assertTrue(pinned[0], "the thread was pinned");
        assertEquals(1, seen[0], "processors seen while pinned to one core");
        assertEquals(cores, seen[1], "processors seen once let go");
    }

    @Test
    void aThreadIsFoundByItsName() throws Exception {
        assumeTrue(Affinity.available(), "pinning needs Linux's sched_setaffinity");
        Object lock = new Object();
        int[] seen = new int[1];
        Thread t = new Thread(() -> {
            synchronized (lock) {
                try {
                    lock.wait(10_000);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                seen[0] = Runtime.getRuntime().availableProcessors();
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
        assertEquals(1, seen[0], "processors the named thread saw after it was pinned");
    }
}
