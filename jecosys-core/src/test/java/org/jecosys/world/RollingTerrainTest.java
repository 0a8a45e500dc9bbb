package org.jecosys.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** {@link RollingTerrain}: seeded, unbounded, gentle. */
class RollingTerrainTest {
    @Test
    void seededBoundedAndEverywhere() {
        RollingTerrain a = RollingTerrain.gentle(4);
        assertEquals(a.height(12.5, -7.25), RollingTerrain.gentle(4).height(12.5, -7.25));
        assertNotEquals(a.height(12.5, -7.25), RollingTerrain.gentle(5).height(12.5, -7.25));
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < 4000; k++) {
            double x = (k % 64) * 7.3 - 1e6 * (k % 3);
            double z = (k / 64) * 7.3 + 3e5 * (k % 5);
            double h = a.height(x, z);
            assertTrue(Double.isFinite(h) && Math.abs(h) <= 3, "height " + h + " at " + x + ", " + z);
            lo = Math.min(lo, h);
            hi = Math.max(hi, h);
        }
        assertTrue(hi - lo > 1.5, "hills, not a plain: " + lo + " .. " + hi);
        assertThrows(IllegalArgumentException.class, () -> new RollingTerrain(1, -1, 90, 4));
        assertThrows(IllegalArgumentException.class, () -> new RollingTerrain(1, 3, 0.5, 4));
        assertThrows(IllegalArgumentException.class, () -> new RollingTerrain(1, 3, 90, 0));
    }

    @Test
    void gentleAndSmooth() {
        RollingTerrain a = RollingTerrain.gentle(9);
        double steepest = 0;
        for (int k = 0; k < 10_000; k++) {
            double x = (k % 100) * 1.7 - 80;
            double z = (k / 100) * 1.7 + 40;
            steepest = Math.max(steepest, a.slope(x, z));
            assertEquals(a.height(x, z), a.height(x + 0.01, z), 0.01, "continuous");
        }
        assertTrue(steepest > 0.01 && steepest < 0.2, "gentle slopes, radians: " + steepest);
    }
}
