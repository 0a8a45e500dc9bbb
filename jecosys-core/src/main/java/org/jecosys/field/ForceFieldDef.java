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
            double d = Require.elementAbove("lodDistances", i, lodDistances.get(i), 0, MAX_LOD_DISTANCE);
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
     * {@return these settings with the field switched on or off, every other value kept}
     *
     * @param on whether the field evaluates flows
     */
    public ForceFieldDef withEnabled(boolean on) {
        return new ForceFieldDef(on, maxObjectsPerNode, maxDepth, lodDistances, thinStart, thinEnd, thinMinFraction,
                lodFovY);
    }

    /** Default {@link #maxObjectsPerNode()}. */
    public static final int DEFAULT_MAX_OBJECTS_PER_NODE = 8;
    /** Default {@link #maxDepth()}. */
    public static final int DEFAULT_MAX_DEPTH = 8;
    /** Default {@link #lodDistances()}, metres: collapse one level beyond 15 m and two beyond 30 m. */
    public static final List<Double> DEFAULT_LOD_DISTANCES = List.of(15.0, 30.0);

    /**
     * {@return the scene schema's defaults, {@code builder().build()}: enabled, 8 plants per node, depth
     * 8, collapse one level beyond 15 m and two beyond 30 m, no thinning, a 60 degree lens} Any thread;
     * allocates.
     */
    public static ForceFieldDef defaults() {
        return builder().build();
    }

    /**
     * A builder with every value at the scene schema's default ({@code DEFAULT_*}): what an empty
     * {@code <field/>} element loads as. Any thread; allocates.
     *
     * @return a new builder
     */
    public static Builder builder() {
        return new Builder();
    }

    /**
     * A builder holding every value of this def, to change a few. Any thread; allocates.
     *
     * @return a new builder
     */
    public Builder toBuilder() {
        return new Builder().enabled(enabled).maxObjectsPerNode(maxObjectsPerNode).maxDepth(maxDepth)
                .lodDistances(lodDistances).thinning(thinStart, thinEnd, thinMinFraction).lodFovY(lodFovY);
    }

    /**
     * Fluent builder of a {@link ForceFieldDef} with the scene schema's defaults (see
     * {@link ForceFieldDef#builder}); values are checked by {@link #build()}. One thread; allocates.
     */
    public static final class Builder {
        private boolean enabled = true;
        private int maxObjectsPerNode = DEFAULT_MAX_OBJECTS_PER_NODE;
        private int maxDepth = DEFAULT_MAX_DEPTH;
        private List<Double> lodDistances = DEFAULT_LOD_DISTANCES;
        private double thinStart = DEFAULT_THIN_START;
        private double thinEnd = DEFAULT_THIN_END;
        private double thinMinFraction = DEFAULT_THIN_MIN_FRACTION;
        private double lodFovY = DEFAULT_LOD_FOV_Y;

        private Builder() {
        }

        /**
         * Sets whether the field evaluates flows (default true).
         *
         * @param enabled false: no flow is evaluated and plants receive no force
         * @return this builder
         */
        public Builder enabled(boolean enabled) {
            this.enabled = enabled;
            return this;
        }

        /**
         * Sets the split threshold.
         *
         * @param maxObjectsPerNode plants a leaf holds before it splits, in [1, {@link #MAX_OBJECTS_PER_NODE}]
         * @return this builder
         */
        public Builder maxObjectsPerNode(int maxObjectsPerNode) {
            this.maxObjectsPerNode = maxObjectsPerNode;
            return this;
        }

        /**
         * Sets the deepest level.
         *
         * @param maxDepth the deepest level a node may have (root is 0), in [0, {@link #MAX_DEPTH}]
         * @return this builder
         */
        public Builder maxDepth(int maxDepth) {
            this.maxDepth = maxDepth;
            return this;
        }

        /**
         * Sets the level-of-detail distances.
         *
         * @param lodDistances strictly ascending distances, metres; empty for no distance LOD
         * @return this builder
         */
        public Builder lodDistances(List<Double> lodDistances) {
            this.lodDistances = lodDistances;
            return this;
        }

        /**
         * Sets the level-of-detail distances.
         *
         * @param lodDistances strictly ascending distances, metres; none for no distance LOD
         * @return this builder
         */
        public Builder lodDistances(double... lodDistances) {
            Require.nonNull("lodDistances", lodDistances);
            List<Double> list = new java.util.ArrayList<>(lodDistances.length);
            for (double d : lodDistances) {
                list.add(d);
            }
            this.lodDistances = list;
            return this;
        }

        /**
         * Sets the distance thinning of the drawing (default none).
         *
         * @param start       where thinning starts, metres, in [0, {@link #MAX_LOD_DISTANCE}]
         * @param end         where the kept share reaches {@code minFraction}, metres, &gt;= start
         * @param minFraction share of plants kept at and beyond {@code end}, in [0, 1]; 1 for none
         * @return this builder
         */
        public Builder thinning(double start, double end, double minFraction) {
            this.thinStart = start;
            this.thinEnd = end;
            this.thinMinFraction = minFraction;
            return this;
        }

        /**
         * Sets the lens the level-of-detail distances are meant for.
         *
         * @param lodFovY vertical field of view, radians, in [{@link #MIN_LOD_FOV_DEGREES},
         *                {@link #MAX_LOD_FOV_DEGREES}] degrees
         * @return this builder
         */
        public Builder lodFovY(double lodFovY) {
            this.lodFovY = lodFovY;
            return this;
        }

        /**
         * The def. Allocates.
         *
         * @return a new def
         * @throws IllegalArgumentException when a value is out of range or the distances do not ascend
         */
        public ForceFieldDef build() {
            return new ForceFieldDef(enabled, maxObjectsPerNode, maxDepth, lodDistances, thinStart, thinEnd,
                    thinMinFraction, lodFovY);
        }
    }
}
