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
 * @param thinStart         distance thinning of the drawing: the distance where it starts, metres, in [0,
 *                          {@link #MAX_LOD_DISTANCE}] (see {@code org.jecosys.sim.DrawDecision})
 * @param thinEnd           where the kept share reaches thinMinFraction, metres, &gt;= thinStart
 * @param thinMinFraction   share of plants kept at and beyond thinEnd, in [0, 1]; 1 (the default) for no
 *                          thinning
 * @param lodFovY           the vertical field of view, radians, that every level-of-detail distance (the
 *                          field's and the species') is meant for: a view with another lens, or an
 *                          orthographic one, picks the level a plant's projected size on screen gives,
 *                          as if it were seen through this lens (see {@code org.jecosys.sim.ViewLod});
 *                          in [{@link #MIN_LOD_FOV_DEGREES}, {@link #MAX_LOD_FOV_DEGREES}] degrees
 */
public record ForceFieldDef(boolean enabled, int maxObjectsPerNode, int maxDepth, List<Double> lodDistances,
                            double thinStart, double thinEnd, double thinMinFraction, double lodFovY) {
    /** Largest allowed {@link #maxDepth()}. */
    public static final int MAX_DEPTH = 16;
    /** Largest {@link #maxObjectsPerNode()} (the scene schema's range and the API's). */
    public static final int MAX_OBJECTS_PER_NODE = 1_000_000;
    /** Most {@link #lodDistances()}. */
    public static final int MAX_LOD_DISTANCES = 16;
    /** Largest LOD distance, metres. */
    public static final double MAX_LOD_DISTANCE = 1e6;
    /** Default {@link #thinStart()}, metres. */
    public static final double DEFAULT_THIN_START = 30;
    /** Default {@link #thinEnd()}, metres. */
    public static final double DEFAULT_THIN_END = 60;
    /** Default {@link #thinMinFraction()}: 1, no thinning. */
    public static final double DEFAULT_THIN_MIN_FRACTION = 1;
    /** Default {@link #lodFovY()}, radians: 60 degrees, the default camera's lens. */
    public static final double DEFAULT_LOD_FOV_Y = Math.toRadians(60);
    /** Smallest {@link #lodFovY()}, degrees. */
    public static final double MIN_LOD_FOV_DEGREES = 1;
    /** Largest {@link #lodFovY()}, degrees. */
    public static final double MAX_LOD_FOV_DEGREES = 179;

    /**
     * Checks the components and copies the distances.
     *
     * @param enabled           whether the field evaluates flows
     * @param maxObjectsPerNode split threshold, in [1, {@link #MAX_OBJECTS_PER_NODE}]
     * @param maxDepth          deepest level, in [0, {@link #MAX_DEPTH}]
     * @param lodDistances      at most {@link #MAX_LOD_DISTANCES} strictly ascending distances, metres, each
     *                          in (0, {@link #MAX_LOD_DISTANCE}]
     * @param thinStart         where distance thinning starts, metres, in [0, {@link #MAX_LOD_DISTANCE}]
     * @param thinEnd           where it reaches thinMinFraction, metres, in [thinStart,
     *                          {@link #MAX_LOD_DISTANCE}]
     * @param thinMinFraction   share of plants kept beyond thinEnd, in [0, 1]; 1 for none
     * @param lodFovY           the lens the LOD distances are meant for, radians, in
     *                          [{@link #MIN_LOD_FOV_DEGREES}, {@link #MAX_LOD_FOV_DEGREES}] degrees
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
        Require.range("thinStart", thinStart, 0, MAX_LOD_DISTANCE);
        Require.range("thinEnd", thinEnd, 0, MAX_LOD_DISTANCE);
        if (thinEnd < thinStart) {
            throw new IllegalArgumentException("thinEnd must be >= thinStart, got " + thinEnd + " < " + thinStart);
        }
        Require.range("thinMinFraction", thinMinFraction, 0, 1);
        Require.degrees("lodFovY", lodFovY, MIN_LOD_FOV_DEGREES, MAX_LOD_FOV_DEGREES);
    }

    /**
     * Settings with the default {@link #lodFovY()} ({@link #DEFAULT_LOD_FOV_Y}); checks as the canonical
     * constructor does.
     *
     * @param enabled           whether the field evaluates flows
     * @param maxObjectsPerNode split threshold, in [1, {@link #MAX_OBJECTS_PER_NODE}]
     * @param maxDepth          deepest level, in [0, {@link #MAX_DEPTH}]
     * @param lodDistances      strictly ascending distances, metres
     * @param thinStart         where distance thinning starts, metres
     * @param thinEnd           where it reaches thinMinFraction, metres
     * @param thinMinFraction   share of plants kept beyond thinEnd, in [0, 1]
     * @throws IllegalArgumentException when a value is out of range or the distances do not ascend
     */
    public ForceFieldDef(boolean enabled, int maxObjectsPerNode, int maxDepth, List<Double> lodDistances,
                         double thinStart, double thinEnd, double thinMinFraction) {
        this(enabled, maxObjectsPerNode, maxDepth, lodDistances, thinStart, thinEnd, thinMinFraction,
                DEFAULT_LOD_FOV_Y);
    }

    /**
     * Settings without distance thinning ({@link #DEFAULT_THIN_START}, {@link #DEFAULT_THIN_END},
     * {@link #DEFAULT_THIN_MIN_FRACTION}); checks as the canonical constructor does.
     *
     * @param enabled           whether the field evaluates flows
     * @param maxObjectsPerNode split threshold, in [1, {@link #MAX_OBJECTS_PER_NODE}]
     * @param maxDepth          deepest level, in [0, {@link #MAX_DEPTH}]
     * @param lodDistances      strictly ascending distances, metres
     * @throws IllegalArgumentException when a value is out of range or the distances do not ascend
     */
    public ForceFieldDef(boolean enabled, int maxObjectsPerNode, int maxDepth, List<Double> lodDistances) {
        this(enabled, maxObjectsPerNode, maxDepth, lodDistances, DEFAULT_THIN_START, DEFAULT_THIN_END,
                DEFAULT_THIN_MIN_FRACTION);
    }

    /**
     * {@return these settings with the field switched on or off, every other value kept}
     *
     * @param on whether the field evaluates flows
     */
    public ForceFieldDef withEnabled(boolean on) {
        return new ForceFieldDef(on, maxObjectsPerNode, maxDepth, lodDistances, thinStart, thinEnd, thinMinFraction,
                lodFovY);
    }

    /** {@return enabled, 8 plants per node, depth 8, collapse one level beyond 15 m and two beyond 30 m} */
    public static ForceFieldDef defaults() {
        return new ForceFieldDef(true, 8, 8, List.of(15.0, 30.0));
    }
}
