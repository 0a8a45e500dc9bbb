package org.jecosys.sim;

import org.jecosys.terrain.PlantLayout;
import org.jecosys.terrain.Terrain;

/** The order of a {@link World}'s plants: Morton order of their position over the terrain. Build time; allocates. */
final class SpatialOrder {
    private SpatialOrder() {
    }

    /**
     * The plants in Morton (Z-order) order of their position over the terrain, ties by layout index:
     * plants near each other are near each other in every per-plant and per-component array, so the
     * plants of a visible region form long contiguous runs for the animation workers and the
     * renderer. Deterministic for a layout.
     */
    static int[] of(PlantLayout layout, Terrain terrain) {
        int n = layout.count();
        org.jecosys.terrain.Heightfield h = terrain.heightfield();
        double sx = 65535 / Math.max(1e-9, h.maxX() - h.minX());
        double sz = 65535 / Math.max(1e-9, h.maxZ() - h.minZ());
        long[] keys = new long[n];
        for (int i = 0; i < n; i++) {
            int qx = (int) Math.max(0, Math.min(65535, (layout.x(i) - h.minX()) * sx));
            int qz = (int) Math.max(0, Math.min(65535, (layout.z(i) - h.minZ()) * sz));
            keys[i] = (interleave(qx) | interleave(qz) << 1) << 32 | i;
        }
        java.util.Arrays.sort(keys);
        int[] order = new int[n];
        for (int i = 0; i < n; i++) {
            order[i] = (int) keys[i];
        }
        return order;
    }

    /** Spreads the low 16 bits of v to the even bits of the result. */
    private static long interleave(int v) {
        long x = v & 0xFFFFL;
        x = (x | x << 8) & 0x00FF00FFL;
        x = (x | x << 4) & 0x0F0F0F0FL;
        x = (x | x << 2) & 0x33333333L;
        x = (x | x << 1) & 0x55555555L;
        return x;
    }
}
