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
    void schedstatsFieldsAreRead() {
        java.nio.ByteBuffer line = java.nio.ByteBuffer.wrap("5123 877 12\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        assertEquals(5123, CoreShares.field(line, line.capacity(), 0), "ns on a core");
        assertEquals(877, CoreShares.field(line, line.capacity(), 1), "ns in the run queue");
        assertEquals(12, CoreShares.field(line, line.capacity(), 2));
        assertEquals(-1, CoreShares.field(line, line.capacity(), 3), "no fourth field");
        assertEquals(51, CoreShares.field(line, 2, 0), "only the bytes read count");
        assertEquals(-1, CoreShares.field(line, 0, 0), "nothing read");
    }

    @Test
    void aBusyTileWorkersTimeAndAStepThreadsWaitAreRead() throws Exception {
        assumeTrue(CoreShares.available(), "per-thread schedstat (Linux)");
        int cores = Runtime.getRuntime().availableProcessors();
        AtomicBoolean stop = new AtomicBoolean();
        java.util.List<Thread> busy = new java.util.ArrayList<>();
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        try (CoreShares shares = new CoreShares()) {
            // three tile workers a core and one step thread, all spinning: the step thread waits for a core
            // most of the time, and its time on a core plus its wait is the time it was runnable
            for (int i = 0; i < 3 * cores; i++) {
                spin(busy, stop, "jecosys-tiles-t" + i);
            }
            Thread step = spin(busy, stop, "jecosys-world-t");
            Thread.sleep(20);
            shares.rescan();
            long[] before = new long[CoreShares.SLOTS];
            long[] after = new long[CoreShares.SLOTS];
            long cpu0 = mx.getThreadCpuTime(step.getId());
            long t0 = System.nanoTime();
            shares.read(before);
            Thread.sleep(300);
            shares.read(after);
            long elapsed = System.nanoTime() - t0;
            long cpu = mx.getThreadCpuTime(step.getId()) - cpu0;
            for (int k = 0; k < CoreShares.SLOTS; k++) {
                assertTrue(after[k] >= before[k], "run and wait times only grow");
            }
            long tiles = after[CoreShares.TILES] - before[CoreShares.TILES];
            long waited = after[CoreShares.WAITED] - before[CoreShares.WAITED];
            assertTrue(tiles > 20_000_000L, "the spinning tile workers ran " + tiles + " ns in 300 ms");
            assertEquals(elapsed, waited + cpu, 0.25 * elapsed, "the step thread waited " + waited + " ns and ran "
                    + cpu + " ns in " + elapsed + " ns, always runnable");
        } finally {
            stop.set(true);
            for (Thread t : busy) {
                t.join();
            }
        }
    }

    private static Thread spin(java.util.List<Thread> busy, AtomicBoolean stop, String name) {
        Thread t = new Thread(() -> {
            double s = 0;
            while (!stop.get()) {
                s += Math.sqrt(s + 1);
            }
        }, name);
        t.start();
        busy.add(t);
        return t;
    }

}
