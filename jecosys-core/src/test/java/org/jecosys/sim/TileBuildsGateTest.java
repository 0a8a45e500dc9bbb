package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * When the open world's tile workers may start a build phase ({@link TileBuilds#mayStart}): never
 * during a step nor between the fixed steps of one burst; right after a burst whatever the phase's
 * length; later only if the phase is expected to end before the next burst (expected after the shorter
 * of the last two intervals between bursts); and, after a pause too long to go by, within the build
 * window after the last burst.
 */
class TileBuildsGateTest {
    private static final long MS = 1_000_000;

    private static TileBuilds builds() throws Exception {
        SimulationDef def = OpenWorldTest.meadowDef();
        org.jecosys.plant.PlantModel model = org.jecosys.plant.PlantModel.build(def.species(), def.seed(),
                org.jecosys.plant.GravityBend.EARTH_GRAVITY, org.jecosys.math.Progress.NONE,
                org.jecosys.plant.ComponentFactories.NONE);
        return new TileBuilds(def, model, OpenWorldTest.placer(def), () -> false);
    }

    /** Bursts of two fixed steps (4 ms each) every 33 ms from {@code t0}, {@code n} of them; returns the last end. */
    private static long bursts(TileBuilds b, long t0, int n) {
        long end = 0;
        for (int k = 0; k < n; k++) {
            long start = t0 + k * 33 * MS;
            b.stepStarting(true, start);
            assertFalse(b.mayStart(0, start + 2 * MS), "no phase starts during a step");
            assertFalse(b.mayStart(0, start + 4 * MS + MS / 10), "nor between the steps of a burst");
            b.stepStarting(false, start + 4 * MS + MS / 5);
            end = start + 8 * MS;
            b.burstEnded(end);
        }
        return end;
    }

    @Test
    void aPhaseStartsOnlyWhereItFitsBeforeTheNextBurst() throws Exception {
        TileBuilds b = builds();
        b.ran(2, 10 * MS); // the simulation phase takes 10 ms, twice that is allowed for
        long end = bursts(b, 1_000 * MS, 5); // the next burst at 33 ms after the last start: 25 ms after its end
        assertTrue(b.mayStart(2, end + MS / 2), "right after a burst, whatever the phase's length");
        assertTrue(b.mayStart(2, end + 3 * MS), "10 ms (twice: 20) plus the lead fit in the 22 ms left");
        assertFalse(b.mayStart(2, end + 6 * MS), "19 ms left: a 10 ms phase might run into the next burst");
        b.ran(0, MS);
        assertTrue(b.mayStart(0, end + 20 * MS), "a 1 ms phase still fits 5 ms before the burst");
        assertFalse(b.mayStart(0, end + 23 * MS), "but not 2 ms before it");
    }

    @Test
    void afterALongPauseTheBuildWindowAfterTheLastBurstHolds() throws Exception {
        TileBuilds b = builds();
        b.ran(0, MS);
        long t = 1_000 * MS;
        long[] gaps = {30, 300, 20, 400}; // the last interval over 250 ms: no cadence to go by
        for (long g : gaps) {
            t += g * MS;
            b.stepStarting(false, t);
            b.burstEnded(t + 4 * MS);
        }
        long end = t + 4 * MS;
        assertTrue(b.mayStart(0, end + OpenWorld.BUILD_WINDOW_NANOS - MS), "within the window");
        assertFalse(b.mayStart(0, end + OpenWorld.BUILD_WINDOW_NANOS + MS), "past it");
    }
}
