package com.example.consumer;

import org.jecosys.math.Camera;
import org.jecosys.render.SceneRenderer;
import org.jecosys.sim.Simulation;

/**
 * How a game draws the plants in its own OpenGL context: with the renderer it made for its
 * simulation, after each step, into the framebuffer it has bound. Compiled by the release check (no
 * context is made there).
 */
public final class PlantView implements AutoCloseable {
    private final Simulation simulation;
    private final SceneRenderer renderer;

    public PlantView(Simulation simulation, SceneRenderer renderer) {
        this.simulation = simulation;
        this.renderer = renderer;
    }

    /** Draws the latest frame for the game's camera; on the game's GL thread. */
    public void draw(Camera camera) {
        renderer.render(simulation.latestFrame(), camera);
    }

    @Override
    public void close() {
        renderer.close();
    }
}
