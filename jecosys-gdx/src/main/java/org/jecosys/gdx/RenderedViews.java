package org.jecosys.gdx;

import org.jecosys.sim.Simulation;

/**
 * The cameras a {@link PlantLayer} draws with besides the one it steps with (split screens, minimaps):
 * each is registered with the simulation as a view ({@link Simulation#addView}) the first time it is
 * drawn, so what it sees animates too, kept current each time it is drawn, and dropped
 * ({@link Simulation#removeView}) once it has not been drawn for {@link #IDLE_FRAMES} updates, so a
 * viewport the game removed stops costing animation. Render thread; allocates only when a camera
 * comes or goes.
 */
final class RenderedViews {
    /** Updates without a draw after which a camera's view is dropped. */
    static final int IDLE_FRAMES = 30;
    private static final int MAX = Simulation.MAX_VIEWS - 1;

    private final Simulation simulation;
    private final com.badlogic.gdx.graphics.Camera[] hosts = new com.badlogic.gdx.graphics.Camera[MAX];
    private final GdxCamera[] views = new GdxCamera[MAX];
    private final long[] lastDrawn = new long[MAX];
    private int count;
    private long frame;

    RenderedViews(Simulation simulation) {
        this.simulation = simulation;
    }

    /**
     * The library camera for a game camera drawn now, registered as a view when it is new (when
     * {@link Simulation#MAX_VIEWS} views are taken it is drawn but not registered). No allocation for a
     * known camera.
     */
    GdxCamera drawn(com.badlogic.gdx.graphics.Camera host) {
        for (int i = 0; i < count; i++) {
            if (hosts[i] == host) {
                lastDrawn[i] = frame;
                return views[i].update(host);
            }
        }
        GdxCamera view = new GdxCamera().update(host);
        if (count < MAX && simulation.inspect().viewCount() < Simulation.MAX_VIEWS) {
            simulation.addView(view);
            hosts[count] = host;
            views[count] = view;
            lastDrawn[count++] = frame;
        }
        return view;
    }

    /** One game frame passed (the layer's update): drops the views not drawn for {@link #IDLE_FRAMES}. */
    void tick() {
        frame++;
        for (int i = count - 1; i >= 0; i--) {
            if (frame - lastDrawn[i] > IDLE_FRAMES) {
                simulation.removeView(views[i]);
                count--;
                hosts[i] = hosts[count];
                views[i] = views[count];
                lastDrawn[i] = lastDrawn[count];
                hosts[count] = null;
                views[count] = null;
            }
        }
    }

    /** {@return the game cameras registered as views now} */
    int count() {
        return count;
    }
}
