package org.jecosys.plant;

import org.jecosys.math.Require;

/**
 * A {@link PlantComponent} that forwards every method to another one: extend it and override only
 * what changes (a stiffer spring, a slower response, other pose tables). The usual base of a
 * {@link ComponentFactory}'s result. Immutable when the delegate is; any thread; allocates nothing.
 */
public class ForwardingPlantComponent implements PlantComponent {
    /** The component every method forwards to. */
    protected final PlantComponent delegate;

    /**
     * Forwards to {@code delegate}.
     *
     * @param delegate the component to forward to, not null
     * @throws IllegalArgumentException when delegate is null
     */
    public ForwardingPlantComponent(PlantComponent delegate) {
        this.delegate = Require.nonNull("delegate", delegate);
    }

    @Override
    public ComponentDef def() {
        return delegate.def();
    }

    @Override
    public int variants() {
        return delegate.variants();
    }

    @Override
    public PoseTable poseTable(int variant) {
        return delegate.poseTable(variant);
    }

    @Override
    public double length(int variant) {
        return delegate.length(variant);
    }

    @Override
    public double mass(int variant) {
        return delegate.mass(variant);
    }

    @Override
    public double stiffness() {
        return delegate.stiffness();
    }

    @Override
    public double responseTime() {
        return delegate.responseTime();
    }

    @Override
    public double dragArea() {
        return delegate.dragArea();
    }

    @Override
    public int levels() {
        return delegate.levels();
    }

    @Override
    public int lodPointCount(int level) {
        return delegate.lodPointCount(level);
    }

    @Override
    public int lodPoint(int level, int i) {
        return delegate.lodPoint(level, i);
    }

    @Override
    public ComponentMesh mesh(int level) {
        return delegate.mesh(level);
    }
}
