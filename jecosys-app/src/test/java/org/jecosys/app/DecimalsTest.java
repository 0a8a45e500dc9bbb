package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** Values set through float sliders are kept as the decimal the slider showed. */
class DecimalsTest {
    @Test
    void aFloatBecomesItsShortestDecimal() {
        assertEquals("43.145999908447266", Double.toString((double) 43.146f), "the issue's saved value");
        assertEquals(43.146, Decimals.ofFloat(43.146f));
        assertEquals(0.1, Decimals.ofFloat(0.1f));
        assertEquals(-2.7, Decimals.ofFloat(-2.7f));
        assertEquals(1e-7, Decimals.ofFloat(1e-7f));
        assertEquals(Double.POSITIVE_INFINITY, Decimals.ofFloat(Float.POSITIVE_INFINITY));
        assertEquals(3.47, Decimals.round(3.47283, 2));
        assertEquals(-0.5, Decimals.round(-0.499, 2));
        assertEquals(12, Decimals.significant(12.345678, 2));
        assertEquals(0.37, Decimals.significant(0.36789, 2));
        assertEquals("43.146", ViewerPanel.number(Decimals.ofFloat(43.146f)));
        assertEquals("4", ViewerPanel.number(4.0));
    }
}
