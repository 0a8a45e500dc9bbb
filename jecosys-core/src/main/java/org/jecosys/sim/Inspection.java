package org.jecosys.sim;

import org.jecosys.anim.AnimationMode;
import org.jecosys.anim.AnimationState;
import org.jecosys.anim.AnimationView;
import org.jecosys.field.FieldCounters;
import org.jecosys.field.ForceField;
import org.jecosys.field.ForceFieldFactory;
import org.jecosys.wind.WindField;

/**
 * The read-only inspection of a running {@link Simulation} ({@link Simulation#inspect()}): its clock
 * and counters, the mode and field switches the last step ran with, the animated state, the force
 * field, the wind each plant felt, the state hash that shows determinism, and the workers. For tools,
 * tests, benchmarks and debug views; a game needs none of it to step, command and draw.
 *
 * <p>One per simulation, made with it; it holds no state of its own and reads the simulation's live
 * values, so what it returns changes with every step. Threads: each method says; the stepping-thread
 * ones read between steps, never concurrently with one. Nothing allocates except
 * {@link #workerThreadIds()}.
 */
public final class Inspection {
    private final StepLoop loop;

    Inspection(StepLoop loop) {
        this.loop = loop;
    }

    /** {@return the views registered with {@link Simulation#addView}, besides each step's camera} Any thread. */
    public int viewCount() {
        return loop.viewCount();
    }

    /**
     * {@return the commands queued and not yet applied, at most {@link Simulation#MAX_PENDING_COMMANDS}}
     * Any thread.
     */
    public int pendingCommands() {
        return loop.commands.pending();
    }

    /**
     * {@return the flows held or queued: the scene's, agents, blasts and user flows, at most
     * {@link Simulation#MAX_FLOWS}} Any thread.
     */
    public int flowCount() {
        return loop.commands.flowCount();
    }

    /** {@return where distance thinning starts, metres (see {@link Simulation#setThinning})} Any thread. */
    public double thinStart() {
        return loop.draw.thinStart();
    }

    /** {@return where the kept share reaches {@link #thinMinFraction()}, metres} Any thread. */
    public double thinEnd() {
        return loop.draw.thinEnd();
    }

    /** {@return the share of plants drawn at and beyond {@link #thinEnd()}; 1 when thinning is off} Any thread. */
    public double thinMinFraction() {
        return loop.draw.thinMinFraction();
    }

    /** {@return the animation mode of the last step} Stepping thread. */
    public AnimationMode mode() {
        return loop.mode();
    }

    /** {@return whether the force field was on in the last step} Stepping thread. */
    public boolean fieldEnabled() {
        return loop.fieldEnabled();
    }

    /**
     * {@return the number of threads that animate: the pool's threads and the stepping thread, which
     * helps} Any thread.
     */
    public int workers() {
        return loop.pool.workers();
    }

    /** {@return the number of fixed chunks of plants} Any thread. */
    public int chunks() {
        return loop.chunkAnimator.chunks();
    }

    /** {@return the fixed step, seconds} Any thread. */
    public double fixedStep() {
        return loop.fixedStep();
    }

    /** {@return the number of fixed steps run so far} Stepping thread. */
    public long steps() {
        return loop.steps();
    }

    /** {@return the simulation time, seconds (fixed steps x fixed step)} Stepping thread. */
    public double time() {
        return loop.time();
    }

    /** {@return the number of fixed steps dropped by the sub-step cap so far} Stepping thread. */
    public long droppedSteps() {
        return loop.droppedSteps();
    }

    /**
     * A read-only view of the animated state (deviations, velocities, outputs, levels), for reading
     * between steps. Stepping thread; the view allocates nothing.
     *
     * @return the live view (not a copy: it changes with every step)
     */
    public AnimationView state() {
        return loop.state;
    }

    /**
     * The force field: the paper's quadtree ({@code org.jecosys.field.QuadtreeForceField}) unless
     * the simulation was built with another {@link ForceFieldFactory}. Its debug view and counters
     * reflect the update for the next step. Stepping thread; read it, do not add or move plants.
     *
     * @return the field
     */
    public ForceField forceField() {
        return loop.field;
    }

    /** {@return the counters of the field's last update} Stepping thread. */
    public FieldCounters fieldCounters() {
        return loop.field.counters();
    }

    /**
     * {@return the wind flows} Stepping thread. Add and remove flows through {@link Simulation#addFlow}
     * and {@link Simulation#removeFlow}: flows added here directly are not counted in
     * {@link Simulation#MAX_FLOWS}, and their ids are not known to the duplicate check of the command
     * methods.
     */
    public WindField windField() {
        return loop.wind;
    }

    /**
     * {@return the wind X (m/s) at plant p's node that the last step used} Stepping thread.
     *
     * @param p world plant index, in [0, {@link Simulation#plantCount()})
     */
    public float windX(int p) {
        return loop.sampler.windX[loop.sampled()][p];
    }

    /**
     * {@return the wind Z (m/s) at plant p's node that the last step used} Stepping thread.
     *
     * @param p world plant index, in [0, {@link Simulation#plantCount()})
     */
    public float windZ(int p) {
        return loop.sampler.windZ[loop.sampled()][p];
    }

    /**
     * {@return whether plant p was visible in the last step} Stepping thread.
     *
     * @param p world plant index, in [0, {@link Simulation#plantCount()})
     */
    public boolean plantVisible(int p) {
        return loop.sampler.visible[loop.sampled()][p];
    }

    /** {@return the {@link AnimationState#stateHash()} of the current state} Stepping thread, between steps. */
    public long stateHash() {
        return loop.state.stateHash();
    }

    /** {@return the ids of the pool's worker threads, {@link #workers()} - 1 of them} Allocates; any thread. */
    public long[] workerThreadIds() {
        return loop.pool.threadIds();
    }

    /**
     * Bytes allocated so far by every worker thread and by the last stepping thread
     * ({@code com.sun.management.ThreadMXBean#getThreadAllocatedBytes}); -1 when the JVM cannot tell.
     * Any thread; allocates nothing itself.
     *
     * @return bytes, or -1
     */
    public long allocatedBytes() {
        return loop.pool.allocatedBytes(loop.steppingThread());
    }
}
