package org.jecosys.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The element checks name {@code array[index]} exactly as a check given that name would, and build the
 * name only when they throw: a loop over a tile's components allocates nothing.
 */
class RequireElementTest {
    private static String message(Runnable r) {
        return assertThrows(IllegalArgumentException.class, r::run).getMessage();
    }

    @Test
    void anElementOutOfRangeIsNamedAsBefore() {
        assertEquals(3, Require.elementRange("kind", 7, 3, 0, 5));
        assertEquals(0.5, Require.elementRange("w", 2, 0.5, 0, 1));
        assertEquals(1.0, Require.elementAbove("d", 1, 1.0, 0, 2));
        assertEquals("x", Require.elementNonNull("defs", 0, "x"));
        assertEquals(message(() -> Require.range("kind[7]", 9, 0, 5)), message(() -> Require.elementRange("kind", 7, 9, 0, 5)));
        assertEquals(message(() -> Require.range("w[2]", 1.5, 0, 1)), message(() -> Require.elementRange("w", 2, 1.5, 0, 1)));
        assertEquals(message(() -> Require.range("w[2]", Double.NaN, 0, 1)),
                message(() -> Require.elementRange("w", 2, Double.NaN, 0, 1)));
        assertEquals(message(() -> Require.range("w[2]", Double.POSITIVE_INFINITY, 0, Double.POSITIVE_INFINITY)),
                message(() -> Require.elementRange("w", 2, Double.POSITIVE_INFINITY, 0, Double.POSITIVE_INFINITY)));
        assertEquals(message(() -> Require.above("d[1]", 0, 0, 2)), message(() -> Require.elementAbove("d", 1, 0, 0, 2)));
        assertEquals(message(() -> Require.nonNull("defs[4]", null)), message(() -> Require.elementNonNull("defs", 4, null)));
        assertTrue(message(() -> Require.elementRange("kind", 7, -1, 0, 5)).startsWith("kind[7] must be in [0, 5]"));
    }

    @Test
    void aPassingElementCheckAllocatesNothing() {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean)
                java.lang.management.ManagementFactory.getThreadMXBean();
        int[] v = new int[100_000];
        double[] d = new double[100_000];
        long sum = 0;
        for (int warm = 0; warm < 3; warm++) {
            long before = mx.getThreadAllocatedBytes(Thread.currentThread().getId());
            for (int i = 0; i < v.length; i++) {
                v[i] = i % 5;
                d[i] = (i % 7) / 7.0;
                sum += Require.elementRange("v", i, v[i], 0, 4);
                sum += (long) Require.elementRange("d", i, d[i], 0, 1);
            }
            long bytes = mx.getThreadAllocatedBytes(Thread.currentThread().getId()) - before;
            if (warm == 2) {
                // the bean's own reads may allocate a little; 200,000 names would take megabytes
                assertTrue(bytes < 4096, "200,000 passing element checks allocated " + bytes + " bytes");
            }
        }
        assertTrue(sum > 0);
    }
}
