package org.jecosys.plant;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import org.jecosys.math.Require;

/**
 * The user components of a scene built in code: which {@link ComponentFactory} supplies the
 * component type {@code componentId} of species {@code speciesId} (an extension point, see
 * docs/ARCHITECTURE.md, "Extension points"; paper §5.1). Pass it to {@code World.build(def, baseDir, threads, progress, distributor,
 * components)}; types not named keep their built-in {@link ComponentModel}. Scene files cannot name
 * user components: this is the code-built path only.
 * <pre>{@code
 * ComponentFactories custom = ComponentFactories.NONE
 *         .with("grassA", "leaf", (species, builtIn) -> new ForwardingPlantComponent(builtIn) {
 *             public double stiffness() {
 *                 return 0.5 * super.stiffness();
 *             }
 *         });
 * }</pre>
 *
 * <p>Immutable; any thread. {@link #with} allocates a new instance.
 */
public final class ComponentFactories {
    /** No user components: every species uses its built-in components. */
    public static final ComponentFactories NONE = new ComponentFactories(Map.of());

    private final Map<String, Map<String, ComponentFactory>> bySpecies;

    private ComponentFactories(Map<String, Map<String, ComponentFactory>> bySpecies) {
        this.bySpecies = bySpecies;
    }

    /**
     * These factories plus {@code factory} for component type {@code componentId} of species
     * {@code speciesId} (replacing an earlier one for the same pair). Allocates.
     *
     * @param speciesId   the species' id ({@link SpeciesDef#id()})
     * @param componentId the component type's id within it ({@link ComponentDef#id()})
     * @param factory     supplies the component
     * @return a new instance; this one is unchanged
     * @throws IllegalArgumentException on a null argument
     */
    public ComponentFactories with(String speciesId, String componentId, ComponentFactory factory) {
        Require.nonNull("speciesId", speciesId);
        Require.nonNull("componentId", componentId);
        Require.nonNull("factory", factory);
        Map<String, Map<String, ComponentFactory>> m = new LinkedHashMap<>();
        for (Map.Entry<String, Map<String, ComponentFactory>> e : bySpecies.entrySet()) {
            m.put(e.getKey(), new LinkedHashMap<>(e.getValue()));
        }
        m.computeIfAbsent(speciesId, k -> new LinkedHashMap<>()).put(componentId, factory);
        Map<String, Map<String, ComponentFactory>> frozen = new LinkedHashMap<>();
        for (Map.Entry<String, Map<String, ComponentFactory>> e : m.entrySet()) {
            frozen.put(e.getKey(), Collections.unmodifiableMap(e.getValue()));
        }
        return new ComponentFactories(Collections.unmodifiableMap(frozen));
    }

    /**
     * The factory registered for a component type, or null.
     *
     * @param speciesId   the species' id
     * @param componentId the component type's id
     * @return the factory, or null when the type keeps its built-in component
     */
    public ComponentFactory get(String speciesId, String componentId) {
        Map<String, ComponentFactory> m = bySpecies.get(speciesId);
        return m == null ? null : m.get(componentId);
    }

    /**
     * Whether no factory is registered.
     *
     * @return true for {@link #NONE} and its equivalents
     */
    public boolean isEmpty() {
        return bySpecies.isEmpty();
    }

    /**
     * The species that have at least one factory, in registration order.
     *
     * @return an unmodifiable set
     */
    public Set<String> speciesIds() {
        return bySpecies.keySet();
    }

    /**
     * The component types of {@code speciesId} that have a factory, in registration order.
     *
     * @param speciesId the species' id
     * @return an unmodifiable set, empty when none
     */
    public Set<String> componentIds(String speciesId) {
        Map<String, ComponentFactory> m = bySpecies.get(speciesId);
        return m == null ? Set.of() : m.keySet();
    }
}
