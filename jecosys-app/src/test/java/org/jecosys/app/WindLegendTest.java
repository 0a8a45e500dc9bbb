package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The wind legend's scale: a round number above the wind, rising at once and falling slowly. */
class WindLegendTest {
    @Test
    void theScaleIsRoundRisesAtOnceAndFallsAfterTwoQuietSeconds() {
        assertEquals(1, WindLegend.niceScale(0));
        assertEquals(1, WindLegend.niceScale(0.7));
        assertEquals(2, WindLegend.niceScale(1.2));
        assertEquals(5, WindLegend.niceScale(2.5));
        assertEquals(10, WindLegend.niceScale(6.38));
        assertEquals(10, WindLegend.niceScale(10));
        assertEquals(50, WindLegend.niceScale(42.78));
        WindLegend w = new WindLegend();
        w.update(6, 0.1);
        assertEquals(10, w.scale());
        w.update(12, 0.1);
        assertEquals(20, w.scale(), "up at once");
        for (int i = 0; i < 19; i++) {
            w.update(3, 0.1);
        }
        assertEquals(20, w.scale(), "not down within two seconds");
        w.update(3, 0.1);
        w.update(3, 0.1);
        assertEquals(5, w.scale(), "down after two quiet seconds");
        w.update(4.5, 0.1);
        assertEquals(5, w.scale());
    }
}
