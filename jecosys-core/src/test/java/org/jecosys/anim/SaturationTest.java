package org.jecosys.anim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * {@link SpringRuns#saturation}, written with comparisons, gives the bits of its formula written with
 * {@code Math.min} and {@code Math.max} for every number it takes (finite, &gt;= 0): zero, subnormals,
 * around the knee and far beyond it; and, up to the rest point's cap, it stays in (0, 1].
 */
class SaturationTest {
    private static final float KNEE = SpringKinds.KNEE;
    private static final float SPAN = 1 - KNEE;

    private static float reference(float x) {
        if (x <= KNEE && x >= Float.MIN_NORMAL) {
            return 1f;
        }
        float u = Math.max(0f, (x - KNEE) * (1 / SPAN));
        float w = 1f + u;
        return (Math.min(x, KNEE) * w + SPAN * u) / (Math.max(x, Float.MIN_NORMAL) * w);
    }

    @Test
    void comparisonsGiveTheMinMaxBits() {
        SplittableRandom r = new SplittableRandom(3);
        float[] special = {0f, Float.MIN_VALUE, Float.MIN_NORMAL, Math.nextDown(Float.MIN_NORMAL),
            Math.nextUp(Float.MIN_NORMAL), KNEE, Math.nextDown(KNEE), Math.nextUp(KNEE), 1f, 1e12f, Float.MAX_VALUE / 4};
        int n = 0;
        for (int i = 0; i < 200_000; i++) {
            float x = i < special.length ? special[i]
                    : i % 2 == 0 ? (float) (r.nextDouble() * 3) : Float.intBitsToFloat(r.nextInt(0x7F000000));
            float s = SpringRuns.saturation(x);
            assertEquals(Float.floatToRawIntBits(reference(x)), Float.floatToRawIntBits(s), "x = " + x);
            if (x <= SpringRuns.MAX_TARGET_KNEES) { // the rest point caps x there
                assertTrue(s > 0 && s <= 1 || x == 0, "x = " + x + ": " + s);
            }
            n++;
        }
        assertEquals(200_000, n);
    }
}
