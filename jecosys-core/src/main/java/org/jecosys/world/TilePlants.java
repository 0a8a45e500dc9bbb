package org.jecosys.world;

/**
 * The plants of one tile, from {@link TilePlacer#place}: flat arrays of equal length, one entry per
 * plant, in the order the competition accepted them. Positions lie in the tile's square
 * [tileI size, (tileI + 1) size) x [tileJ size, (tileJ + 1) size) (rounded to float).
 *
 * <p>The arrays are the caller's: they are not copied, and nothing else holds them. Immutable as long
 * as nobody writes into them; then any thread may read them.
 *
 * @param tileI       the tile's index along X
 * @param tileJ       the tile's index along Z
 * @param x           world X of each plant, metres
 * @param y           world Y (the ground height under the plant, from the placer's height function), metres
 * @param z           world Z, metres
 * @param species     species index of each plant (the placer's per-distribution index)
 * @param variantSeed seed of each plant's variation (shape, size class), any long
 * @param azimuth     rotation of each plant about Y, radians in [0, 2 pi)
 */
public record TilePlants(int tileI, int tileJ, float[] x, float[] y, float[] z, int[] species, long[] variantSeed,
                         float[] azimuth) {
    /**
     * Checks that the arrays are present and of one length.
     *
     * @param tileI       the tile's index along X
     * @param tileJ       the tile's index along Z
     * @param x           world X of each plant, metres
     * @param y           world Y of each plant, metres
     * @param z           world Z of each plant, metres
     * @param species     species index of each plant
     * @param variantSeed seed of each plant's variation
     * @param azimuth     rotation of each plant about Y, radians
     * @throws IllegalArgumentException when an array is null or their lengths differ
     */
    public TilePlants {
        if (x == null || y == null || z == null || species == null || variantSeed == null || azimuth == null) {
            throw new IllegalArgumentException("the arrays of a tile must not be null");
        }
        int n = x.length;
        if (y.length != n || z.length != n || species.length != n || variantSeed.length != n || azimuth.length != n) {
            throw new IllegalArgumentException("the arrays of a tile must have one length, got x " + n + ", y "
                    + y.length + ", z " + z.length + ", species " + species.length + ", variantSeed "
                    + variantSeed.length + ", azimuth " + azimuth.length);
        }
    }

    /** {@return the number of plants} */
    public int count() {
        return x.length;
    }
}
