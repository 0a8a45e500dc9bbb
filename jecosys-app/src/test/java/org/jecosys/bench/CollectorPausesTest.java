package org.jecosys.bench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The open-world section's record of the collector's pauses: a real collection arrives through the
 * JVM's notifications and is placed on System.nanoTime() though the collector's clock has another origin;
 * the pauses within a walk leave out the collections the bench asked for itself;
 * the slow steps that overlapped a pause are told from those that did not.
 */
class CollectorPausesTest {
    private static final long MS = 1_000_000L;

    /** A time (System.nanoTime()) ten hours back: before this JVM began, so no real pause lies near it. */
    private static long beforeThisJvm() {
        return System.nanoTime() - 36_000_000L * MS;
    }

    @Test
    void aCollectionAskedForArrivesAsAPause() throws InterruptedException {
        try (CollectorPauses pauses = new CollectorPauses()) {
            long before = System.nanoTime();
            System.gc();
            // the notification comes on the JVM's own thread, a little after the pause
            long giveUp = System.nanoTime() + 10_000 * MS;
            while (pauses.count() == 0 && System.nanoTime() < giveUp) {
                Thread.sleep(10);
            }
            assertTrue(pauses.count() >= 1, "the collection was noted");
            double[] all = pauses.within(before - 5 * MS, System.nanoTime(), new long[0], new long[0], 0);
            assertTrue(all[0] >= 1, "the pause began after the call, give or take the two milliseconds it is placed to");
            double[] skipped = pauses.within(before - 5 * MS, System.nanoTime(), new long[] {before - 5 * MS},
                    new long[] {System.nanoTime()}, 1);
            assertEquals(0, skipped[0], "a collection asked for is left out");
        }
    }

    @Test
    void pausesWithinAWalkLeaveOutTheSkippedWindows() {
        try (CollectorPauses p = new CollectorPauses()) {
            long t = beforeThisJvm();
            // on a collector's clock 7 s behind System.nanoTime(); notices arrive 0.3 to 5 ms after a pause's end
            long behind = 7_000 * MS;
            p.add(t - behind, 20 * MS, t + 20 * MS + MS / 3);
            p.add(t + 100 * MS - behind, 5 * MS, t + 110 * MS);
            p.add(t + 200 * MS - behind, 40 * MS, t + 241 * MS); // a checkpoint's full collection
            p.add(t + 900 * MS - behind, 8 * MS, t + 909 * MS); // after the walk
            double[] r = p.within(t - MS, t + 500 * MS, new long[] {t + 199 * MS}, new long[] {t + 260 * MS}, 1);
            assertArrayEquals(new double[] {2, 25, 20}, r, 1e-9, "{pauses, ms in all, longest ms}");
            assertArrayEquals(new double[] {0, 0, 0}, p.within(t + 300 * MS, t + 400 * MS, new long[0], new long[0],
                    0), 1e-9);
        }
    }

    @Test
    void slowStepsInAPauseAreCounted() {
        try (CollectorPauses p = new CollectorPauses()) {
            long t = beforeThisJvm();
            p.add(t + 10 * MS, 15 * MS, t + 25 * MS);
            // five 4 ms steps 33 ms apart; the second (slow) overlaps the pause, the fourth (slow) does not,
            // the first (not slow) ends 2 ms before it
            double[] wall = {4, 12, 4, 11, 4};
            long[] start = new long[5];
            long[] end = new long[5];
            for (int i = 0; i < 5; i++) {
                start[i] = t + 33 * MS * i + (i == 0 ? 4 * MS : 0);
                end[i] = start[i] + (long) (wall[i] * MS);
            }
            start[1] = t + 20 * MS;
            end[1] = start[1] + 12 * MS;
            assertTrue(p.overlaps(start[1], end[1]));
            assertFalse(p.overlaps(start[3], end[3]));
            assertEquals(1, SlowSteps.inPauses(wall, SlowSteps.inPause(start, end, wall.length, p)));
        }
    }

    @Test
    void concurrentCyclesAreNotPauses() {
        assertTrue(CollectorPauses.pauses("G1 Young Generation"));
        assertTrue(CollectorPauses.pauses("G1 Old Generation"));
        assertTrue(CollectorPauses.pauses("ZGC Pauses"));
        assertFalse(CollectorPauses.pauses("ZGC Cycles"));
        assertFalse(CollectorPauses.pauses("G1 Concurrent GC"));
        assertFalse(CollectorPauses.names().isEmpty(), "this JVM has a collector that pauses");
        assertFalse(CollectorPauses.names().contains("Cycles"), CollectorPauses.names());
    }
}
