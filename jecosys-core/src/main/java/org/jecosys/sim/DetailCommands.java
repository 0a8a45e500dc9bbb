package org.jecosys.sim;

import org.jecosys.anim.AnimationState;
import org.jecosys.math.Require;

/**
 * The level-of-detail and thinning commands of a {@link Simulation}: each call checks its arguments
 * (the scene schema's ranges) and queues its change, applied at the start of the next fixed step, to
 * the animation's level-of-detail bands ({@link AnimationState}: scale, distances) or to the
 * {@link DrawDecision} (transition band, distance thinning), which read the same bands.
 *
 * <p>Threads: any. Holds no state of its own; each call allocates its command (and
 * {@link #setLodDistances} a copy of the distances).
 */
final class DetailCommands {
    private final World world;
    private final Commands commands;
    private final AnimationState state;
    private final DrawDecision draw;

    DetailCommands(World world, Commands commands, AnimationState state, DrawDecision draw) {
        this.world = world;
        this.commands = commands;
        this.state = state;
        this.draw = draw;
    }

    /** Queues the transition band, metres ({@link Simulation#setLodTransition}). */
    void setLodTransition(double metres) {
        Require.range("lodTransition", metres, 0, 10);
        commands.enqueue(() -> draw.setTransition(metres));
    }

    /** Queues the distance thinning ({@link Simulation#setThinning}). */
    void setThinning(double start, double end, double minFraction) {
        DrawDecision.checkThinning(start, end, minFraction);
        commands.enqueue(() -> draw.setThinning(start, end, minFraction));
    }

    /** Queues one species' level-of-detail distances, metres ({@link Simulation#setLodDistances}). */
    void setLodDistances(int species, double[] maxDistances) {
        Require.range("species", species, 0, world.plants().species().size() - 1);
        int levels = world.plants().species().get(species).levels();
        Require.nonNull("maxDistances", maxDistances);
        if (maxDistances.length != levels - 1) {
            throw new IllegalArgumentException("species " + species + " has " + levels + " levels, so "
                    + (levels - 1) + " distances, got " + maxDistances.length);
        }
        double prev = 0;
        for (int i = 0; i < maxDistances.length; i++) {
            Require.elementRange("maxDistances", i, maxDistances[i], Math.nextUp(prev), 1e6);
            prev = maxDistances[i];
        }
        double[] copy = maxDistances.clone();
        commands.enqueue(() -> state.setLodDistances(species, copy));
    }

    /** Queues a scale of every species' level-of-detail distances ({@link Simulation#setLodScale}). */
    void setLodScale(double scale) {
        Require.range("scale", scale, 0.01, 100);
        commands.enqueue(() -> state.setLodScale(scale));
    }
}
