package org.jecosys.anim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import org.jecosys.math.Rng;
import org.junit.jupiter.api.Test;

/**
 * {@link AnimationState#copyDeviations}: each run's D spread to its components and a scattered plant's
 * own D, equal to the per-component accessors bit for bit, and nothing outside the range written.
 */
class CopyDeviationsTest {
    @Test
    void everyComponentGetsItsDeviationWhateverTheScratch() {
        SpringKinds.Builder b = new SpringKinds.Builder();
        b.add(0.2, 0.3, 0.0004, 0.002, 0.4, 0.05, 1.2, 16, 0xFF);
        b.add(0.5, 0.6, 0.0008, 0.003, 0.3, 0.02, 1.0, 16, 0xFF);
        int plants = 5;
        int[] first = {0, 7, 8, 20, 20, 26};
        int[] kind = new int[26];
        float[] heading = new float[26];
        for (int c = 0; c < kind.length; c++) {
            kind[c] = (c % 5) < 3 ? 0 : 1; // several runs per plant
            heading[c] = 0.3f * c;
        }
        AnimationState s = new AnimationState(b.build(), new double[][] {{10, 15}}, new int[plants], first,
                new float[plants], new float[plants], new float[plants], kind, heading);
        s.kinds().prepare(1.0 / 60, 4);
        float[] wx = {3, -2, 5, 1, 4};
        float[] wz = {1, 2, -3, 0, 2};
        boolean[] all = {true, true, true, true, true};
        for (int i = 0; i < 20; i++) {
            s.animate(0, plants, AnimationStep.of(AnimationMode.CONSTRAINT, wx, wz, all));
        }
        // plant 2 (components 8-19; plant 3 has none) scatters: its components take deviations of their own
        s.animate(2, 3, AnimationStep.of(AnimationMode.RANDOM, wx, wz, all).rng(Rng.forStream(7, 0)));
        assertNotEquals(s.deviationX(8), s.deviationX(9));
        ByteBuffer bytes = ByteBuffer.allocateDirect(8 * 27).order(ByteOrder.LITTLE_ENDIAN);
        FloatBuffer dest = bytes.asFloatBuffer();
        dest.put(52, 99f).put(53, 99f);
        s.copyDeviations(first[1], first[plants], bytes.asLongBuffer());
        assertThrows(IllegalArgumentException.class, () -> s.copyDeviations(first[1], first[plants],
                ByteBuffer.allocateDirect(8 * 27).order(ByteOrder.BIG_ENDIAN).asLongBuffer()));
        for (int c = 0; c < 26; c++) {
            float x = c < first[1] ? 0f : s.deviationX(c);
            float z = c < first[1] ? 0f : s.deviationZ(c);
            assertEquals(x, dest.get(2 * c), "X of component " + c);
            assertEquals(z, dest.get(2 * c + 1), "Z of component " + c);
            if (c >= first[1]) {
                assertEquals(s.poseCoordinate(c), s.geometry().poseCoordinate(c, x, z), "pose of component " + c);
            }
        }
        assertEquals(99f, dest.get(52), "nothing written past the range");
    }
}
