package org.jecosys.sim;

import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import org.jecosys.math.Require;
import org.jecosys.wind.WindField;
import org.jecosys.wind.WindSource;

/**
 * The command side of a {@link Simulation}: the bounded queue of commands that producers on any
 * thread fill and the stepping thread drains at the start of each fixed step, the reservation of
 * flow ids (unique, at most {@link Simulation#MAX_FLOWS} held or queued), and the blasts that are
 * tracked until they expire so their ids are freed again.
 *
 * <p>Threads: {@link #enqueue}, {@link #enqueueReserved}, {@link #reserveFlow}, {@link #releaseFlow},
 * {@link #pending()} and {@link #flowCount()} are called from any thread (lock-free: a concurrent
 * queue, atomic counters and a concurrent map); {@link #drain()}, {@link #trackBlast} and
 * {@link #releaseExpiredBlasts} only by the stepping thread. Allocation: enqueueing and reserving
 * allocate (queue node, map entry); draining and releasing expired blasts allocate nothing, except
 * that the blast list doubles when more blasts live at once than ever before.
 */
final class Commands {
    private final ConcurrentLinkedQueue<Runnable> queue = new ConcurrentLinkedQueue<>();
    /** Commands queued and not yet taken by a step; at most {@link Simulation#MAX_PENDING_COMMANDS}. */
    private final AtomicInteger pendingCommands = new AtomicInteger();
    /** Every flow id held or queued, with its owner (the source, or a blast's token). */
    private final ConcurrentHashMap<String, Object> flowIds = new ConcurrentHashMap<>();
    /** Flows held or queued; at most {@link Simulation#MAX_FLOWS}. */
    private final AtomicInteger flowsReserved = new AtomicInteger();
    /** Set by {@link #close()}. */
    private volatile boolean closed;
    /** Blasts made by {@link Simulation#blast}, with their id tokens, until they expire. Stepping thread. */
    private WindSource[] blasts = new WindSource[4];
    private Object[] blastTokens = new Object[4];
    private int blastCount;

    /**
     * Reserves the ids of the flows a simulation starts with. Build time; allocates.
     *
     * @param wind the simulation's flows, at most {@link Simulation#MAX_FLOWS}
     */
    Commands(WindField wind) {
        for (int i = 0; i < wind.size(); i++) {
            flowIds.put(wind.get(i).id(), wind.get(i));
        }
        flowsReserved.set(wind.size());
    }

    /** Applies the commands queued when it starts, no more (later ones wait for the next step). */
    void drain() {
        for (int n = pendingCommands.get(); n > 0; n--) {
            Runnable r = queue.poll();
            if (r == null) {
                return; // counted but not yet in the queue: the next step takes it
            }
            pendingCommands.decrementAndGet();
            r.run();
        }
    }

    /** Refuses every later command and reservation, and drops those still queued. Any thread. */
    void close() {
        closed = true;
        queue.clear();
        pendingCommands.set(0);
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException(Simulation.CLOSED);
        }
    }

    /**
     * Queues a command, or refuses it past {@link Simulation#MAX_PENDING_COMMANDS} or after
     * {@link #close()}.
     */
    void enqueue(Runnable command) {
        checkOpen();
        if (pendingCommands.incrementAndGet() > Simulation.MAX_PENDING_COMMANDS) {
            pendingCommands.decrementAndGet();
            throw new IllegalStateException("the simulation's command queue is full: "
                    + Simulation.MAX_PENDING_COMMANDS
                    + " commands wait for the next step (Simulation.MAX_PENDING_COMMANDS); step more often or "
                    + "send fewer commands");
        }
        queue.add(command);
    }

    /** {@return the commands queued and not yet applied, at most {@link Simulation#MAX_PENDING_COMMANDS}} */
    int pending() {
        return Math.min(pendingCommands.get(), Simulation.MAX_PENDING_COMMANDS);
    }

    /** {@return the flows held or queued, at most {@link Simulation#MAX_FLOWS}} */
    int flowCount() {
        return flowsReserved.get();
    }

    /** Reserves a flow id for {@code owner}, refusing a duplicate or a flow past {@link Simulation#MAX_FLOWS}. */
    void reserveFlow(String id, Object owner) {
        checkOpen();
        Require.nonNull("id", id);
        if (id.isEmpty()) {
            throw new IllegalArgumentException("a flow id must not be empty");
        }
        if (flowsReserved.incrementAndGet() > Simulation.MAX_FLOWS) {
            flowsReserved.decrementAndGet();
            throw new IllegalStateException("the simulation holds " + Simulation.MAX_FLOWS
                    + " flows (Simulation.MAX_FLOWS, "
                    + "queued ones included): remove one before adding '" + id + "'");
        }
        if (flowIds.putIfAbsent(id, owner) != null) {
            flowsReserved.decrementAndGet();
            throw new IllegalArgumentException("a flow with id '" + id + "' is already in the simulation (or "
                    + "queued): flow ids are unique");
        }
    }

    /** Frees {@code id} when {@code owner} holds it. */
    void releaseFlow(String id, Object owner) {
        if (id != null && flowIds.remove(id, owner)) {
            flowsReserved.decrementAndGet();
        }
    }

    /**
     * Queues a command for a flow whose id was just reserved; releases the id when the command is
     * refused here, or when it throws in the step (the flow then never joins the field).
     */
    void enqueueReserved(String id, Object owner, Runnable command) {
        try {
            enqueue(() -> {
                try {
                    command.run();
                } catch (RuntimeException e) {
                    releaseFlow(id, owner);
                    throw e;
                }
            });
        } catch (RuntimeException e) {
            releaseFlow(id, owner);
            throw e;
        }
    }

    /** Frees the ids of blasts the wind field removed at their end (wind time {@code now}, seconds). */
    void releaseExpiredBlasts(double now) {
        for (int i = blastCount - 1; i >= 0; i--) {
            if (blasts[i].expired(now)) {
                releaseFlow(blasts[i].id(), blastTokens[i]);
                blastCount--;
                blasts[i] = blasts[blastCount];
                blastTokens[i] = blastTokens[blastCount];
                blasts[blastCount] = null;
                blastTokens[blastCount] = null;
            }
        }
    }

    /** Tracks a blast the wind field made, with the token its id is reserved for. */
    void trackBlast(WindSource b, Object token) {
        if (blastCount == blasts.length) {
            blasts = java.util.Arrays.copyOf(blasts, 2 * blastCount);
            blastTokens = java.util.Arrays.copyOf(blastTokens, 2 * blastCount);
        }
        blasts[blastCount] = b;
        blastTokens[blastCount++] = token;
    }
}
