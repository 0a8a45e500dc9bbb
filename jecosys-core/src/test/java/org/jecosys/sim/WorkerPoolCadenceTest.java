package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;

/**
 * How the animation pool's threads wait between steps ({@link WorkerPool}'s anticipation): a step the
 * owner said follows finds them awake; a burst later than its window finds them polling, not parked,
 * so the owner need not wake them (how well the threads wake before a burst is the bench's to measure,
 * not a test's: it depends on the machine's load; the rhythm itself is {@link BurstsTest}'s); without a
 * rhythm they sleep until the owner wakes them; and the owner is never left a stray permit that would
 * cut its own next park short (a game's frame pacing). The timing checks are loose: a busy machine may
 * wake a thread late now and then.
 */
class WorkerPoolCadenceTest {
    /** A chunk of about 20 microseconds of arithmetic. */
    private static volatile double sink;

    private static WorkerPool pool(int chunks) {
        return new WorkerPool("cadence", 2, chunks, (c, worker) -> {
            double s = 0;
            long until = System.nanoTime() + 20_000;
            while (System.nanoTime() < until) {
                s += Math.sqrt(s + c);
            }
            sink = s;
        });
    }

    private static void sleepUntil(long deadline) {
        for (long w = deadline - System.nanoTime(); w > 0; w = deadline - System.nanoTime()) {
            LockSupport.parkNanos(w);
        }
    }

    @Test
    void aStepTheOwnerSaidFollowsFindsThePoolThreadAwake() {
        // a follow cap of 10 s, which no machine's load reaches: once the pool thread has seen a step that
        // said another follows, every step after it finds the thread spinning, none needs the owner's unpark
        // (a loaded machine may not run the thread at all for a while: the owner then goes on without it)
        try (WorkerPool pool = new WorkerPool("cadence-follow", 2, 16, (c, worker) -> sink = c, 10_000_000_000L,
                WorkerPool.POLL_SPAN_NANOS)) {
            pool.start(true);
            pool.await();
            long until = System.nanoTime() + 20_000_000_000L;
            while (pool.awakeSteps() + pool.unparkedSteps() == 0 && System.nanoTime() < until) {
                LockSupport.parkNanos(1_000_000); // until the thread has seen the first step
            }
            assertTrue(pool.awakeSteps() + pool.unparkedSteps() > 0, "the pool thread saw the first step");
            long before = pool.unparkedSteps();
            int steps = 200;
            for (int s = 0; s < steps; s++) {
                pool.start(s + 1 < steps);
                pool.await();
            }
            assertEquals(before, pool.unparkedSteps(), "no unpark for a step that followed another");
        }
    }

    @Test
    void aLateBurstFindsThePoolThreadLookingByItself() {
        // a steady 20 ms rhythm, then a burst 3 ms late: past the window, inside the polling (made longer
        // than any load here), so the owner leaves the thread to come by itself: no unpark that could move it.
        // Five rounds: on a loaded machine the thread may not have reached its polling in one of them (the CI
        // machine's full suite once unparked it); without the polling every late burst needs an unpark
        try (WorkerPool pool = new WorkerPool("cadence-late", 2, 16, (c, worker) -> sink = c, 0, 10_000_000_000L)) {
            long deadline = System.nanoTime();
            int unparked = 0;
            int rounds = 5;
            for (int round = 0; round < rounds; round++) {
                for (int b = 0; b < 200 && (b < (round == 0 ? 12 : 6) || !pool.anticipating()); b++) {
                    deadline += 20_000_000;
                    sleepUntil(deadline);
                    pool.start(false);
                    pool.await();
                }
                assertTrue(pool.anticipating(), "a steady 20 ms rhythm was found, round " + round);
                long before = pool.unparkedSteps();
                deadline += 23_000_000;
                sleepUntil(deadline);
                pool.start(false);
                pool.await();
                unparked += pool.unparkedSteps() > before ? 1 : 0;
            }
            assertTrue(unparked <= 2, "late bursts that needed an unpark: " + unparked + " of " + rounds);
        }
    }

    @Test
    void aThreadThatComesAfterEveryChunkWasClaimedDoesNotHoldTheStep() {
        // a steady 20 ms rhythm, then a burst 2.5 ms early: the thread sleeps 1.5 ms more (within the
        // grace, so the owner does not wake it); the owner runs the two chunks itself and goes on
        int[] runs = new int[2];
        try (WorkerPool pool = new WorkerPool("cadence-early", 2, runs.length, (c, worker) -> runs[c]++)) {
            long deadline = System.nanoTime();
            int steps = 0;
            for (int round = 0; round < 4; round++) {
                for (int b = 0; b < 200 && (b < 8 || !pool.anticipating()); b++) {
                    deadline += 20_000_000;
                    sleepUntil(deadline);
                    pool.start(false);
                    pool.await();
                    steps++;
                }
                deadline += 17_500_000;
                sleepUntil(deadline);
                pool.start(false);
                pool.await();
                steps++;
            }
            assertTrue(pool.closedOutSteps() >= 1, "the owner went on without the late thread: "
                    + pool.closedOutSteps() + " times");
            assertEquals(steps, runs[0], "chunk 0 ran once a step");
            assertEquals(steps, runs[1], "chunk 1 ran once a step");
        }
    }

    @Test
    void withoutACadenceThePoolThreadSleepsUntilWoken() {
        try (WorkerPool pool = pool(16)) {
            long deadline = System.nanoTime();
            int bursts = 40;
            for (int b = 0; b < bursts; b++) {
                deadline += b % 2 == 0 ? 4_000_000 : 16_000_000; // intervals 4 and 16 ms: no cadence
                sleepUntil(deadline);
                pool.start(false);
                assertFalse(pool.anticipating(), "no window to wake for, burst " + b);
                pool.await();
            }
            // parked between bursts, so the owner wakes it; a thread the loaded machine has not yet run
            // back to its park since the last step is left to come by itself (it still counts as busy)
            assertTrue(pool.unparkedSteps() >= bursts / 4, "woken by the owner: " + pool.unparkedSteps()
                    + " of " + bursts + " steps");
        }
    }

    @Test
    void theOwnerIsLeftNoPermitForItsOwnNextPark() {
        // chunks that make the owner wait for the pool thread at the end of each step, so that it spins in
        // await and the last chunk's end comes while it is not parked
        try (WorkerPool pool = pool(3)) {
            int steps = 40;
            int cutShort = 0;
            for (int s = 0; s < steps; s++) {
                pool.start(false);
                pool.await();
                long t0 = System.nanoTime();
                LockSupport.parkNanos(2_000_000);
                if (System.nanoTime() - t0 < 1_500_000) {
                    cutShort++;
                }
            }
            // a park may return early now and then on its own (the JDK allows it); a stray permit after
            // each step would cut most of them short
            assertTrue(cutShort <= 4, "the owner's park was cut short after " + cutShort + " of " + steps + " steps");
        }
    }

    @Test
    void everyChunkRunsOnceWhateverTheWaiting() {
        int[] runs = new int[64];
        try (WorkerPool pool = new WorkerPool("cadence-count", 3, runs.length, (c, worker) -> runs[c]++)) {
            for (int s = 0; s < 50; s++) {
                pool.start(s % 3 != 2);
                pool.await();
            }
        }
        for (int c = 0; c < runs.length; c++) {
            assertEquals(50, runs[c], "chunk " + c);
        }
    }
}
