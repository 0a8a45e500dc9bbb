package org.jecosys.field;

import org.jecosys.math.Require;

/**
 * The box a simulation's force field covers: the terrain's ground rectangle and the height range
 * of the terrain plus its tallest plant, the box the quadtree's nodes are culled with (paper §3.1.1).
 * Given to a {@link ForceFieldFactory}. Immutable; any thread.
 *
 * @param minX west edge, metres
 * @param minZ north edge, metres
 * @param maxX east edge, metres, &gt; minX
 * @param maxZ south edge, metres, &gt; minZ
 * @param minY lowest terrain height, metres
 * @param maxY highest terrain height plus the tallest plant, metres, &gt;= minY
 */
public record FieldBounds(double minX, double minZ, double maxX, double maxZ, double minY, double maxY) {
    /**
     * Checks the box.
     *
     * @param minX west edge, metres (finite)
     * @param minZ north edge, metres (finite)
     * @param maxX east edge, metres, &gt; minX
     * @param maxZ south edge, metres, &gt; minZ
     * @param minY lowest height, metres (finite)
     * @param maxY highest height, metres, &gt;= minY
     * @throws IllegalArgumentException when a value is not finite or the box is empty
     */
    public FieldBounds {
        Require.finite("minX", minX);
        Require.finite("minZ", minZ);
        Require.finite("maxX", maxX);
        Require.finite("maxZ", maxZ);
        Require.finite("minY", minY);
        Require.finite("maxY", maxY);
        if (maxX <= minX || maxZ <= minZ || maxY < minY) {
            throw new IllegalArgumentException("the field's bounds must not be empty, got x [" + minX + ", " + maxX
                    + "], z [" + minZ + ", " + maxZ + "], y [" + minY + ", " + maxY + "]");
        }
    }
}
