package org.jecosys.sim;

import org.jecosys.anim.AnimationMode;
import org.jecosys.anim.AnimationState;
import org.jecosys.field.FieldBounds;
import org.jecosys.field.ForceField;
import org.jecosys.field.ForceFieldFactory;
import org.jecosys.math.Require;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.WindField;

/**
 * Build-time helpers of a {@link Simulation}'s constructor: the plant positions, the force field
 * over the terrain's box (paper §3), the plants' first components, and the settling of every plant
 * at the equilibrium of the wind at t = 0 (paper §4.2). Holds nothing: static methods only. Called
 * once per simulation on the thread that builds it; every method allocates (build time only).
 */
final class SimulationBuild {
    private SimulationBuild() {
    }

    /** {@return the plants' node positions, metres: {xs, ys, zs}, each indexed by world plant} */
    static float[][] positions(World world) {
        int plants = world.plantCount();
        float[] xs = new float[plants];
        float[] zs = new float[plants];
        float[] ys = new float[plants];
        for (int p = 0; p < plants; p++) {
            xs[p] = world.plantX(p);
            ys[p] = world.plantY(p);
            zs[p] = world.plantZ(p);
        }
        return new float[][] {xs, ys, zs};
    }

    /**
     * Builds the force field with {@code fields} over the terrain's box raised by the tallest plant.
     *
     * @throws IllegalArgumentException when the factory returns null or a field that does not hold
     *                                  exactly the world's plants
     */
    static ForceField field(World world, SimulationDef def, ForceFieldFactory fields, WindField wind, float[] xs,
            float[] zs) {
        Heightfield hf = world.terrain().heightfield();
        int plants = world.plantCount();
        double plantHeight = 0;
        for (SpeciesDef s : def.species()) {
            double h = 0;
            for (var c : s.components()) {
                h += c.length();
            }
            plantHeight = Math.max(plantHeight, h);
        }
        ForceField field = Require.nonNull("the force field factory's result",
                fields.create(new FieldBounds(hf.minX(), hf.minZ(), hf.maxX(), hf.maxZ(), hf.minHeight(),
                        hf.maxHeight() + plantHeight), def.field(), wind, xs.clone(), zs.clone()));
        if (field.plantCount() != plants) {
            throw new IllegalArgumentException("the force field must hold the world's " + plants + " plants, it holds "
                    + field.plantCount());
        }
        return field;
    }

    /** {@return each plant's first component, then the component count (plants + 1 entries)} */
    static int[] firstComponents(World world) {
        int plants = world.plantCount();
        int[] first = new int[plants + 1];
        for (int p = 0; p < plants; p++) {
            first[p] = world.firstComponent(p);
        }
        first[plants] = world.componentCount();
        return first;
    }

    /**
     * In CONSTRAINT mode with the paper's quadtree field on: puts every plant at the equilibrium of
     * the flows at its own position at t = 0 (one evaluation per plant, once), so that the frames a
     * reader sees before the first step already show the meadow in the wind. The first step then
     * settles the plants it sees on the field's own wind at t = 0 (Simulation.prime).
     *
     * @return whether the plants were settled
     */
    static boolean settleEverywhere(AnimationMode mode, boolean fieldEnabled, ForceField field, WindField wind,
            AnimationState state, float[] xs, float[] zs) {
        if (mode != AnimationMode.CONSTRAINT || !fieldEnabled
                || !(field instanceof org.jecosys.field.QuadtreeForceField)) {
            return false; // a game's own field may blow other winds than the flows: the first step settles on it
        }
        int n = xs.length;
        float[] wx = new float[n];
        float[] wz = new float[n];
        boolean[] all = new boolean[n];
        org.joml.Vector2d u = new org.joml.Vector2d();
        for (int p = 0; p < n; p++) {
            wind.velocity(xs[p], zs[p], u);
            wx[p] = (float) u.x;
            wz[p] = (float) u.y;
            all[p] = true;
        }
        state.settle(0, n, org.jecosys.anim.AnimationStep.of(mode, wx, wz, all));
        return true;
    }
}
