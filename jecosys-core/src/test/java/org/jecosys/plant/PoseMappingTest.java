package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class PoseMappingTest {
    @Test
    void zeroDeviationIsRestPose() {
        assertEquals(0, PoseMapping.poseCoordinate(0, 0.4, 1.2, 16), 0);
        assertEquals(0, PoseMapping.poseCoordinate(Double.NaN, 0.4, 1.2, 16), 0);
    }

    @Test
    void mapsTheLengthKeepingAngleLinearlyAndSaturates() {
        double l = 0.5;
        double maxBend = 1.0;
        double d = l * Math.sin(0.5); // the tip of a 0.5 m component turned by 0.5 rad
        assertEquals(15, PoseMapping.poseCoordinate(l * Math.sin(maxBend), l, maxBend, 16), 1e-12);
        assertEquals(15, PoseMapping.poseCoordinate(l, l, maxBend, 16), 0);
        assertEquals(7.5, PoseMapping.poseCoordinate(d, l, maxBend, 16), 1e-12);
        assertEquals(7.5, PoseMapping.poseCoordinate(-d, l, maxBend, 16), 1e-12);
        assertEquals(15, PoseMapping.poseCoordinate(100, l, maxBend, 16), 0);
        assertEquals(7, PoseMapping.poseIndex(7.5, 16));
        assertEquals(0.5, PoseMapping.blendWeight(7.5, 16), 1e-12);
        assertEquals(14, PoseMapping.poseIndex(15, 16));
        assertEquals(1.0, PoseMapping.blendWeight(15, 16), 0);
    }

    @Test
    void monotonicInDeviation() {
        double prev = -1;
        for (int i = 0; i <= 1000; i++) {
            double c = PoseMapping.poseCoordinate(i * 1e-3, 0.3, 0.9, 16);
            assertTrue(c >= prev);
            assertTrue(c >= 0 && c <= 15);
            prev = c;
        }
    }
}
