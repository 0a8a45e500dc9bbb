package org.jecosys.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;

/**
 * The streamer's tile workers ({@link BuildWorkers}): every build handed in runs once, also when the
 * workers park between hand-ins (no hand-in is lost between a worker's last look at the queue and its
 * park); a stop lets the running build finish and cancels those not started.
 */
class BuildWorkersTest {
    @Test
    void everyBuildRunsOnceAlsoWhenTheWorkersParkBetweenHandIns() throws Exception {
        BuildWorkers w = new BuildWorkers("build-test", 2);
        try {
            int n = 3000;
            int[] runs = new int[n];
            List<Future<Integer>> results = new ArrayList<>();
            for (int k = 0; k < n; k++) {
                int task = k;
                results.add(w.submit(() -> {
                    runs[task]++;
                    return task * 7;
                }));
                if (k % 3 == 0) {
                    LockSupport.parkNanos(k % 2 == 0 ? 50_000 : 5_000); // idle workers park in the gaps
                }
            }
            for (int k = 0; k < n; k++) {
                assertEquals(k * 7, results.get(k).get(20, TimeUnit.SECONDS), "build " + k);
            }
            for (int k = 0; k < n; k++) {
                assertEquals(1, runs[k], "build " + k + " ran once");
            }
        } finally {
            w.shutdownNow();
        }
    }

    @Test
    void aStopLetsTheRunningBuildFinishAndCancelsTheRest() throws Exception {
        BuildWorkers w = new BuildWorkers("build-test", 1);
        CountDownLatch started = new CountDownLatch(1);
        CountDownLatch release = new CountDownLatch(1);
        Future<String> running = w.submit(() -> {
            started.countDown();
            release.await(20, TimeUnit.SECONDS);
            return "done";
        });
        assertTrue(started.await(20, TimeUnit.SECONDS), "the first build started");
        List<Future<String>> queued = new ArrayList<>();
        for (int k = 0; k < 3; k++) {
            queued.add(w.submit(() -> "never"));
        }
        w.shutdownNow();
        release.countDown();
        for (Future<String> f : queued) {
            assertTrue(f.isCancelled(), "a build not started is cancelled");
        }
        // the stop interrupts the worker: a build that waits sees it, as a tile's build gate does
        assertTrue(running.isDone() || waitDone(running), "the running build finished");
        assertThrows(IllegalStateException.class, () -> w.submit(() -> "late"), "no hand-in after a stop");
    }

    private static boolean waitDone(Future<?> f) {
        long until = System.nanoTime() + 20_000_000_000L;
        while (!f.isDone() && System.nanoTime() < until) {
            LockSupport.parkNanos(1_000_000);
        }
        return f.isDone();
    }
}
