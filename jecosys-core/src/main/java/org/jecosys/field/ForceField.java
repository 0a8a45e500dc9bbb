package org.jecosys.field;

import org.jecosys.math.Camera;
import org.joml.Vector2d;

/**
 * The force field (paper §3): places plants on the ground, updates visibility and level of detail
 * from the camera, and answers the wind acting on each plant. Every plant belongs to exactly one
 * leaf node; after {@link #update} every visible plant is represented by one <i>effective node</i>
 * (its leaf or an ancestor chosen by distance LOD) whose resultant wind velocity it shares.
 *
 * <p>The field stores wind <b>velocity</b> (m/s, x = X component, y = Z component), not force: the
 * animation layer converts it per species with {@link DragLaw}.
 *
 * <p>Threads: one owner thread calls every method; not thread-safe. After {@link #update}
 * returns, the per-plant queries may be read by other threads as long as the owner does not
 * call {@code update}, {@link #addPlant} or {@link #movePlant} meanwhile. Queries and
 * {@code update} do not allocate.
 */
public interface ForceField {

    /**
     * Adds a plant at ground point (x, z), metres, inside the field's bounds; returns its id
     * (0, 1, 2, ... in order). A plant added or moved into a leaf created since the last
     * {@link #update} reads as not visible until the next one. Allocates only when arrays must grow.
     */
    int addPlant(double x, double z);

    /** Moves a movable plant/object to (x, z), metres, re-locating its leaf. No allocation unless arrays grow. */
    void movePlant(int plant, double x, double z);

    /** Number of plants. */
    int plantCount();

    /**
     * Recomputes visibility, LOD and the wind of every effective node for this camera, with the
     * flows at their current time (paper §3.1.1 and §3.2). No allocation.
     */
    void update(Camera camera);

    /** Whether the plant was on a visible node at the last update (invisible plants are not animated). */
    boolean isVisible(int plant);

    /** The effective node representing the plant at the last update, or -1 when it is not visible. */
    int effectiveNode(int plant);

    /** The leaf node holding the plant (stable until the tree splits that leaf). */
    int leafNode(int plant);

    /** Depth of the plant's leaf (root 0). */
    int depth(int plant);

    /**
     * Writes the wind velocity (m/s) at the plant's effective node into dest; (0, 0) when the
     * plant is not visible. No allocation.
     */
    Vector2d wind(int plant, Vector2d dest);

    /**
     * Bulk per-plant read for the animation workers: for plants {@code first .. first + n - 1}
     * writes {@code visible[i]} and, for visible plants only, {@code windX[i]}, {@code windZ[i]}
     * (m/s) at index {@code i = plant - first}; invisible plants keep their previous wind
     * ("they keep their last state"). No allocation.
     */
    void gather(int first, int n, float[] windX, float[] windZ, boolean[] visible);

    /** Counters of the last update (a live, preallocated view). */
    FieldCounters counters();

    /** Per-node debug data of the last update, for the viewer's overlays (a live, preallocated view). */
    FieldDebugView debugView();
}
