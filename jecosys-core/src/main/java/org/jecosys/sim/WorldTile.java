package org.jecosys.sim;

import org.jecosys.math.Camera;
import org.jecosys.wind.WindSource;

/**
 * A live tile of an {@link OpenWorld}: its plants' world and simulation. Made on a tile worker, then
 * read by the stepping thread (and a renderer on it).
 */
public final class WorldTile {
    final int i;
    final int j;
    final World world;
    final Simulation simulation;
    /** Whether its clock has joined the world's (stepping thread). */
    boolean started;
    /** Its views registered so far (stepping thread). */
    Camera[] views = new Camera[0];
    /** Whether no view could see it at the last step (stepping thread). */
    boolean wasOutside;
    /** Whether this step only advances its clock (set by the stepping thread before the workers run). */
    boolean idle;
    /** Its instance of each flow added at run time, in the order of {@link WorldFlows} (stepping thread). */
    WindSource[] handles = new WindSource[0];

    WorldTile(int i, int j, World world, Simulation simulation) {
        this.i = i;
        this.j = j;
        this.world = world;
        this.simulation = simulation;
    }

    /** {@return the tile's index along X: it covers [i size, (i + 1) size) metres} */
    public int i() {
        return i;
    }

    /** {@return the tile's index along Z} */
    public int j() {
        return j;
    }

    /** {@return the tile's plants and ground (plants in world coordinates)} */
    public World world() {
        return world;
    }

    /**
     * {@return the tile's simulation} Its frames are what a renderer draws; stepping it is the open
     * world's business, not the caller's.
     */
    public Simulation simulation() {
        return simulation;
    }

    /**
     * {@return the tallest any plant of these species can stand, metres: the most, over the species, of
     * its components' lengths added up (a component on the tip of another raises it)} Build time.
     *
     * @param species the species
     */
    static double tallest(java.util.List<org.jecosys.plant.SpeciesDef> species) {
        double top = 0;
        for (org.jecosys.plant.SpeciesDef sp : species) {
            double h = 0;
            for (var c : sp.components()) {
                h += c.length();
            }
            top = Math.max(top, h);
        }
        return top;
    }

    /**
     * Whether no view's frustum meets this tile's box (its square, from its lowest ground to its highest
     * plus the tallest plant). Stepping thread; no allocation.
     */
    boolean outside(org.joml.FrustumIntersection[] frusta, int viewCount, double tallest) {
        org.jecosys.terrain.Heightfield g = world.terrain().heightfield();
        float x0 = (float) g.minX();
        float z0 = (float) g.minZ();
        float x1 = (float) g.maxX();
        float z1 = (float) g.maxZ();
        float y0 = (float) g.minHeight() - 0.5f;
        float y1 = (float) (g.maxHeight() + tallest) + 0.5f;
        for (int v = 0; v < viewCount; v++) {
            if (frusta[v].testAab(x0, y0, z0, x1, y1, z1)) {
                return false;
            }
        }
        return true;
    }

    /** Registers on its simulation exactly {@code list}, the world's views. Stepping thread; allocates. */
    void syncViews(Camera[] list) {
        for (Camera v : views) {
            if (!ViewLists.contains(list, v)) {
                simulation.removeView(v);
            }
        }
        for (Camera v : list) {
            if (!ViewLists.contains(views, v)) {
                simulation.addView(v);
            }
        }
        views = list;
    }

    /**
     * Joins the world at its first step: its clock set to the world's, the flows added at run time, the
     * thinning set on the world (null: the def's). Stepping thread; allocates.
     */
    void start(double time, WorldFlows flows, double[] thinning) {
        simulation.loop.startAt(time);
        flows.startTile(this);
        if (thinning != null) {
            simulation.setThinning(thinning[0], thinning[1], thinning[2]);
        }
        started = true;
    }
}
