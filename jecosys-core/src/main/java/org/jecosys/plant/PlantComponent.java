package org.jecosys.plant;

/**
 * A component type of a species, ready to animate and draw (paper §4.1 and §4.2; an extension
 * point, see docs/ARCHITECTURE.md, "Extension points"): its pre-computed bent skeletons (one
 * {@link PoseTable} per shape variant), its level of
 * detail subsets and meshes, and its dynamic-constraint parameters. The updater in {@code anim}
 * animates every component of a type over flat arrays using these values.
 *
 * <p>The built-in implementation is {@link ComponentModel}; a game supplies its own for a component
 * type of a species with a {@link ComponentFactory} (often a {@link ForwardingPlantComponent} over the
 * built-in one), registered in {@link ComponentFactories}.
 *
 * <p>Implementations are immutable after construction: any thread; accessors do not allocate.
 */
public interface PlantComponent {
    /** {@return the definition this component was built from} */
    ComponentDef def();

    /** {@return the number of shape variants (pose tables) of this component type, &gt;= 1} */
    int variants();

    /**
     * {@return the pose table of a shape variant}
     *
     * @param variant shape variant, in [0, variants())
     */
    PoseTable poseTable(int variant);

    /**
     * {@return the skeleton length of a variant, metres (used by {@link PoseMapping})}
     *
     * @param variant shape variant, in [0, variants())
     */
    double length(int variant);

    /**
     * {@return the mass of a variant, kg (eq. 4's m)}
     *
     * @param variant shape variant, in [0, variants())
     */
    double mass(int variant);

    /** {@return the spring constant PC of eq. 4, N/m} */
    double stiffness();

    /** {@return the response time tau of the dynamic constraint, seconds} */
    double responseTime();

    /** {@return the drag coefficient times area, m^2} */
    double dragArea();

    /** {@return the number of levels of detail (the species' count)} */
    int levels();

    /**
     * {@return the number of skeleton points used at a level (animation updates only these, §4.1)}
     *
     * @param level level of detail, in [0, levels())
     */
    int lodPointCount(int level);

    /**
     * {@return the {@code i}-th point index used at a level; ascending in i}
     *
     * @param level level of detail, in [0, levels())
     * @param i     in [0, lodPointCount(level))
     */
    int lodPoint(int level, int i);

    /**
     * {@return the mesh of one instance of this component at a level}
     *
     * @param level level of detail, in [0, levels())
     */
    ComponentMesh mesh(int level);
}
