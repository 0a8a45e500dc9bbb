package org.jecosys.sim;

import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import org.jecosys.wind.WindSource;

/**
 * The pending moves of agents ({@link Simulation#moveAgent}): one slot per moved flow holding its
 * latest requested centre, so that a game moving its player every frame allocates nothing. A slot is
 * made at a flow's first move (allocates once) and dropped when the flow has left the simulation.
 * The stepping thread applies every pending move after the queued commands of the step
 * ({@link Commands#drain}); moves of one flow between two steps coalesce (the latest wins), as the
 * flow would have ended there anyway.
 *
 * <p>Threads: {@link #move} from any thread (a slot's two coordinates are written and read under the
 * slot's lock, so a step never sees half a move); {@link #apply} only by the stepping thread.
 * {@link #move} allocates nothing once the flow has its slot; {@link #apply} allocates nothing
 * unless a flow has left (its slot is then removed from the list, which copies it).
 */
final class AgentMoves {
    /** One flow's latest requested centre. */
    private static final class Slot {
        final WindSource source;
        double x;
        double z;
        boolean pending;

        Slot(WindSource source) {
            this.source = source;
        }
    }

    private final ConcurrentHashMap<WindSource, Slot> bySource = new ConcurrentHashMap<>();
    /** The same slots, for the stepping thread's scan by index (no iterator). */
    private final CopyOnWriteArrayList<Slot> slots = new CopyOnWriteArrayList<>();

    /**
     * Records that {@code source} should be centred at (x, z) metres at the next step. Any thread; no
     * allocation once the flow has been moved before.
     */
    void move(WindSource source, double x, double z) {
        Slot s = bySource.get(source);
        if (s == null) {
            s = bySource.computeIfAbsent(source, k -> {
                Slot made = new Slot(k);
                slots.add(made);
                return made;
            });
        }
        synchronized (s) {
            s.x = x;
            s.z = z;
            s.pending = true;
        }
    }

    /** Forgets the slot of a flow that left the simulation (any thread). */
    void forget(WindSource source) {
        Slot s = bySource.remove(source);
        if (s != null) {
            slots.remove(s);
        }
    }

    /**
     * Moves every flow with a pending move to its latest centre ({@link WindSource#setCentre}).
     * Stepping thread. A flow whose {@code setCentre} throws (a user flow without a movable centre)
     * passes the exception to the step, after the other flows have moved.
     *
     * @param held whether a flow is still in the simulation; the slots of the others are dropped
     */
    void apply(java.util.function.Predicate<WindSource> held) {
        RuntimeException failure = null;
        for (int i = slots.size() - 1; i >= 0; i--) {
            Slot s = slots.get(i);
            double x;
            double z;
            synchronized (s) {
                if (!s.pending) {
                    if (!held.test(s.source)) {
                        forget(s.source);
                    }
                    continue;
                }
                s.pending = false;
                x = s.x;
                z = s.z;
            }
            try {
                s.source.setCentre(x, z);
            } catch (RuntimeException e) {
                if (failure == null) {
                    failure = e;
                }
            }
        }
        if (failure != null) {
            throw failure;
        }
    }
}
