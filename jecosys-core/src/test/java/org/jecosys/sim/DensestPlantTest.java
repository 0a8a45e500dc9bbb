package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** {@link World#densestPlant}: the middle of a species' densest patch, against a count done here. */
class DensestPlantTest {
    private static int neighbours(World w, int p, double radius) {
        int n = 0;
        for (int q = 0; q < w.plantCount(); q++) {
            if (w.plantSpecies(q) == w.plantSpecies(p)
                    && Math.hypot(w.plantX(p) - w.plantX(q), w.plantZ(p) - w.plantZ(q)) < radius) {
                n++;
            }
        }
        return n;
    }

    @Test
    void noPlantOfTheSpeciesHasMoreNeighboursOfItsOwnKind() throws Exception {
        World w = SimFixtures.world();
        // radii from a fraction of the plants' spacing (grid cells hold few plants) to wider than the
        // terrain (one cell)
        for (double radius : new double[] {0.05, 0.4, 1.5, 1e6}) {
            for (int s = 0; s < w.plants().species().size(); s++) {
                int best = w.densestPlant(s, radius);
                if (best < 0) {
                    for (int p = 0; p < w.plantCount(); p++) {
                        assertTrue(w.plantSpecies(p) != s, "species " + s + " has plants but none was found");
                    }
                    continue;
                }
                assertEquals(s, w.plantSpecies(best));
                int most = neighbours(w, best, radius);
                for (int p = 0; p < w.plantCount(); p++) {
                    if (w.plantSpecies(p) == s) {
                        int n = neighbours(w, p, radius);
                        assertTrue(n < most || (n == most && p >= best), "radius " + radius + ": plant " + p
                                + " has " + n + " neighbours, the one found " + most);
                    }
                }
            }
        }
        assertEquals(-1, w.densestPlant(w.plants().species().size(), 1), "no plant of a species not in the world");
        assertThrows(IllegalArgumentException.class, () -> w.densestPlant(0, 0));
    }
}
