package org.jecosys.plant;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.jecosys.math.Require;

/**
 * A plant species: its components, levels of detail and variation (paper §4.1, Tables 1-3).
 * Immutable; any thread.
 *
 * @param id        unique within the scene; distributions refer to it
 * @param name      human-readable name
 * @param poses     pose-table size K: poses from rest to {@code maxBend}, in [2, 64]
 * @param maxBend   bend of the last pose beyond the rest shape, radians, in (0, pi/2]
 * @param components the component types, at least one
 * @param lods      levels of detail ordered by ascending maxDistance; the last is unbounded
 * @param variation per-instance variation
 * @param trail     how strong pushes leave trails ({@link TrailDef#NONE}: none)
 */
public record SpeciesDef(String id, String name, int poses, double maxBend, List<ComponentDef> components,
                         List<LodDef> lods, VariationDef variation, TrailDef trail) {
    /** Largest pose-table size K (the scene schema's range and the API's). */
    public static final int MAX_POSES = 64;
    /** Smallest {@link #maxBend()}, degrees (the API takes radians). */
    public static final double MIN_MAX_BEND_DEGREES = 0.1;
    /** Largest {@link #maxBend()}, degrees. */
    public static final double MAX_MAX_BEND_DEGREES = 90;
    /** Default pose-table size K: 16 poses from rest to {@code maxBend}. */
    public static final int DEFAULT_POSES = 16;

    /**
     * Checks the components and copies the lists.
     *
     * @param id         unique within the scene, not empty
     * @param name       human-readable name, not null
     * @param poses      pose-table size, in [2, {@link #MAX_POSES}]
     * @param maxBend    bend of the last pose, radians, in [{@link #MIN_MAX_BEND_DEGREES},
     *                   {@link #MAX_MAX_BEND_DEGREES}] degrees
     * @param components at least one; unique ids, one lodSegments value per level, attachTo naming
     *                   another component
     * @param lods       at least one, maxDistance ascending, only the last one unbounded
     * @param variation  per-instance variation, not null
     * @param trail      trails after strong pushes, not null ({@link TrailDef#NONE} for none)
     * @throws IllegalArgumentException when a rule above is broken
     */
    public SpeciesDef {
        Require.nonNull("id", id);
        if (id.isEmpty()) {
            throw new IllegalArgumentException("id must not be empty");
        }
        Require.nonNull("name", name);
        Require.range("poses", poses, 2, MAX_POSES);
        Require.degrees("maxBend", maxBend, MIN_MAX_BEND_DEGREES, MAX_MAX_BEND_DEGREES);
        components = List.copyOf(Require.nonNull("components", components));
        lods = List.copyOf(Require.nonNull("lods", lods));
        Require.nonNull("variation", variation);
        Require.nonNull("trail", trail);
        if (components.isEmpty()) {
            throw new IllegalArgumentException("a species needs at least one component");
        }
        if (lods.isEmpty()) {
            throw new IllegalArgumentException("a species needs at least one level of detail");
        }
        double prev = 0;
        for (int i = 0; i < lods.size(); i++) {
            double d = lods.get(i).maxDistance();
            if (d <= prev) {
                throw new IllegalArgumentException("lod maxDistance must ascend, got " + d + " after " + prev);
            }
            if (d == Double.POSITIVE_INFINITY && i != lods.size() - 1) {
                throw new IllegalArgumentException("only the last lod may be unbounded");
            }
            prev = d;
        }
        if (lods.get(lods.size() - 1).maxDistance() != Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("the last lod must be unbounded (no maxDistance)");
        }
        Set<String> ids = new HashSet<>();
        for (ComponentDef c : components) {
            if (!ids.add(c.id())) {
                throw new IllegalArgumentException("duplicate component id '" + c.id() + "'");
            }
            if (c.lodSegments().size() != lods.size()) {
                throw new IllegalArgumentException("component '" + c.id() + "' lodSegments has "
                        + c.lodSegments().size() + " values, the species has " + lods.size() + " lods");
            }
        }
        for (ComponentDef c : components) {
            if (c.attachTo() != null && (!ids.contains(c.attachTo()) || c.attachTo().equals(c.id()))) {
                throw new IllegalArgumentException("component '" + c.id() + "' attachTo '" + c.attachTo()
                        + "' is not another component of this species");
            }
        }
    }

    /** {@return the components of one plant: the sum of every component's count} */
    public int componentsPerPlant() {
        int n = 0;
        for (ComponentDef c : components) {
            n += c.count();
        }
        return n;
    }

    /** Default {@link #maxBend()}, radians: 80 degrees beyond the rest shape. */
    public static final double DEFAULT_MAX_BEND = Math.toRadians(80);

    /**
     * A builder for species {@code id} with the scene schema's defaults: name = id (what the loader
     * makes of an absent name), {@link #DEFAULT_POSES} poses, {@link #DEFAULT_MAX_BEND},
     * {@link VariationDef#NONE}. At least one level of detail and one component must be added. Any
     * thread; allocates.
     *
     * @param id unique within the scene, not empty
     * @return a new builder
     */
    public static Builder builder(String id) {
        return new Builder(id);
    }

    /**
     * A builder holding every value of this def, to change a few. Any thread; allocates.
     *
     * @return a new builder
     */
    public Builder toBuilder() {
        Builder b = new Builder(id).name(name).poses(poses).maxBend(maxBend).variation(variation).trail(trail);
        b.components.addAll(components);
        b.lods.addAll(lods);
        return b;
    }

    /**
     * Fluent builder of a {@link SpeciesDef} with the scene schema's defaults (see
     * {@link SpeciesDef#builder}); values are checked by {@link #build()}. One thread; allocates.
     */
    public static final class Builder {
        private final String id;
        private String name;
        private int poses = DEFAULT_POSES;
        private double maxBend = DEFAULT_MAX_BEND;
        private VariationDef variation = VariationDef.NONE;
        private TrailDef trail = TrailDef.NONE;
        private final List<ComponentDef> components = new java.util.ArrayList<>();
        private final List<LodDef> lods = new java.util.ArrayList<>();

        private Builder(String id) {
            this.id = id;
            this.name = id;
        }

        /**
         * Sets the human-readable name.
         *
         * @param name not null
         * @return this builder
         */
        public Builder name(String name) {
            this.name = name;
            return this;
        }

        /**
         * Sets the pose-table size K.
         *
         * @param poses in [2, 64]
         * @return this builder
         */
        public Builder poses(int poses) {
            this.poses = poses;
            return this;
        }

        /**
         * Sets the bend of the last pose beyond the rest shape.
         *
         * @param maxBend radians, in (0, pi/2]
         * @return this builder
         */
        public Builder maxBend(double maxBend) {
            this.maxBend = maxBend;
            return this;
        }

        /**
         * Sets the per-instance variation.
         *
         * @param variation not null
         * @return this builder
         */
        public Builder variation(VariationDef variation) {
            this.variation = variation;
            return this;
        }

        /**
         * Sets how strong pushes leave trails.
         *
         * @param trail not null; {@link TrailDef#NONE} for none
         * @return this builder
         */
        public Builder trail(TrailDef trail) {
            this.trail = trail;
            return this;
        }

        /**
         * Adds a level of detail, after those added so far (ascending distance; the last unbounded).
         *
         * @param lod the level
         * @return this builder
         */
        public Builder lod(LodDef lod) {
            lods.add(lod);
            return this;
        }

        /**
         * Adds levels of detail, after those added so far.
         *
         * @param lods the levels, in ascending distance
         * @return this builder
         */
        public Builder lods(List<LodDef> lods) {
            this.lods.addAll(lods);
            return this;
        }

        /**
         * Adds a component type, after those added so far.
         *
         * @param component the component type
         * @return this builder
         */
        public Builder component(ComponentDef component) {
            components.add(component);
            return this;
        }

        /**
         * Adds component types, after those added so far.
         *
         * @param components the component types
         * @return this builder
         */
        public Builder components(List<ComponentDef> components) {
            this.components.addAll(components);
            return this;
        }

        /**
         * The def. Allocates.
         *
         * @return a new def
         * @throws IllegalArgumentException when a rule of {@link SpeciesDef} is broken (no level of
         *                                  detail or component, a value out of range...)
         */
        public SpeciesDef build() {
            return new SpeciesDef(id, name, poses, maxBend, components, lods, variation, trail);
        }
    }
}
