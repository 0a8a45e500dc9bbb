package org.jecosys.field;

import java.util.List;
import org.jecosys.math.Require;

/**
 * Settings of the LOD quadtree force field (paper §3.1). Immutable; any thread.
 *
 * @param enabled           when false, no flow is evaluated and plants receive no force
 * @param maxObjectsPerNode a leaf splits into four when it would hold more plants than this, &gt;= 1
 * @param maxDepth          the deepest level a node may have (root is depth 0), in [0, 16]
 * @param lodDistances      ascending distances in metres: beyond the i-th (1-based) distance, i
 *                          levels collapse into their ancestor; empty for no distance LOD
 */
public record ForceFieldDef(boolean enabled, int maxObjectsPerNode, int maxDepth, List<Double> lodDistances) {
    /** Largest allowed {@link #maxDepth()}. */
    public static final int MAX_DEPTH = 16;
    /** Largest {@link #maxObjectsPerNode()} (the scene schema's range and the API's). */
    public static final int MAX_OBJECTS_PER_NODE = 1_000_000;
    /** Most {@link #lodDistances()}. */
    public static final int MAX_LOD_DISTANCES = 16;
    /** Largest LOD distance, metres. */
    public static final double MAX_LOD_DISTANCE = 1e6;

    /**
     * Checks the components and copies the distances.
     *
     * @param enabled           whether the field evaluates flows
     * @param maxObjectsPerNode split threshold, in [1, {@link #MAX_OBJECTS_PER_NODE}]
     * @param maxDepth          deepest level, in [0, {@link #MAX_DEPTH}]
     * @param lodDistances      at most {@link #MAX_LOD_DISTANCES} strictly ascending distances, metres, each
     *                          in (0, {@link #MAX_LOD_DISTANCE}]
     * @throws IllegalArgumentException when a value is out of range or the distances do not ascend
     */
    public ForceFieldDef {
        Require.range("maxObjectsPerNode", maxObjectsPerNode, 1, MAX_OBJECTS_PER_NODE);
        Require.range("maxDepth", maxDepth, 0, MAX_DEPTH);
        lodDistances = List.copyOf(Require.nonNull("lodDistances", lodDistances));
        if (lodDistances.size() > MAX_LOD_DISTANCES) {
            throw new IllegalArgumentException("lodDistances holds at most " + MAX_LOD_DISTANCES + " distances, got "
                    + lodDistances.size());
        }
        double prev = 0;
        for (int i = 0; i < lodDistances.size(); i++) {
            double d = Require.above("lodDistances[" + i + "]", lodDistances.get(i), 0, MAX_LOD_DISTANCE);
            if (d <= prev) {
                throw new IllegalArgumentException("lodDistances must be strictly ascending, got "
                        + lodDistances);
            }
            prev = d;
        }
    }

    /** {@return enabled, 8 plants per node, depth 8, collapse one level beyond 15 m and two beyond 30 m} */
    public static ForceFieldDef defaults() {
        return new ForceFieldDef(true, 8, 8, List.of(15.0, 30.0));
    }
}
