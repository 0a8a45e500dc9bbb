package org.jecosys.render.ground;

import org.jecosys.sim.World;

/**
 * Where the ground cover grows ({@code <groundCover>}): a level in [0, 1] per texel of a grid over the
 * terrain, rising with the number of plants within {@code spread} metres of the point. Each plant adds a
 * smooth bump {@code (1 - (d / spread)^2)^2} to a count, worked out on a coarse grid (a quarter of the
 * spread, at least {@value #MIN_CELL} m) and read bilinearly onto the fine one; the level is
 * {@code 1 - exp(-count / }{@value #SATURATION}{@code )}, so a few plants nearby cover the ground and a
 * lone plant in open ground gets a patch of cover round its foot. Built on any thread, allocates; immutable
 * after construction.
 */
public final class CoverMap {
    /** Smallest cell of the coarse count grid, metres. */
    public static final double MIN_CELL = 0.1;
    /** Count of nearby plants at which the cover reaches 63% (1 - 1/e). */
    public static final double SATURATION = 1.5;

    /** The spread the map was built with, metres. */
    public final double spread;
    /** Cover level per fine texel, rows along X, in [0, 1]. */
    public final float[] level;

    private CoverMap(double spread, float[] level) {
        this.spread = spread;
        this.level = level;
    }

    /**
     * Builds the map on a grid whose texel (i, j) centre is at {@code (minX + i texelX, minZ + j texelZ)}
     * (the contact-occlusion map's grid).
     *
     * @param world  the plants
     * @param spread distance from a plant over which it brings cover, metres, &gt; 0
     * @param width  texels along X
     * @param height texels along Z
     * @param minX   X of texel column 0, metres
     * @param minZ   Z of texel row 0, metres
     * @param texelX texel size along X, metres
     * @param texelZ texel size along Z, metres
     * @return the map
     */
    public static CoverMap of(World world, double spread, int width, int height, double minX, double minZ,
                              double texelX, double texelZ) {
        double sizeX = (width - 1) * texelX;
        double sizeZ = (height - 1) * texelZ;
        double cell = Math.max(MIN_CELL, spread / 4);
        int cw = (int) Math.ceil(sizeX / cell) + 1;
        int ch = (int) Math.ceil(sizeZ / cell) + 1;
        double cx = sizeX / (cw - 1);
        double cz = sizeZ / (ch - 1);
        float[] count = new float[cw * ch];
        double r2 = spread * spread;
        for (int p = 0; p < world.plantCount(); p++) {
            double u = (world.plantX(p) - minX) / cx;
            double v = (world.plantZ(p) - minZ) / cz;
            int i0 = (int) Math.max(0, Math.ceil(u - spread / cx));
            int i1 = (int) Math.min(cw - 1, Math.floor(u + spread / cx));
            int j0 = (int) Math.max(0, Math.ceil(v - spread / cz));
            int j1 = (int) Math.min(ch - 1, Math.floor(v + spread / cz));
            for (int j = j0; j <= j1; j++) {
                double dz = (j - v) * cz;
                for (int i = i0; i <= i1; i++) {
                    double dx = (i - u) * cx;
                    double q = 1 - (dx * dx + dz * dz) / r2;
                    if (q > 0) {
                        count[j * cw + i] += (float) (q * q);
                    }
                }
            }
        }
        float[] level = new float[width * height];
        for (int j = 0; j < height; j++) {
            double v = Math.min(ch - 1.000001, j * texelZ / cz);
            int vj = (int) v;
            double fv = v - vj;
            for (int i = 0; i < width; i++) {
                double u = Math.min(cw - 1.000001, i * texelX / cx);
                int ui = (int) u;
                double fu = u - ui;
                double a = count[vj * cw + ui];
                double b = count[vj * cw + ui + 1];
                double c = count[(vj + 1) * cw + ui];
                double d = count[(vj + 1) * cw + ui + 1];
                double n = (a * (1 - fu) + b * fu) * (1 - fv) + (c * (1 - fu) + d * fu) * fv;
                level[j * width + i] = (float) (1 - Math.exp(-n / SATURATION));
            }
        }
        return new CoverMap(spread, level);
    }
}
