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
 */
public record SpeciesDef(String id, String name, int poses, double maxBend, List<ComponentDef> components,
                         List<LodDef> lods, VariationDef variation) {
    /** Default pose-table size (DESIGN.md). */
    public static final int DEFAULT_POSES = 16;

    public SpeciesDef {
        Require.nonNull("id", id);
        if (id.isEmpty()) {
            throw new IllegalArgumentException("id must not be empty");
        }
        Require.nonNull("name", name);
        Require.range("poses", poses, 2, 64);
        Require.range("maxBend", maxBend, 1e-3, Math.PI / 2);
        components = List.copyOf(Require.nonNull("components", components));
        lods = List.copyOf(Require.nonNull("lods", lods));
        Require.nonNull("variation", variation);
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

    /** Components summed over a plant: the sum of every component's count. */
    public int componentsPerPlant() {
        int n = 0;
        for (ComponentDef c : components) {
            n += c.count();
        }
        return n;
    }
}
