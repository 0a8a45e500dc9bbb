package org.jecosys.plant;

/**
 * A component type of a species, ready to animate and draw (DESIGN.md extension point; paper §4.1
 * and §4.2): its pre-computed bent skeletons (one {@link PoseTable} per shape variant), its level of
 * detail subsets and meshes, and its dynamic-constraint parameters. The updater in {@code anim}
 * animates every component of a type over flat arrays using these values.
 *
 * <p>Implementations are immutable after construction: any thread; accessors do not allocate.
 */
public interface PlantComponent {
    /** The definition this component was built from. */
    ComponentDef def();

    /** Shape variants (pose tables) of this component type, &gt;= 1. */
    int variants();

    /** The pose table of shape variant {@code variant}, in [0, variants()). */
    PoseTable poseTable(int variant);

    /** Skeleton length of variant {@code variant}, metres (used by {@link PoseMapping}). */
    double length(int variant);

    /** Mass of variant {@code variant}, kg (eq. 4's m). */
    double mass(int variant);

    /** Spring constant PC of eq. 4, N/m. */
    double stiffness();

    /** Response time tau of the dynamic constraint, seconds. */
    double responseTime();

    /** Drag coefficient times area, m^2. */
    double dragArea();

    /** Levels of detail (the species' count). */
    int levels();

    /** Skeleton points used at {@code level} (animation updates only these, §4.1). */
    int lodPointCount(int level);

    /** The {@code i}-th point index used at {@code level}, ascending. */
    int lodPoint(int level, int i);

    /** The mesh of one instance of this component at {@code level}. */
    ComponentMesh mesh(int level);
}
