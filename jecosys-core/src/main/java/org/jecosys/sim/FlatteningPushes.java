package org.jecosys.sim;

import java.util.Arrays;
import org.jecosys.anim.AnimationState;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.WindField;
import org.jecosys.wind.WindSource;
import org.joml.Vector2d;

/**
 * The push that may flatten plants (trails, {@code org.jecosys.anim.Trails}): the wind of the flows
 * that flatten ({@link WindField#flattens}: source, sink, vortex, blast), evaluated exactly at each
 * visible plant whose species leaves trails, but only where it can matter. Below the smallest speed
 * that flattens any of these plants ({@link AnimationState#flatteningSpeed}) nothing flattens, and a
 * point flow of strength s (m^2/s) blows at most {@code |s| / (2 pi r)} at distance r (less inside
 * its core), so with n such flows acting, a plant further than {@code n |s| / (2 pi minSpeed)} from
 * every one of them (or beyond its influence radius) cannot reach that speed: those plants are not
 * evaluated and get no push. The plants are found through a uniform grid built once.
 *
 * <p>Stepping thread only (the field sampler's); allocates at construction only.
 */
final class FlatteningPushes {
    /** Most grid cells along a side. */
    private static final int MAX_CELLS = 256;
    private final WindField wind;
    private final float[] plantX;
    private final float[] plantZ;
    /** The smallest speed that flattens any trail plant, m/s. */
    private final double minSpeed;
    private final double gridX;
    private final double gridZ;
    private final double cell;
    private final int cellsX;
    private final int cellsZ;
    /** Per cell its first entry in {@link #cellPlants}, plus the count at the end. */
    private final int[] cellStart;
    private final int[] cellPlants;
    /** Per buffer, whether the last sampling into it wrote a push (to clear). */
    private final boolean[] wrote = new boolean[2];
    private final Vector2d velocity = new Vector2d();

    /**
     * The grid of the trail plants. Build time; allocates.
     *
     * @param wind   the simulation's flows
     * @param state  the plants' state (their flattening speeds)
     * @param plantX per plant X, metres (kept by reference)
     * @param plantZ per plant Z, metres (kept by reference)
     * @param trail  per plant whether its species leaves trails
     */
    FlatteningPushes(WindField wind, AnimationState state, float[] plantX, float[] plantZ, boolean[] trail) {
        this.wind = wind;
        this.plantX = plantX;
        this.plantZ = plantZ;
        double least = Double.POSITIVE_INFINITY;
        double x0 = Double.POSITIVE_INFINITY;
        double z0 = Double.POSITIVE_INFINITY;
        double x1 = Double.NEGATIVE_INFINITY;
        double z1 = Double.NEGATIVE_INFINITY;
        int n = 0;
        for (int p = 0; p < trail.length; p++) {
            if (trail[p]) {
                least = Math.min(least, state.flatteningSpeed(p));
                x0 = Math.min(x0, plantX[p]);
                z0 = Math.min(z0, plantZ[p]);
                x1 = Math.max(x1, plantX[p]);
                z1 = Math.max(z1, plantZ[p]);
                n++;
            }
        }
        minSpeed = least;
        if (n == 0) {
            x0 = z0 = 0;
            x1 = z1 = 1;
        }
        gridX = x0;
        gridZ = z0;
        cell = Math.max(1.0, Math.max(x1 - x0, z1 - z0) / MAX_CELLS);
        cellsX = Math.min(MAX_CELLS, (int) ((x1 - x0) / cell) + 1);
        cellsZ = Math.min(MAX_CELLS, (int) ((z1 - z0) / cell) + 1);
        cellStart = new int[cellsX * cellsZ + 1];
        int[] cellOf = new int[trail.length];
        for (int p = 0; p < trail.length; p++) {
            if (trail[p]) {
                cellOf[p] = cellIndex(plantX[p], plantZ[p]);
                cellStart[cellOf[p] + 1]++;
            }
        }
        for (int c = 0; c < cellsX * cellsZ; c++) {
            cellStart[c + 1] += cellStart[c];
        }
        cellPlants = new int[n];
        int[] fill = Arrays.copyOf(cellStart, cellStart.length - 1);
        for (int p = 0; p < trail.length; p++) {
            if (trail[p]) {
                cellPlants[fill[cellOf[p]]++] = p;
            }
        }
    }

    private int cellIndex(double x, double z) {
        return cellClamp(z - gridZ, cellsZ) * cellsX + cellClamp(x - gridX, cellsX);
    }

    /** The cell along one axis of an offset from the grid's corner, metres, clamped into [0, cells). */
    private int cellClamp(double offset, int cells) {
        return (int) Math.max(0, Math.min(cells - 1, Math.floor(offset / cell)));
    }

    /**
     * Writes the push (m/s) at every visible trail plant within reach of a flow that flattens into
     * {@code px, pz} (indexed by plant), 0 elsewhere. No allocation.
     *
     * @param b        the buffer written (0 or 1), for clearing what it held
     * @param visible  per plant whether it is seen
     * @param px       per plant push X, written
     * @param pz       per plant push Z, written
     * @param fieldOn  whether the field acts (off: no push)
     */
    void sample(int b, boolean[] visible, float[] px, float[] pz, boolean fieldOn) {
        if (wrote[b]) {
            Arrays.fill(px, 0f);
            Arrays.fill(pz, 0f);
            wrote[b] = false;
        }
        int acting = fieldOn ? wind.flatteningCount() : 0;
        if (acting == 0 || minSpeed == Double.POSITIVE_INFINITY) {
            return;
        }
        double t = wind.time();
        double speed = minSpeed / acting;
        for (int i = 0, n = wind.size(); i < n; i++) {
            WindSource f = wind.get(i);
            double w = f.weight(t);
            FlowDef d = f.def();
            if (!WindField.flattens(f.kind()) || w <= 0 || d == null) {
                continue;
            }
            double reach = w * Math.abs(d.strength()) / (2 * Math.PI * speed);
            if (reach < d.coreRadius()) {
                continue; // its fastest wind, at its core, is slower than the speed that flattens
            }
            wrote[b] |= within(f.centreX(), f.centreZ(), Math.min(reach, f.influenceRadius()), visible, px, pz);
        }
    }

    /** Evaluates the push at the visible trail plants within {@code reach} of (cx, cz); whether any was. */
    private boolean within(double cx, double cz, double reach, boolean[] visible, float[] px, float[] pz) {
        if (!(reach > 0)) {
            return false;
        }
        double r = Math.min(reach, 1e7);
        int ax = cellClamp(cx - r - gridX, cellsX);
        int bx = cellClamp(cx + r - gridX, cellsX);
        int az = cellClamp(cz - r - gridZ, cellsZ);
        int bz = cellClamp(cz + r - gridZ, cellsZ);
        double r2 = r * r;
        boolean any = false;
        for (int z = az; z <= bz; z++) {
            for (int x = ax; x <= bx; x++) {
                int c = z * cellsX + x;
                for (int k = cellStart[c], e = cellStart[c + 1]; k < e; k++) {
                    int p = cellPlants[k];
                    double dx = plantX[p] - cx;
                    double dz = plantZ[p] - cz;
                    if (visible[p] && dx * dx + dz * dz <= r2) {
                        wind.flatteningVelocity(plantX[p], plantZ[p], velocity);
                        px[p] = (float) velocity.x;
                        pz[p] = (float) velocity.y;
                        any = true;
                    }
                }
            }
        }
        return any;
    }
}
