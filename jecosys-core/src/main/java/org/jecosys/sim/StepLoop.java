package org.jecosys.sim;

import java.util.concurrent.locks.ReentrantLock;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.anim.AnimationState;
import org.jecosys.anim.AnimationStep;
import org.jecosys.anim.SpringKinds;
import org.jecosys.field.ForceField;
import org.jecosys.field.ForceFieldFactory;
import org.jecosys.math.Camera;
import org.jecosys.wind.WindField;

/**
 * The running parts of a {@link Simulation}, wired from its world and def, and its fixed-step loop
 * (paper §5.1; "Stepping" and "Start" in the Simulation's comment): the accumulator and its cap on
 * sub-steps, one fixed step (commands, the field beside the animation workers, publication), the
 * priming before the first, the registered views, the clock, mode and field switch, and closing.
 *
 * <p>Threads: {@link #step} and {@link #stepFixed} on the stepping thread, each under the step lock;
 * {@link #addView}, {@link #removeView} and {@link #close} from any thread. Allocation: the parts at
 * construction; a step nothing after warm-up; a view change a small array.
 */
final class StepLoop {
    private static final Camera[] NO_VIEWS = {};

    final WindField wind;
    final ForceField field;
    final AnimationState state;
    final FrameExchange exchange;
    final WorkerPool pool;
    final ChunkAnimator chunkAnimator;
    /** Double-buffered field samples (wind, visibility, eye, frustum, flow switches). */
    final FieldSampler sampler;
    final DrawDecision draw;
    /** The command queue and the flow-id reservations. */
    final Commands commands;
    private final SpringKinds kinds;
    private final int plants;
    private final double fixedStep;
    private final int maxSubSteps;
    private final int subIntervals;
    /** Whether the constructor put the plants at the equilibrium of the wind at t = 0. */
    private final boolean settledAtBuild;
    /** Fixed steps still to run before the first step a caller asks for ({@link AnimationDef#prewarm()}). */
    private int prewarmSteps;

    private AnimationMode mode;
    private boolean fieldEnabled;
    private double accumulator;
    private boolean primed;
    private int current;
    private long steps;
    private double time;
    private long droppedSteps;
    private volatile long steppingThread = -1;
    /** Set first by {@link #close()}: steps and commands are refused from then on. */
    private volatile boolean closed;
    /**
     * Held by a step for its whole run and by {@link #close()} while it stops the workers, so close
     * waits for a running step instead of pulling its workers away (no allocation uncontended).
     */
    private final ReentrantLock stepLock = new ReentrantLock();
    /** Views registered with {@link #addView}; replaced whole (copy on write), read once per step. */
    private volatile Camera[] views = NO_VIEWS;
    /** Tests: every component of frame n carries D = (n, -n). */
    boolean stampFrames;

    /**
     * Builds the parts of a simulation of {@code world}: flows, force field, animation state (settled
     * in the wind of t = 0 where "Start" says so), frames, draw decision and workers. Build time;
     * allocates.
     *
     * @param template the world's species' kinds prepared for the def's usual step, copied
     *                 ({@link SpringKinds#copy}); null: built and prepared here
     */
    StepLoop(World world, SimulationDef def, int workers, int chunkComponents, ForceFieldFactory fields,
             SpringKinds template) {
        AnimationDef ad = def.animation();
        fixedStep = ad.fixedStep();
        maxSubSteps = ad.maxSubSteps();
        subIntervals = ad.subIntervals();
        prewarmSteps = ad.prewarmSteps();
        mode = ad.mode();
        fieldEnabled = def.field().enabled();
        wind = WindField.of(def.flows());
        if (wind.size() > Simulation.MAX_FLOWS) {
            throw new IllegalArgumentException("a simulation holds at most " + Simulation.MAX_FLOWS
                    + " flows, the def has " + wind.size());
        }
        commands = new Commands(wind);
        plants = world.plantCount();
        float[][] positions = SimulationBuild.positions(world);
        float[] xs = positions[0];
        float[] ys = positions[1];
        float[] zs = positions[2];
        field = SimulationBuild.field(world, def, fields, wind, xs, zs);
        kinds = template != null ? template.copy() : SpringKinds.of(world.plants().species());
        // the step's spring coefficients for the usual step (no flow switching inside it), at build: the
        // first step finds them ready (1.1 ms of an open world's tile, whose build runs on a tile worker;
        // a tile's copy of its open world's prepared kinds is ready already)
        kinds.prepare(fixedStep, subIntervals, -1);
        int comps = world.componentCount();
        int[] first = SimulationBuild.firstComponents(world);
        state = AnimationStates.of(world, kinds, first, xs, ys, zs, def.seed());
        boolean[] trailPlants = AnimationStates.trailPlants(world);
        sampler = new FieldSampler(wind, field, commands, plants, fixedStep, subIntervals, def.field().lodFovY(),
                trailPlants == null ? null : new FlatteningPushes(wind, state, xs, zs, trailPlants));
        settledAtBuild = SimulationBuild.settleEverywhere(mode, fieldEnabled, field, wind, state, xs, zs);
        exchange = new FrameExchange(plants, state.geometry());
        for (int i = 0; i < 3; i++) {
            state.copyDeviations(0, comps, exchange.frame(i).renderStateLongs);
        }
        int[] speciesLevels = new int[world.plants().species().size()];
        for (int sp = 0; sp < speciesLevels.length; sp++) {
            speciesLevels[sp] = world.plants().species().get(sp).levels();
        }
        draw = new DrawDecision(world, new DrawDecision.Edges() {
            @Override
            public int levels(int sp) {
                return speciesLevels[sp]; // per plant in the workers: an array, not the species list
            }

            @Override
            public double edge(int sp, int l) {
                return state.lodEdge(sp, l);
            }
        });
        draw.setThinning(def.field().thinStart(), def.field().thinEnd(), def.field().thinMinFraction());
        chunkAnimator = new ChunkAnimator(state, first, plants, chunkComponents, sampler, ad.seed(), draw);
        pool = new WorkerPool("jecosys-anim", workers, chunkAnimator.chunks(), chunkAnimator);
    }

    /** {@link Simulation#step}: adds {@code dt} to the accumulator and runs the fixed steps it completes. */
    int step(double dt, Camera camera) {
        stepLock.lock();
        try {
            return stepLocked(dt, camera);
        } finally {
            stepLock.unlock();
        }
    }

    private int stepLocked(double dt, Camera camera) {
        checkOpen();
        prewarmLocked(camera);
        accumulator += dt;
        int n = 0;
        while (accumulator >= fixedStep && n < maxSubSteps) {
            if (closed) {
                return n; // close() waits for this step: stop at a fixed-step boundary
            }
            // another fixed step follows at once: the workers spin for it instead of sleeping
            stepFixedLocked(camera, accumulator - fixedStep >= fixedStep && n + 1 < maxSubSteps);
            accumulator -= fixedStep;
            n++;
        }
        if (accumulator >= fixedStep) {
            long drop = (long) (accumulator / fixedStep); // saturates at Long.MAX_VALUE for absurd pauses
            droppedSteps = droppedSteps > Long.MAX_VALUE - drop ? Long.MAX_VALUE : droppedSteps + drop;
            accumulator -= drop * fixedStep;
            if (!(accumulator < fixedStep)) {
                accumulator = 0; // a pause so long that the remainder lost all precision: drop it too
            }
        }
        return n;
    }

    /** {@link Simulation#stepFixed}: exactly one fixed step, ignoring the accumulator. */
    void stepFixed(Camera camera) {
        stepLock.lock();
        try {
            checkOpen();
            prewarmLocked(camera);
            stepFixedLocked(camera, false);
        } finally {
            stepLock.unlock();
        }
    }

    /**
     * Before the first step a caller asks for: the scene's prewarm ({@link AnimationDef#prewarm()}), that
     * many fixed steps with the caller's camera, each published as usual, none counted against
     * maxSubSteps. A prewarm step that throws (a game's camera or flow) reaches the caller, and the steps
     * not yet done run at the next call; a close stops it at a step's end. Stepping thread, under the
     * step lock.
     */
    private void prewarmLocked(Camera camera) {
        while (prewarmSteps > 0 && !closed) {
            stepFixedLocked(camera, prewarmSteps > 1); // the prewarm's steps follow one another
            prewarmSteps--;
        }
    }

    /** Refuses a call after {@link #close()} with {@link Simulation#CLOSED}. */
    void checkOpen() {
        if (closed) {
            throw new IllegalStateException(Simulation.CLOSED);
        }
    }

    private void stepFixedLocked(Camera camera, boolean followed) {
        steppingThread = Thread.currentThread().getId();
        commands.drain();
        checkOpen(); // a command may have closed the simulation (close() from this very thread)
        Camera[] others = views;
        sampler.checkViews(camera, others, others.length);
        if (!primed) {
            prime(camera);
            primed = true;
        }
        kinds.prepare(fixedStep, subIntervals, sampler.edge[current]);
        Frame f = exchange.back();
        exchange.beginWrite();
        int b = current; // the buffer the workers animate from: the views sampled one step ago
        chunkAnimator.prepare(mode, b, f, exchange.backIndex(), steps, time + fixedStep,
                stampFrames);
        draw.prepare();
        long t0 = System.nanoTime();
        pool.start(followed);
        try {
            sampler.update(camera, others, others.length, 1 - b, fieldEnabled);
        } catch (RuntimeException | Error e) {
            // a game's flow or camera threw beside the workers: let them finish this step's chunks
            // (every plant advances, whatever the number of workers) so the pool is idle for the next
            // step, then give the exception to the caller; the frame is not published
            try {
                pool.await();
            } catch (RuntimeException | Error w) {
                e.addSuppressed(w);
            }
            throw e;
        }
        long fieldNanos = System.nanoTime() - t0;
        pool.await();
        current = 1 - current;
        steps++;
        time += fixedStep;
        f.number = steps;
        f.time = time;
        f.componentsAnimated = chunkAnimator.animated();
        f.fieldNanos = fieldNanos;
        f.animationNanos = pool.animationNanos(); // the chunks' own span, beside or after the field
        f.setThinning(draw.thinStart(), draw.thinEnd(), draw.thinMinFraction());
        f.recordDecision(sampler.viewProjection[b], sampler.eye[b][0], sampler.eye[b][1], sampler.eye[b][2], draw,
                sampler.reference);
        exchange.publish();
    }

    /**
     * A fixed step of a simulation whose plants no view can see, nor could at the last step (an open
     * world's tile out of every view): queued commands apply and the clock and the flows advance;
     * nothing is sampled, animated, decided or published. The last step that ran sampled every plant
     * as unseen, so the plants stopped following the wind then and start at the equilibrium of the wind
     * when seen again, as in any step; the next full step animates from that sample, as it would.
     * Stepping thread; no allocation.
     *
     * @throws IllegalStateException when the simulation is closed
     */
    void idleStep() {
        stepLock.lock();
        try {
            checkOpen();
            steppingThread = Thread.currentThread().getId();
            commands.drain();
            checkOpen();
            sampler.advance(current);
            steps++;
            time += fixedStep;
        } finally {
            stepLock.unlock();
        }
    }

    /**
     * Before the first step: samples the field at t = 0 and, in CONSTRAINT mode, puts the plants
     * visible then at the equilibrium of that wind (the force each starts its first step from),
     * unless the constructor already put every plant at the equilibrium of the flows at t = 0 and
     * the field is still on (the first step then leads from that wind to the field's without a jump);
     * then advances to the end of the first step. A plant seen later starts at the equilibrium of the wind
     * when it comes into view ({@link AnimationState}).
     */
    private void prime(Camera camera) {
        int b = 1 - current;
        Camera[] others = views;
        sampler.sample(camera, others, others.length, b, fieldEnabled);
        if (mode == AnimationMode.CONSTRAINT && !(settledAtBuild && fieldEnabled)) {
            state.settle(0, plants, AnimationStep.of(mode, sampler.windX[b], sampler.windZ[b], sampler.visible[b]));
        }
        sampler.update(camera, others, others.length, current, fieldEnabled);
    }

    /** {@link Simulation#addView}, its arguments checked but for duplicates and the count. */
    synchronized void addView(Camera view) {
        checkOpen();
        Camera.requireFinite("view", view, new org.joml.Matrix4f());
        views = ViewLists.with(views, view, Simulation.MAX_VIEWS - 1, "a simulation");
    }

    /** {@link Simulation#removeView}. */
    synchronized boolean removeView(Camera view) {
        checkOpen();
        Camera[] v = views;
        views = ViewLists.without(v, view);
        return views != v;
    }

    /** {@return the views registered with {@link #addView}} */
    int viewCount() {
        return views.length;
    }

    /** Queues a change of animation mode ({@link Simulation#setMode}). */
    void setMode(AnimationMode mode) {
        commands.enqueue(() -> this.mode = mode);
    }

    /** Queues switching the force field ({@link Simulation#setFieldEnabled}). */
    void setFieldEnabled(boolean enabled) {
        commands.enqueue(() -> fieldEnabled = enabled);
    }

    /** {@return the animation mode of the last step} */
    AnimationMode mode() {
        return mode;
    }

    /** {@return whether the force field was on in the last step} */
    boolean fieldEnabled() {
        return fieldEnabled;
    }

    /** {@return the fixed step, seconds} */
    double fixedStep() {
        return fixedStep;
    }

    /**
     * Before the first step: starts the clock (the loop's and the flows') at {@code t}, for a tile of
     * an open world that joins the others' running time ({@link WindField#startAt}); such a tile does not
     * prewarm (it joins plants already in motion). Stepping thread.
     *
     * @throws IllegalStateException when a step has run already
     */
    void startAt(double t) {
        if (steps != 0 || primed) {
            throw new IllegalStateException("the clock can only be set before the first step");
        }
        wind.startAt(t);
        time = t;
        prewarmSteps = 0;
    }

    /** {@return the fixed steps run so far} */
    long steps() {
        return steps;
    }

    /** {@return the simulation time, seconds} */
    double time() {
        return time;
    }

    /** {@return the fixed steps dropped by the sub-step cap so far} */
    long droppedSteps() {
        return droppedSteps;
    }

    /** {@return the sampler buffer the last step animated from (its wind, visibility)} */
    int sampled() {
        return 1 - current;
    }

    /** {@return the id of the thread that ran the last fixed step, or -1 before the first} */
    long steppingThread() {
        return steppingThread;
    }

    /**
     * {@link Simulation#close()}: refuses later steps and commands, waits at most
     * {@link Simulation#CLOSE_WAIT_MILLIS} for a running step, stops the workers.
     */
    void close() {
        closed = true;
        commands.close();
        boolean locked = false;
        try {
            locked = stepLock.tryLock(Simulation.CLOSE_WAIT_MILLIS, java.util.concurrent.TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt(); // stop the workers all the same, without waiting
        }
        try {
            // with the lock: no step runs. Without it a step is stuck in a game's flow or camera: the
            // workers finish the chunks they hold and end; that step completes alone when it returns
            pool.close();
        } finally {
            if (locked) {
                stepLock.unlock();
            }
        }
    }
}
