package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class LodChooserTest {
    private final LodChooser chooser = new LodChooser(SpeciesLibrary.table3Lods(), 1.0);

    @Test
    void levelsAtBandEdges() {
        assertEquals(3, chooser.levels());
        assertEquals(0, chooser.level(0));
        assertEquals(0, chooser.level(Math.nextDown(10.0)));
        assertEquals(1, chooser.level(10.0));
        assertEquals(1, chooser.level(Math.nextDown(15.0)));
        assertEquals(2, chooser.level(15.0));
        assertEquals(2, chooser.level(1e9));
        assertEquals(0, chooser.level(-3));
    }

    @Test
    void fadeRisesAcrossTheBandAndIsContinuousAtTheEdge() {
        assertEquals(0, chooser.fade(9.0), 0);
        assertEquals(0.5, chooser.fade(9.5), 1e-12);
        assertEquals(1.0, chooser.coordinate(Math.nextDown(10.0)), 1e-9);
        assertEquals(1.0, chooser.coordinate(10.0), 0);
        assertEquals(1.5, chooser.coordinate(14.5), 1e-12);
        assertEquals(2.0, chooser.coordinate(15.0), 0);
        assertEquals(0, chooser.fade(100), 0);
        double prev = 0;
        for (int i = 0; i <= 4000; i++) {
            double c = chooser.coordinate(i * 0.005);
            assertTrue(c >= prev && c - prev < 0.01, "continuous, non-decreasing at " + i * 0.005);
            prev = c;
        }
    }

    @Test
    void ditheringSplitsInstancesByFade() {
        assertEquals(0, LodChooser.ditheredLevel(0.25, 0.3));
        assertEquals(1, LodChooser.ditheredLevel(0.25, 0.2));
        assertEquals(2, LodChooser.ditheredLevel(2.0, 0.0));
    }

    @Test
    void zeroBandSwitchesHard() {
        LodChooser hard = new LodChooser(SpeciesLibrary.table3Lods(), 0);
        assertEquals(0, hard.coordinate(9.999), 0);
        assertEquals(1, hard.coordinate(10), 0);
    }

    @Test
    void bandWiderThanAGapIsRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new LodChooser(SpeciesLibrary.table3Lods(), 6));
        assertTrue(e.getMessage().contains("bandWidth"));
    }
}
