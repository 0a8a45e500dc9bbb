package org.jecosys.math;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** {@link Boxes}: nearest and farthest squared distances of a box read from an offset. */
class BoxesTest {
    private static final float[] BOXES = {9, 9, 9, 9, 9, 9, -1, 0, 2, 3, 1, 5};

    @Test
    void insideTheNearestIsZeroAndTheFarthestACorner() {
        assertEquals(0, Boxes.near2(BOXES, 6, 0, 0.5, 3), 0);
        // farthest corner from (0, 0.5, 3): (3, 0 or 1, 5)
        assertEquals(9 + 0.25 + 4, Boxes.far2(BOXES, 6, 0, 0.5, 3), 0);
    }

    @Test
    void outsideEachAxisCountsItsGap() {
        // (-4, 3, 7): 3 before X, 2 above Y, 2 past Z
        assertEquals(9 + 4 + 4, Boxes.near2(BOXES, 6, -4, 3, 7), 0);
        // farthest corner (3, 0, 2): 7, 3, 5
        assertEquals(49 + 9 + 25, Boxes.far2(BOXES, 6, -4, 3, 7), 0);
    }
}
