package org.jecosys.sim;

import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import org.jecosys.math.Require;
import org.jecosys.math.Waypoint;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.jecosys.wind.WindField;
import org.jecosys.wind.WindSource;

/**
 * The command side of a {@link Simulation}: the bounded queue of commands that producers on any
 * thread fill and the stepping thread drains at the start of each fixed step, the reservation of
 * flow ids (unique, at most {@link Simulation#MAX_FLOWS} held or queued), the blasts that are
 * tracked until they expire so their ids are freed again, and the flow and agent commands
 * ({@link #addFlow}, {@link #removeFlow}, {@link #attachAgent}, {@link #moveAgent}, {@link #blast},
 * {@link #setFlowEnabled}), each checked by the call as the Simulation method of that name says.
 *
 * <p>Threads: the commands, {@link #enqueue}, {@link #enqueueReserved}, {@link #reserveFlow},
 * {@link #releaseFlow}, {@link #pending()} and {@link #flowCount()} are called from any thread
 * (lock-free: a concurrent queue, atomic counters and a concurrent map); {@link #drain()},
 * {@link #trackBlast} and {@link #releaseExpiredBlasts} only by the stepping thread. Allocation:
 * commands, enqueueing and reserving allocate (the command, queue node, map entry); draining and
 * releasing expired blasts allocate nothing, except that the blast list doubles when more blasts
 * live at once than ever before.
 */
final class Commands {
    private final WindField wind;
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
    /** The latest requested centre of each moved flow, applied after the queue ({@link #moveAgent}). */
    private final AgentMoves moves = new AgentMoves();
    /** Whether a flow still holds its id here (for {@link AgentMoves#apply}); made once. */
    private final java.util.function.Predicate<WindSource> held = source -> flowIds.get(source.id()) == source;

    /**
     * Reserves the ids of the flows a simulation starts with. Build time; allocates.
     *
     * @param wind the simulation's flows, at most {@link Simulation#MAX_FLOWS}; the flow commands change them
     */
    Commands(WindField wind) {
        this.wind = wind;
        for (int i = 0; i < wind.size(); i++) {
            flowIds.put(wind.get(i).id(), wind.get(i));
        }
        flowsReserved.set(wind.size());
    }

    /**
     * Applies the commands queued when it starts, no more (later ones wait for the next step), then
     * the agents' latest moves.
     */
    void drain() {
        for (int n = pendingCommands.get(); n > 0; n--) {
            Runnable r = queue.poll();
            if (r == null) {
                break; // counted but not yet in the queue: the next step takes it
            }
            pendingCommands.decrementAndGet();
            r.run();
        }
        moves.apply(held);
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

    /** Queues a new flow ({@link Simulation#addFlow(WindSource)}); returns {@code source}. */
    WindSource addFlow(WindSource source) {
        Require.nonNull("source", source);
        String id = source.id();
        reserveFlow(id, source);
        enqueueReserved(id, source, () -> wind.add(source));
        return source;
    }

    /** Queues the removal of a flow or agent ({@link Simulation#removeFlow}); frees its id now. */
    void removeFlow(WindSource source) {
        Require.nonNull("source", source);
        enqueue(() -> wind.remove(source));
        releaseFlow(source.id(), source);
        moves.forget(source);
    }

    /** Queues an agent, a flow of FIXED motion ({@link Simulation#attachAgent}); returns its handle. */
    WindSource attachAgent(FlowDef def) {
        Require.nonNull("def", def);
        if (def.motion().kind() != MotionDef.Kind.FIXED) {
            throw new IllegalArgumentException("an agent's motion must be FIXED (the game moves it), got "
                    + def.motion().kind());
        }
        return addFlow(WindSource.of(def));
    }

    /**
     * Moves a flow's centre to (x, z), metres, at the next step ({@link Simulation#moveAgent}): the
     * latest move of a flow between two steps wins. A flow that is not in the simulation (never added,
     * or removed) is not moved. No allocation after the flow's first move.
     */
    void moveAgent(WindSource agent, double x, double z) {
        checkOpen();
        Require.nonNull("agent", agent);
        Require.range("x", x, -Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE);
        Require.range("z", z, -Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE);
        if (held.test(agent)) {
            moves.move(agent, x, z);
        }
    }

    /** Queues a blast, its id reserved until it is over ({@link Simulation#blast}). */
    void blast(String id, double x, double z, double strength, double duration) {
        Require.positive("strength", strength);
        // a blast is removed when it ends: it must end (the step would refuse +Infinity)
        Require.above("duration", duration, 0, ActivationDef.MAX_TIME);
        FlowDef.builder(id, FlowKind.BLAST).centre(x, z).strength(strength).duration(duration)
                .build(); // checks every value with the scene schema's ranges
        Object token = new Object();
        reserveFlow(id, token);
        enqueueReserved(id, token, () -> trackBlast(wind.blast(id, x, z, strength, duration), token));
    }

    /** Queues switching a flow on or off ({@link Simulation#setFlowEnabled}). */
    void setFlowEnabled(WindSource source, boolean enabled) {
        Require.nonNull("source", source);
        enqueue(() -> source.setEnabled(enabled));
    }
}
