package org.jecosys.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Random;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.jecosys.math.Camera;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.wind.AbstractWindSource;
import org.joml.Matrix4f;
import org.joml.Vector2d;
import org.joml.Vector3f;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

/**
 * Reliability, fourth pass, faults 1 and 9: a game's own flow or camera that throws during a step
 * (while the workers animate beside the field) never leaves the worker pool busy: the exception
 * reaches the caller as it was thrown, the next step runs, and {@link Simulation#close()} returns
 * promptly. A camera or view that is not finite is refused with a message before anything moves.
 * {@code -Djecosys.userCode.trials=1000} runs more trials.
 */
@Tag("reliability")
class UserCodeReliabilityTest {
    /**
     * Trials per worker count and kind of fault: 100 in the default run (the whole test run must stay
     * under 6 minutes on 2 cores); the issue that asked for this test asked 200, which
     * {@code -Djecosys.userCode.trials=200} runs.
     */
    static final int TRIALS = Integer.getInteger("jecosys.userCode.trials", 100);
    /** Far beyond any step of the fixture: past it, a thread is hung. */
    private static final long HANG_MILLIS = 20_000;
    /** What close() may take once the step that threw has returned. */
    private static final long CLOSE_MILLIS = 1_000;

    private static SceneDef scene;
    private static World world;

    /** 2,000 tufts of 25 leaves: 50,000 components, every one in view (the close-race fixture). */
    private static synchronized World world() throws Exception {
        if (world == null) {
            scene = SceneFiles.parse(Path.of("jecosys-core/src/test/resources/org/jecosys/sim/close-race-fixture.xml"));
            world = World.build(scene.simulationDef(), Path.of("scenes"), 2, Progress.NONE);
        }
        return world;
    }

    /** The game's fault: a RuntimeException of its own. */
    static final class GameFault extends RuntimeException {
        GameFault(String message) {
            super(message);
        }
    }

    /**
     * A countdown that throws when it reaches zero: armed at a random call of the game's code, so the
     * fault strikes before the workers start, beside them, or at the end of the field's work.
     */
    static final class Trap {
        private final AtomicLong left = new AtomicLong(-1);
        final AtomicLong calls = new AtomicLong();

        void arm(long afterCalls) {
            left.set(afterCalls);
        }

        void disarm() {
            left.set(-1);
        }

        void call() {
            calls.incrementAndGet();
            if (left.get() >= 0 && left.getAndDecrement() == 0) {
                throw new GameFault("the game's own code failed");
            }
        }
    }

    /** A game's flow: a light breeze that throws when its trap springs. */
    static final class TrappedFlow extends AbstractWindSource {
        final Trap trap = new Trap();

        TrappedFlow() {
            super("game-flow");
        }

        @Override
        protected void flow(double x, double z, double time, Vector2d dest) {
            trap.call();
            dest.set(0.5, 0.2);
        }
    }

    /** A game's camera: the scene's camera, throwing when its trap springs. */
    static final class TrappedCamera implements Camera {
        final Trap trap = new Trap();
        final ViewCamera inner;

        TrappedCamera(ViewCamera inner) {
            this.inner = inner;
        }

        @Override
        public double x() {
            trap.call();
            return inner.x();
        }

        @Override
        public double y() {
            trap.call();
            return inner.y();
        }

        @Override
        public double z() {
            trap.call();
            return inner.z();
        }

        @Override
        public Vector3f forward(Vector3f dest) {
            trap.call();
            return inner.forward(dest);
        }

        @Override
        public Matrix4f view(Matrix4f dest) {
            trap.call();
            return inner.view(dest);
        }

        @Override
        public Matrix4f projection(Matrix4f dest) {
            trap.call();
            return inner.projection(dest);
        }

        @Override
        public Matrix4f viewProjection(Matrix4f dest) {
            trap.call();
            return inner.viewProjection(dest);
        }

        @Override
        public double viewHeightPerMetre() {
            trap.call();
            return inner.viewHeightPerMetre();
        }

        @Override
        public double viewHeightAtEye() {
            trap.call();
            return inner.viewHeightAtEye();
        }
    }

    @ParameterizedTest(name = "{0} workers")
    @ValueSource(ints = {2, 4})
    void aThrowingFlowReachesTheCallerAndTheNextStepRuns(int workers) throws Exception {
        World w = world();
        ViewCamera cam = ViewCamera.of(scene.camera(), 0, 16.0 / 9);
        Random rnd = new Random(31 + workers);
        for (int trial = 0; trial < TRIALS; trial++) {
            Simulation sim = Simulation.of(w, scene.simulationDef(), workers);
            TrappedFlow flow = new TrappedFlow();
            sim.addFlow(flow);
            runTrial("flow, " + workers + " workers, trial " + trial, sim, cam, flow.trap, rnd);
        }
    }

    @ParameterizedTest(name = "{0} workers")
    @ValueSource(ints = {2, 4})
    void aThrowingCameraReachesTheCallerAndTheNextStepRuns(int workers) throws Exception {
        World w = world();
        TrappedCamera cam = new TrappedCamera(ViewCamera.of(scene.camera(), 0, 16.0 / 9));
        Random rnd = new Random(37 + workers);
        for (int trial = 0; trial < TRIALS; trial++) {
            Simulation sim = Simulation.of(w, scene.simulationDef(), workers);
            runTrial("camera, " + workers + " workers, trial " + trial, sim, cam, cam.trap, rnd);
        }
    }

    /**
     * Steps once or twice normally (counting the game's calls per step), arms the trap at a random
     * call of the next step, steps (the fault must come out as it is), disarms, steps again (it must
     * publish a new frame), then closes within {@link #CLOSE_MILLIS}. Each step runs on a thread of
     * its own, so that a hang fails the test instead of stopping it.
     */
    private static void runTrial(String what, Simulation sim, Camera cam, Trap trap, Random rnd) throws Exception {
        try {
            int warm = 2 + rnd.nextInt(2); // the first step also primes: count the calls of a later one
            long before = 0;
            for (int i = 0; i < warm; i++) {
                before = trap.calls.get();
                assertSame(null, stepOn(what, sim, cam), what + ": a normal step failed");
            }
            long perStep = Math.max(1, trap.calls.get() - before);
            trap.arm(rnd.nextLong(perStep));
            Throwable fault = stepOn(what, sim, cam);
            assertTrue(fault instanceof GameFault, what + ": the game's exception reaches the caller as it is, got " + fault);
            trap.disarm();
            long frames = sim.inspect().steps();
            assertSame(null, stepOn(what, sim, cam), what + ": the step after the fault failed");
            assertEquals(frames + 1, sim.inspect().steps(), what + ": the step after the fault ran");
        } finally {
            long t0 = System.nanoTime();
            Thread closer = new Thread(sim::close, "user-code-closer");
            closer.setDaemon(true);
            closer.start();
            closer.join(HANG_MILLIS);
            assertFalse(closer.isAlive(), what + ": close() hung");
            long millis = (System.nanoTime() - t0) / 1_000_000;
            assertTrue(millis <= CLOSE_MILLIS, what + ": close() took " + millis + " ms");
        }
        IllegalStateException closed = assertThrows(IllegalStateException.class, () -> sim.stepFixed(cam));
        assertEquals(Simulation.CLOSED, closed.getMessage());
    }

    /** One fixed step on a thread of its own; what it threw, or null. Fails when it hangs. */
    private static Throwable stepOn(String what, Simulation sim, Camera cam) throws InterruptedException {
        AtomicReference<Throwable> thrown = new AtomicReference<>();
        Thread t = new Thread(() -> {
            try {
                sim.stepFixed(cam);
            } catch (Throwable e) {
                thrown.set(e);
            }
        }, "user-code-stepper");
        t.setDaemon(true);
        t.start();
        t.join(HANG_MILLIS);
        assertFalse(t.isAlive(), what + ": the step hung");
        return thrown.get();
    }

    @Test
    void aStepStuckInTheGamesFlowDoesNotHoldCloseAndEndsAloneWhenTheFlowReturns() throws Exception {
        World w = world();
        ViewCamera cam = ViewCamera.of(scene.camera(), 0, 16.0 / 9);
        Simulation sim = Simulation.of(w, scene.simulationDef(), 2);
        java.util.concurrent.CountDownLatch entered = new java.util.concurrent.CountDownLatch(1);
        java.util.concurrent.CountDownLatch release = new java.util.concurrent.CountDownLatch(1);
        sim.stepFixed(cam);
        sim.addFlow(new AbstractWindSource("stuck") {
            @Override
            protected void flow(double x, double z, double time, Vector2d dest) {
                entered.countDown();
                try {
                    release.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                dest.set(0, 0);
            }
        });
        AtomicReference<Throwable> end = new AtomicReference<>();
        Thread stepper = new Thread(() -> {
            try {
                sim.stepFixed(cam);
            } catch (Throwable e) {
                end.set(e);
            }
        });
        stepper.setDaemon(true);
        stepper.start();
        assertTrue(entered.await(HANG_MILLIS, java.util.concurrent.TimeUnit.MILLISECONDS), "the flow was never called");
        long t0 = System.nanoTime();
        Thread closer = new Thread(sim::close, "user-code-closer");
        closer.setDaemon(true);
        closer.start();
        closer.join(HANG_MILLIS / 4);
        long millis = (System.nanoTime() - t0) / 1_000_000;
        release.countDown();
        assertFalse(closer.isAlive(), "close() waited " + millis + " ms for a step that could not finish");
        assertTrue(millis <= 2 * Simulation.CLOSE_WAIT_MILLIS + CLOSE_MILLIS, "close() took " + millis + " ms");
        stepper.join(HANG_MILLIS);
        assertFalse(stepper.isAlive(), "the stuck step never ended after its flow returned");
        assertSame(null, end.get(), "the step that close() overtook ends normally");
        assertThrows(IllegalStateException.class, () -> sim.stepFixed(cam));
    }

    /** A game's camera whose eye or lens it sets itself, without the checks of MatrixCamera. */
    static final class LooseCamera implements Camera {
        final ViewCamera inner;
        double x;
        float m00 = Float.NaN;
        boolean badEye;
        boolean badLens;

        LooseCamera(ViewCamera inner) {
            this.inner = inner;
        }

        @Override
        public double x() {
            return badEye ? x : inner.x();
        }

        @Override
        public double y() {
            return inner.y();
        }

        @Override
        public double z() {
            return inner.z();
        }

        @Override
        public Vector3f forward(Vector3f dest) {
            return inner.forward(dest);
        }

        @Override
        public Matrix4f view(Matrix4f dest) {
            return inner.view(dest);
        }

        @Override
        public Matrix4f projection(Matrix4f dest) {
            inner.projection(dest);
            return badLens ? dest.m00(m00) : dest;
        }

        @Override
        public Matrix4f viewProjection(Matrix4f dest) {
            inner.viewProjection(dest);
            return badLens ? dest.m00(m00) : dest;
        }

        @Override
        public double viewHeightPerMetre() {
            return inner.viewHeightPerMetre();
        }

        @Override
        public double viewHeightAtEye() {
            return inner.viewHeightAtEye();
        }
    }

    @Test
    void aCameraOrViewThatIsNotFiniteIsRefusedBeforeAnythingMoves() throws Exception {
        try (Simulation sim = SimFixtures.c1(2)) {
            ViewCamera good = SimFixtures.camera();
            sim.stepFixed(good);
            long steps = sim.inspect().steps();
            double[] bad = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};
            for (double v : bad) {
                LooseCamera eyeless = new LooseCamera(good);
                eyeless.badEye = true;
                eyeless.x = v;
                IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> sim.stepFixed(eyeless));
                assertTrue(e.getMessage().startsWith("camera: its eye position must be finite"), e.getMessage());
                assertThrows(IllegalArgumentException.class, () -> sim.step(1, eyeless));
                LooseCamera lens = new LooseCamera(good);
                lens.badLens = true;
                lens.m00 = (float) v;
                e = assertThrows(IllegalArgumentException.class, () -> sim.stepFixed(lens));
                assertTrue(e.getMessage().startsWith("camera: its view-projection matrix"), e.getMessage());
                e = assertThrows(IllegalArgumentException.class, () -> sim.addView(lens));
                assertTrue(e.getMessage().startsWith("view: "), e.getMessage());
            }
            assertEquals(steps, sim.inspect().steps(), "no refused step ran");
            // a registered view that turns NaN later is refused at the step, by its index
            LooseCamera later = new LooseCamera(good);
            sim.addView(later);
            sim.stepFixed(good);
            later.badLens = true;
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> sim.stepFixed(good));
            assertTrue(e.getMessage().startsWith("view 0 (registered with addView): "), e.getMessage());
            sim.removeView(later);
            sim.stepFixed(good);
            assertEquals(steps + 2, sim.inspect().steps());
        }
    }
}
