package org.jecosys.math;

/**
 * Squared distances from a point to an axis-aligned box kept as six floats in an array (minimum X, Y,
 * Z, then maximum, metres, from an offset), as the per-chunk boxes of plant bases are. Any thread; no
 * allocation.
 */
public final class Boxes {
    private Boxes() {
    }

    /**
     * {@return the squared distance from (x, y, z) to the box's nearest point, metres^2; 0 inside it}
     *
     * @param box the boxes
     * @param o   where this box starts
     * @param x   the point's X, metres (likewise y, z)
     * @param y   the point's Y
     * @param z   the point's Z
     */
    public static double near2(float[] box, int o, double x, double y, double z) {
        double dx = gap(x, box[o], box[o + 3]);
        double dy = gap(y, box[o + 1], box[o + 4]);
        double dz = gap(z, box[o + 2], box[o + 5]);
        return dx * dx + dy * dy + dz * dz;
    }

    /**
     * {@return the squared distance from (x, y, z) to the box's farthest point (a corner), metres^2}
     *
     * @param box the boxes
     * @param o   where this box starts
     * @param x   the point's X, metres (likewise y, z)
     * @param y   the point's Y
     * @param z   the point's Z
     */
    public static double far2(float[] box, int o, double x, double y, double z) {
        double dx = Math.max(Math.abs(x - box[o]), Math.abs(x - box[o + 3]));
        double dy = Math.max(Math.abs(y - box[o + 1]), Math.abs(y - box[o + 4]));
        double dz = Math.max(Math.abs(z - box[o + 2]), Math.abs(z - box[o + 5]));
        return dx * dx + dy * dy + dz * dz;
    }

    /** How far e lies outside [lo, hi], 0 inside. */
    private static double gap(double e, double lo, double hi) {
        return e < lo ? lo - e : e > hi ? e - hi : 0;
    }
}
