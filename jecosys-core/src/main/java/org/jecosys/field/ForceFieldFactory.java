package org.jecosys.field;

import org.jecosys.wind.WindField;

/**
 * Builds the force field a simulation drives its animation with (paper §3; an extension point, see
 * docs/ARCHITECTURE.md, "Extension points"; §5.1's framework interfaces). The default, {@link #QUADTREE}, is the paper's LOD quadtree
 * ({@link QuadtreeForceField}); a game may supply another {@link ForceField}, for instance one that
 * reads its own wind simulation, or one that wraps the quadtree and adds a local effect.
 *
 * <p>Contract for the field returned: it holds exactly {@code plantX.length} plants, plant i at
 * ({@code plantX[i]}, {@code plantZ[i]}) with id i (the world's plant order); it evaluates the
 * wind of the given {@link WindField} at that field's current time (the simulation advances it,
 * and queues the game's flows into it, before each {@link ForceField#update}); and it follows the
 * thread and allocation rules of {@link ForceField} (one owner thread, the simulation's stepping
 * thread; no allocation in {@code update} and {@code gather}).
 *
 * <p>Called once, at simulation build time, on the building thread; may allocate.
 */
@FunctionalInterface
public interface ForceFieldFactory {
    /** The paper's LOD quadtree force field (§3.1), what a simulation uses unless told otherwise. */
    ForceFieldFactory QUADTREE = (bounds, def, wind, plantX, plantZ) -> QuadtreeForceField.build(def, bounds.minX(),
            bounds.minZ(), bounds.maxX(), bounds.maxZ(), bounds.minY(), bounds.maxY(), wind, plantX, plantZ);

    /**
     * Builds the field of a simulation.
     *
     * @param bounds the terrain's box, the tallest plant included
     * @param def    the simulation's field settings (a custom field may ignore what it does not use;
     *               {@code enabled} is also applied by the simulation, which skips the field when off)
     * @param wind   the simulation's flows, to evaluate at their current time
     * @param plantX per plant (world order) its X, metres; a fresh array the field may keep
     * @param plantZ per plant its Z, metres; a fresh array the field may keep
     * @return the field, holding every plant
     */
    ForceField create(FieldBounds bounds, ForceFieldDef def, WindField wind, float[] plantX, float[] plantZ);
}
