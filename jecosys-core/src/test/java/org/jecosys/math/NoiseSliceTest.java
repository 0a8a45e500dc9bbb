package org.jecosys.math;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

/** {@link Noise.Slice1} gives {@link Noise#value1}'s bits for every seed at its coordinate. */
class NoiseSliceTest {
    @Test
    void sliceMatchesValue1BitForBit() {
        SplittableRandom r = new SplittableRandom(11);
        Noise.Slice1 slice = new Noise.Slice1();
        double[] xs = {0, -0.0, 1, -1, 0.5, -0.5, 1e-300, 123456.789, -98765.4321, Math.nextDown(1.0), 1e15};
        for (int i = 0; i < 2000; i++) {
            double x = i < xs.length ? xs[i] : (r.nextDouble() - 0.5) * Math.pow(10, r.nextInt(-3, 9));
            slice.at(x);
            for (int k = 0; k < 20; k++) {
                long seed = k == 0 ? 0 : k == 1 ? -1 : r.nextLong();
                double expected = Noise.value1(seed, x);
                assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(slice.value(seed)),
                        () -> "x=" + x + " seed=" + seed);
            }
        }
    }

    @Test
    void sliceFollowsItsCoordinate() {
        Noise.Slice1 slice = new Noise.Slice1().at(0.25);
        double a = slice.value(42);
        double b = slice.at(3.75).value(42);
        assertEquals(Noise.value1(42, 0.25), a, 0);
        assertEquals(Noise.value1(42, 3.75), b, 0);
    }
}
