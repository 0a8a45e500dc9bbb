package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The stepping thread's bursts ({@link Bursts}): a step begins a burst unless the one before said it
 * follows; each burst's start and the intervals between the last three starts; a burst ended early (a
 * step that threw) lets the next step begin one; and the rhythm: the period two agreeing intervals set,
 * kept over a few misses, and the window in which the next burst is expected (a period after the last
 * start, or after where the frame's grid put it).
 */
class BurstsTest {
    @Test
    void stepsThatFollowOneAnotherAreOneBurst() {
        Bursts b = new Bursts();
        assertTrue(b.step(true, 100), "the first step begins a burst");
        assertEquals(0, b.interval(), "no burst before the first");
        assertFalse(b.step(false, 104), "the step said to follow is in the same burst");
        assertTrue(b.step(true, 133), "the next frame's first step");
        assertEquals(133, b.start());
        assertEquals(33, b.interval());
        assertEquals(0, b.lastInterval());
        assertFalse(b.step(false, 137));
        assertTrue(b.step(false, 170));
        assertEquals(37, b.interval());
        assertEquals(33, b.lastInterval());
    }

    @Test
    void anEndedBurstLetsTheNextStepBeginOne() {
        Bursts b = new Bursts();
        b.step(true, 10);
        b.end(); // the step that was to be followed threw
        assertTrue(b.step(false, 50), "the next step begins a burst");
        assertEquals(40, b.interval());
    }

    private static final long MS = 1_000_000;

    /** Starts one burst of one step at {@code at} ms. */
    private static void burst(Bursts b, long at) {
        assertTrue(b.step(false, at * MS));
    }

    /** Four bursts 33 ms apart, from 1000 to 1099 ms: a period of 33 ms, the grid on 1132 ms. */
    private static void steady(Bursts b) {
        for (long t = 1000; t <= 1099; t += 33) {
            burst(b, t);
        }
    }

    @Test
    void aSteadyFrameIsExpectedAPeriodAfterTheLastStart() {
        Bursts b = new Bursts();
        burst(b, 1000);
        burst(b, 1033);
        assertEquals(0, b.earliestNext(), "one interval is no rhythm yet");
        burst(b, 1066);
        assertEquals(33 * MS, b.period(), "two intervals agree");
        assertEquals(1099 * MS, b.earliestNext());
        assertEquals(1099 * MS, b.latestNext());
    }

    @Test
    void aLateFrameKeepsThePeriodAndTheGrid() {
        Bursts b = new Bursts();
        steady(b);
        burst(b, 1134); // 2 ms late
        assertEquals(33 * MS, b.period(), "one late frame keeps the period");
        assertEquals(1165 * MS, b.earliestNext(), "a loop paced by deadlines comes back to its grid");
        assertEquals(1167 * MS, b.latestNext(), "a loop that sleeps a frame after its start comes a period later");
        burst(b, 1165); // back on the grid: a short interval, a second miss
        assertEquals(33 * MS, b.period());
        assertEquals(1198 * MS, b.earliestNext());
        assertEquals(1198 * MS, b.latestNext());
    }

    @Test
    void aGridTooFarOffIsLetGo() {
        Bursts b = new Bursts();
        steady(b);
        burst(b, 1142); // 10 ms late: beyond the spread in which both are expected
        assertEquals(1175 * MS, b.earliestNext(), "only a period after the late start");
        assertEquals(1175 * MS, b.latestNext());
    }

    @Test
    void aNewRhythmIsTakenWhenTwoIntervalsAgree() {
        Bursts b = new Bursts();
        steady(b);
        burst(b, 1115);
        assertEquals(33 * MS, b.period(), "one interval of 16 ms is a miss");
        burst(b, 1131);
        assertEquals(16 * MS, b.period(), "two agree: a 60 Hz frame now");
        assertEquals(1147 * MS, b.earliestNext());
    }

    @Test
    void irregularBurstsKeepNoRhythm() {
        Bursts b = new Bursts();
        long t = 1000;
        for (int k = 0; k < 20; k++) {
            t += k % 2 == 0 ? 4 : 16;
            burst(b, t);
            assertEquals(0, b.earliestNext(), "alternating intervals, burst " + k);
        }
        Bursts d = new Bursts();
        steady(d);
        long[] misses = {1150, 1210, 1290, 1390};
        for (int k = 0; k < misses.length; k++) {
            burst(d, misses[k]);
            assertEquals(k < Bursts.MISSES_KEPT ? 33 * MS : 0, d.period(), "after " + (k + 1) + " misses");
        }
    }

    @Test
    void aPauseIsNoRhythm() {
        Bursts b = new Bursts();
        burst(b, 1000);
        burst(b, 1300);
        burst(b, 1600);
        assertEquals(0, b.period(), "300 ms apart: longer than a frame");
        assertEquals(0, b.earliestNext());
    }
}
