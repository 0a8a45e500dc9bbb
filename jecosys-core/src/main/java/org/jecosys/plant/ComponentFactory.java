package org.jecosys.plant;

/**
 * Supplies the {@link PlantComponent} a species uses for one of its component types, in place of
 * the built-in {@link ComponentModel} (an extension point, see docs/ARCHITECTURE.md, "Extension
 * points"; paper §4.1 pre-computed shapes,
 * §4.2 eq. 4-5 spring, §5.1 framework interfaces). Register one per (species, component) in
 * {@link ComponentFactories} and pass them to {@code World.build}; the animation then takes the
 * component's spring constants, masses, lengths and pose tables from what the factory returns, and
 * the renderer its pose tables and meshes.
 *
 * <p>The easiest factory decorates the built-in component, e.g. a stiffer stalk:
 * <pre>{@code
 * (species, builtIn) -> new ForwardingPlantComponent(builtIn) {
 *     public double stiffness() {
 *         return 4 * super.stiffness();
 *     }
 * }
 * }</pre>
 * A factory may also build everything itself ({@link PoseTable#build}, {@link ComponentMesh#build},
 * {@link ComponentMesh#lodPoints}). Either way the component must match its species' layout, which
 * {@link SpeciesModel#withComponents} checks: {@code def()} equal to the species' def of that
 * component, one pose table per species variant with the species' pose count and
 * {@code segments + 1} points, one mesh per species level of detail drawn with that level's
 * primitive.
 *
 * <p>Called once per registered component at build time, on the building thread; may allocate.
 * The component returned must be immutable (it is read by the animation workers and the renderer).
 */
@FunctionalInterface
public interface ComponentFactory {
    /**
     * The component species {@code species} uses for the component type {@code builtIn.def()}.
     *
     * @param species the species being built
     * @param builtIn the component it replaces: the built-in {@link ComponentModel} of that type,
     *                already pre-computed (gravity-bent pose tables of every variant, meshes)
     * @return the component to use, not null
     */
    PlantComponent create(SpeciesDef species, PlantComponent builtIn);
}
