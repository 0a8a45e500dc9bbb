package org.jecosys.plant;

/**
 * The built {@link PlantComponent}: pose tables per variant, point subsets and meshes per level
 * (paper §4.1). Created by {@link SpeciesModel#build}. Immutable; any thread; accessors do not
 * allocate.
 */
public final class ComponentModel implements PlantComponent {
    private final ComponentDef def;
    private final PoseTable[] tables;
    private final double[] lengths;
    private final double[] masses;
    private final int[][] lodPoints;
    private final ComponentMesh[] meshes;

    ComponentModel(ComponentDef def, PoseTable[] tables, double[] lengths, double[] masses,
                   int[][] lodPoints, ComponentMesh[] meshes) {
        this.def = def;
        this.tables = tables;
        this.lengths = lengths;
        this.masses = masses;
        this.lodPoints = lodPoints;
        this.meshes = meshes;
    }

    @Override
    public ComponentDef def() {
        return def;
    }

    @Override
    public int variants() {
        return tables.length;
    }

    @Override
    public PoseTable poseTable(int variant) {
        return tables[variant];
    }

    @Override
    public double length(int variant) {
        return lengths[variant];
    }

    @Override
    public double mass(int variant) {
        return masses[variant];
    }

    @Override
    public double stiffness() {
        return def.stiffness();
    }

    @Override
    public double responseTime() {
        return def.responseTime();
    }

    @Override
    public double dragArea() {
        return def.dragArea();
    }

    @Override
    public int levels() {
        return meshes.length;
    }

    @Override
    public int lodPointCount(int level) {
        return lodPoints[level].length;
    }

    @Override
    public int lodPoint(int level, int i) {
        return lodPoints[level][i];
    }

    @Override
    public ComponentMesh mesh(int level) {
        return meshes[level];
    }

    /** {@return whether the tip is pointed (tipWidth 0): the strip rule with one triangle at the tip} */
    public boolean pointed() {
        return def.tipWidth() == 0;
    }

    /**
     * Continuous pose coordinate of a deviation for variant {@code variant}
     * ({@link PoseMapping#poseCoordinate} with this variant's length). No allocation.
     *
     * @param deviation deviation magnitude, metres
     * @param variant   shape variant, in [0, variants())
     * @return pose coordinate in [0, poses - 1]; its integer part and fraction pick and blend two poses
     */
    public double poseCoordinate(double deviation, int variant) {
        PoseTable t = tables[variant];
        return PoseMapping.poseCoordinate(deviation, lengths[variant], t.maxBend(), t.poses());
    }
}
