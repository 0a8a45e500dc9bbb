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
        assertEquals(-1, CoreShares.kind("java"));
        assertEquals(-1, CoreShares.kind("jecosys-world-0"));
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
        long[][] ns = new long[CoreShares.KINDS][wall.length];
        ns[CoreShares.COMPILER][4] = 3_000_000; // a slow step beside a compiler
        ns[CoreShares.TILES][5] = 2_000_000; // a slow step beside a tile worker
        ns[CoreShares.TILES][0] = 1_500_000; // a usual step beside a tile worker
        ns[CoreShares.OTHER][6] = 500_000; // under the threshold: counts as none
        boolean[] pause = new boolean[wall.length];
        long[] a = CoreShares.attribute(wall, ns, pause, 1_000_000);
        // slow: compiler, collector, tiles, other, none; all: compiler, collector, tiles, other, none; slow count
        assertArrayEquals(new long[] {1, 0, 1, 0, 1, 1, 0, 2, 0, 5, 3}, a);
        pause[6] = true;
        assertEquals(0, CoreShares.attribute(wall, ns, pause, 1_000_000)[CoreShares.KINDS], "a pause explains it");
        String note = CoreShares.note(a, wall.length, 1);
        assertTrue(note.contains("While the 3 slow steps ran") && note.contains("the tile workers in 1 (25.0%)")
                && note.contains("nor a collector's pause in 1 (62.5%)"), note);
    }

    @Test
    void aBusyTileWorkersTimeIsRead() throws Exception {
        assumeTrue(CoreShares.available(), "per-thread schedstat (Linux)");
        AtomicBoolean stop = new AtomicBoolean();
        Thread busy = new Thread(() -> {
            double s = 0;
            while (!stop.get()) {
                s += Math.sqrt(s + 1);
            }
        }, "jecosys-tiles-t");
        busy.start();
        try (CoreShares shares = new CoreShares()) {
            Thread.sleep(20);
            shares.rescan();
            long[] before = new long[CoreShares.KINDS];
            long[] after = new long[CoreShares.KINDS];
            shares.read(before);
            long t0 = System.nanoTime();
            while (System.nanoTime() - t0 < 200_000_000L) {
                Thread.onSpinWait();
            }
            shares.read(after);
            long tiles = after[CoreShares.TILES] - before[CoreShares.TILES];
            assertTrue(tiles > 20_000_000L, "the spinning tile worker ran " + tiles + " ns of 200 ms");
            for (int k = 0; k < CoreShares.KINDS; k++) {
                assertTrue(after[k] >= before[k], "run time only grows");
            }
        } finally {
            stop.set(true);
            busy.join();
        }
    }
}
