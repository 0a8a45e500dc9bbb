package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The stepping thread's bursts ({@link Bursts}): a step begins a burst unless the one before said it
 * follows; each burst's start and the intervals between the last three starts; a burst ended early (a
 * step that threw) lets the next step begin one.
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
}
