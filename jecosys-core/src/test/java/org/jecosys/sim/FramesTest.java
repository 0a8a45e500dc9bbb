package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.jecosys.anim.AnimationMode;
import org.jecosys.math.ViewCamera;
import org.junit.jupiter.api.Test;

/** No torn frames: a reader never sees a frame being written, and frame numbers never go back. */
class FramesTest {
    @Test
    void aConcurrentReaderSeesOnlyCompleteFramesInOrder() throws Exception {
        try (Simulation sim = SimFixtures.c1(2)) {
            sim.loop.stampFrames = true; // every component of frame n carries D = (n, -n)
            AtomicBoolean done = new AtomicBoolean();
            AtomicReference<String> problem = new AtomicReference<>();
            AtomicLong checked = new AtomicLong();
            Thread reader = new Thread(() -> {
                long last = 0;
                while (!done.get() && problem.get() == null) {
                    Frame f = sim.latestFrame();
                    long n = f.number();
                    if (n < last) {
                        problem.set("frame " + n + " after " + last);
                    }
                    last = n;
                    if (n == 0) {
                        continue;
                    }
                    float s = (float) (n % 1_000_000);
                    for (int c = 0; c < f.componentCount(); c++) {
                        if (f.deviationX(c) != s || f.deviationZ(c) != -s) {
                            problem.set("frame " + n + " component " + c + " holds " + f.deviationX(c) + ", "
                                    + f.deviationZ(c));
                            break;
                        }
                    }
                    if (f.number() != n) {
                        problem.set("frame " + n + " changed while read");
                    }
                    checked.incrementAndGet();
                }
            }, "frame-reader");
            reader.start();
            ViewCamera cam = SimFixtures.camera();
            for (int i = 0; i < 4000 && problem.get() == null; i++) {
                sim.stepFixed(cam);
            }
            done.set(true);
            reader.join();
            assertEquals(null, problem.get());
            assertTrue(checked.get() > 10, "frames checked: " + checked.get());
        }
    }

    @Test
    void framesStartInTheWindAtTimeZeroAndCarryTheStepStatistics() throws Exception {
        try (Simulation sim = SimFixtures.c1(2)) {
            Frame f0 = sim.latestFrame();
            assertEquals(0, f0.number());
            int bent = 0;
            for (int c = 0; c < f0.componentCount(); c++) {
                assertEquals(sim.inspect().state().poseCoordinate(c), f0.poseCoord(c));
                assertEquals(sim.inspect().state().azimuth(c), f0.bendAzimuth(c));
                bent += f0.poseCoord(c) > 0 ? 1 : 0;
            }
            assertTrue(bent > f0.componentCount() / 2, "before the first step the meadow already leans in the wind: "
                    + bent + " of " + f0.componentCount());
            ViewCamera cam = SimFixtures.camera();
            for (int i = 0; i < 120; i++) {
                sim.stepFixed(cam);
            }
            Frame f = sim.latestFrame();
            assertEquals(120, f.number());
            assertEquals(2.0, f.time(), 1e-9);
            assertTrue(f.componentsAnimated() > 0);
            assertTrue(f.animationNanos() > 0);
            int visible = 0;
            for (int p = 0; p < f.plantCount(); p++) {
                visible += f.plantVisible(p) ? 1 : 0;
                assertEquals(sim.inspect().state().level(p), f.plantLevel(p));
            }
            assertTrue(visible > 0 && visible < f.plantCount(), "visible " + visible);
            for (int c = 0; c < f.componentCount(); c++) {
                assertEquals(sim.inspect().state().poseCoordinate(c), f.poseCoord(c));
            }
        }
    }
    /**
     * Every published frame holds the outputs of the state for every component, also for plants that
     * were not updated (culled, outside their level of detail) and across mode changes: the frames are
     * written only where the state changed and copied or kept elsewhere.
     */
    @Test
    void everyPublishedFrameCarriesTheOutputsOfTheWholeState() throws Exception {
        try (Simulation sim = SimFixtures.c1(2)) {
            ViewCamera cam = SimFixtures.camera();
            double yaw = cam.yaw();
            int culledChecked = 0;
            for (int i = 0; i < 240; i++) {
                if (i == 60) {
                    sim.setMode(AnimationMode.STATIC);
                } else if (i == 90) {
                    sim.setMode(AnimationMode.CONSTRAINT);
                } else if (i == 150) {
                    sim.setMode(AnimationMode.RANDOM);
                } else if (i == 170) {
                    sim.setMode(AnimationMode.CONSTRAINT);
                }
                cam.setOrientation(yaw + 0.03 * i, cam.pitch());
                sim.stepFixed(cam);
                Frame f = sim.latestFrame();
                assertEquals(i + 1, f.number());
                for (int p = 0; p < f.plantCount(); p++) {
                    culledChecked += f.plantVisible(p) ? 0 : 1;
                    int end = sim.inspect().state().firstComponent(p + 1);
                    for (int c = sim.inspect().state().firstComponent(p); c < end; c++) {
                        assertEquals(sim.inspect().state().deviationX(c), f.deviationX(c),
                                "step " + i + " component " + c);
                        assertEquals(sim.inspect().state().deviationZ(c), f.deviationZ(c),
                                "step " + i + " component " + c);
                        assertEquals(sim.inspect().state().deviationX(c), f.renderStates().getFloat(8 * c));
                        assertEquals(sim.inspect().state().deviationZ(c), f.renderStates().getFloat(8 * c + 4));
                        assertEquals(sim.inspect().state().poseCoordinate(c), f.poseCoord(c),
                                "step " + i + " component " + c);
                        assertEquals(sim.inspect().state().azimuth(c), f.bendAzimuth(c),
                                "step " + i + " component " + c);
                    }
                }
            }
            assertTrue(culledChecked > 0);
        }
    }

    /** A frame posed by hand ({@link Frame#set}) reads back the pose and azimuth it was given, to float rounding. */
    @Test
    void aFramePosedByHandReadsBackItsPosesAndAzimuths() throws Exception {
        try (Simulation sim = SimFixtures.c1(1)) {
            Frame f = new Frame(sim.plantCount(), sim.bendGeometry());
            java.util.Random rnd = new java.util.Random(7);
            for (int c = 0; c < f.componentCount(); c++) {
                assertEquals(0f, f.poseCoord(c));
                float max = f.geometry().poseMax(c);
                float pose = (float) (rnd.nextDouble() * max);
                float az = (float) rnd.nextDouble(-Math.PI, Math.PI);
                f.set(c, pose, az);
                assertEquals(pose, f.poseCoord(c), 2e-3 * Math.max(1, max), "component " + c);
                if (pose > 0.05) { // at pose 0 the azimuth is the rest heading's, not the one given
                    double turn = Math.IEEEremainder(f.bendAzimuth(c) - az, 2 * Math.PI);
                    assertEquals(0, turn, 1e-4, "component " + c);
                }
            }
        }
    }
}
