package org.jecosys.bench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;

class CoreSharesTest {
    @Test
    void threadsAreSortedByWhatTheyDo() {
        assertEquals(CoreShares.WAITED, CoreShares.kind("java"));
        assertEquals(CoreShares.WAITED, CoreShares.kind("jecosys-world-0"));
        assertEquals(CoreShares.COMPILER, CoreShares.kind("C2 CompilerThre"));
        assertEquals(CoreShares.COMPILER, CoreShares.kind("C1 CompilerThre"));
        assertEquals(CoreShares.COLLECTOR, CoreShares.kind("GC Thread#1"));
        assertEquals(CoreShares.COLLECTOR, CoreShares.kind("G1 Conc#0"));
        assertEquals(CoreShares.COLLECTOR, CoreShares.kind("VM Thread"));
        assertEquals(CoreShares.TILES, CoreShares.kind("jecosys-tiles"));
        assertEquals(CoreShares.OTHER, CoreShares.kind("VM Periodic Tas"));
    }

    @Test
    void slowStepsAreCountedByWhatRanBesideThem() {
        double[] wall = {4, 4, 4, 4, 9, 10, 11, 4};
        long[][] ns = new long[CoreShares.SLOTS][wall.length];
        ns[CoreShares.COMPILER][4] = 3_000_000; // a slow step beside a compiler
        ns[CoreShares.TILES][5] = 2_000_000; // a slow step beside a tile worker
        ns[CoreShares.TILES][0] = 1_500_000; // a usual step beside a tile worker
        ns[CoreShares.OTHER][6] = 500_000; // under the threshold: counts as none
        ns[CoreShares.WAITED][6] = 2_000_000; // ...and the step's threads waited for a core
        boolean[] pause = new boolean[wall.length];
        CoreShares.Attribution a = CoreShares.attribute(wall, ns, pause, 1_000_000);
        assertEquals(3, a.slow());
        assertArrayEquals(new long[] {1, 0, 1, 0}, a.slowWith());
        assertArrayEquals(new long[] {1, 0, 2, 0}, a.allWith());
        assertEquals(1, a.slowNone());
        assertEquals(5, a.allNone());
        assertEquals(1, a.slowNoneWaited());
        pause[6] = true;
        assertEquals(0, CoreShares.attribute(wall, ns, pause, 1_000_000).slowNone(), "a pause explains it");
        String note = CoreShares.note(a, wall.length, 1);
        assertTrue(note.contains("While the 3 slow steps ran") && note.contains("the tile workers in 1 (25.0%)")
                && note.contains("nor a collector's pause in 1 (62.5%). In 1 of those")
                && note.contains("in the other 0 they did not wait"), note);
    }

    @Test
    void aBusyTileWorkersTimeAndTheStepThreadsWaitAreRead() throws Exception {
        assumeTrue(CoreShares.available(), "per-thread schedstat (Linux)");
        int cores = Runtime.getRuntime().availableProcessors();
        AtomicBoolean stop = new AtomicBoolean();
        java.util.List<Thread> busy = new java.util.ArrayList<>();
        try (CoreShares shares = new CoreShares()) {
            // a tile worker and one step thread spinning, a core each: the step thread hardly waits
            spin(busy, stop, "jecosys-tiles-t");
            spin(busy, stop, "jecosys-world-t0");
            long[] alone = measure(shares, 300);
            assertTrue(alone[CoreShares.TILES] > 100_000_000L,
                    "the spinning tile worker ran " + alone[CoreShares.TILES] + " ns of 300 ms");
            assertTrue(alone[CoreShares.WAITED] < 100_000_000L,
                    "a step thread with a core waited " + alone[CoreShares.WAITED] + " ns of 300 ms, not its run time");
            // then more step threads than cores: they wait for one
            for (int i = 1; i <= cores; i++) {
                spin(busy, stop, "jecosys-world-t" + i);
            }
            long[] crowded = measure(shares, 300);
            assertTrue(crowded[CoreShares.WAITED] > alone[CoreShares.WAITED] + 100_000_000L,
                    "step threads without a core waited " + crowded[CoreShares.WAITED] + " ns of 300 ms each");
        } finally {
            stop.set(true);
            for (Thread t : busy) {
                t.join();
            }
        }
    }

    private static void spin(java.util.List<Thread> busy, AtomicBoolean stop, String name) {
        Thread t = new Thread(() -> {
            double s = 0;
            while (!stop.get()) {
                s += Math.sqrt(s + 1);
            }
        }, name);
        t.start();
        busy.add(t);
    }

    /** Each slot's growth over {@code ms} of sleep, after listing the threads again. */
    private static long[] measure(CoreShares shares, long ms) throws InterruptedException {
        Thread.sleep(20);
        shares.rescan();
        long[] before = new long[CoreShares.SLOTS];
        long[] after = new long[CoreShares.SLOTS];
        shares.read(before);
        Thread.sleep(ms);
        shares.read(after);
        for (int k = 0; k < CoreShares.SLOTS; k++) {
            assertTrue(after[k] >= before[k], "run and wait times only grow");
            after[k] -= before[k];
        }
        return after;
    }
}
