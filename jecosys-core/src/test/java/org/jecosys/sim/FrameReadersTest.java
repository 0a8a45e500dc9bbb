package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.jecosys.math.ViewCamera;
import org.junit.jupiter.api.Test;

/**
 * Frames are never torn, whatever the number of reader threads: {@code latestFrame()} serves one
 * thread and refuses a second one with a clear message; {@code copyLatestFrame} gives every thread a
 * complete copy. Every component of frame n carries n (pose) and -n (azimuth), so one component of
 * another frame shows.
 */
class FrameReadersTest {
    private static final int COPIERS = 3;

    @Test
    void aSecondThreadCallingLatestFrameIsRefusedWithAClearMessage() throws Exception {
        try (Simulation sim = SimFixtures.c1(1)) {
            AtomicReference<Frame> first = new AtomicReference<>();
            Thread reader = new Thread(() -> first.set(sim.latestFrame()), "renderer");
            CountDownLatch hold = new CountDownLatch(1);
            Thread owner = new Thread(() -> {
                sim.latestFrame();
                try {
                    hold.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "renderer");
            owner.start();
            while (owner.getState() != Thread.State.WAITING) {
                Thread.onSpinWait();
            }
            IllegalStateException ex = assertThrows(IllegalStateException.class, sim::latestFrame);
            assertTrue(ex.getMessage().contains("one reader thread, 'renderer'"), ex.getMessage());
            assertTrue(ex.getMessage().contains("copyLatestFrame"), ex.getMessage());
            hold.countDown();
            owner.join();
            // the reader has ended: another thread may take over
            reader.start();
            reader.join();
            assertEquals(0, first.get().number());
        }
    }

    @Test
    void everyReaderThreadSeesOnlyCompleteFramesInOrder() throws Exception {
        try (Simulation sim = SimFixtures.c1(2)) {
            sim.loop.stampFrames = true;
            AtomicBoolean done = new AtomicBoolean();
            AtomicReference<String> problem = new AtomicReference<>();
            AtomicLong checked = new AtomicLong();
            List<Thread> readers = new ArrayList<>();
            for (int t = 0; t <= COPIERS; t++) {
                boolean primary = t == 0;
                Frame own = new Frame(sim.plantCount(), sim.bendGeometry());
                Thread r = new Thread(() -> {
                    long last = 0;
                    while (!done.get() && problem.get() == null) {
                        Frame f = primary ? sim.latestFrame() : sim.copyLatestFrame(own);
                        long n = f.number();
                        if (n < last) {
                            problem.compareAndSet(null, Thread.currentThread().getName() + ": frame " + n + " after "
                                    + last);
                        }
                        last = n;
                        if (n == 0) {
                            continue;
                        }
                        float s = (float) (n % 1_000_000);
                        for (int c = 0; c < f.componentCount(); c++) {
                            if (f.deviationX(c) != s || f.deviationZ(c) != -s) {
                                problem.compareAndSet(null, Thread.currentThread().getName() + ": frame " + n
                                        + " component " + c + " holds " + f.deviationX(c) + ", " + f.deviationZ(c));
                                break;
                            }
                        }
                        if (f.number() != n) {
                            problem.compareAndSet(null, Thread.currentThread().getName() + ": frame " + n
                                    + " changed while read");
                        }
                        checked.incrementAndGet();
                    }
                }, primary ? "renderer" : "copier-" + t);
                readers.add(r);
                r.start();
            }
            ViewCamera cam = SimFixtures.camera();
            for (int i = 0; i < 1500 && problem.get() == null; i++) {
                sim.stepFixed(cam);
            }
            done.set(true);
            for (Thread r : readers) {
                r.join();
            }
            assertNull(problem.get());
            assertTrue(checked.get() > 10, "frames checked: " + checked.get());
        }
    }

    @Test
    void aCopyNeedsAFrameOfTheSimulationsSizes() throws Exception {
        try (Simulation sim = SimFixtures.c1(1)) {
            assertThrows(IllegalArgumentException.class, () -> sim.copyLatestFrame(null));
            assertThrows(IllegalArgumentException.class, () -> sim.copyLatestFrame(new Frame(1, sim.bendGeometry())));
            Frame own = new Frame(sim.plantCount(), sim.bendGeometry());
            sim.stepFixed(SimFixtures.camera());
            assertSame(own, sim.copyLatestFrame(own));
            assertEquals(1, own.number());
        }
    }
}
