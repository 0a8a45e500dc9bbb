package org.jecosys.field;

import org.jecosys.math.Camera;
import org.joml.Vector2d;

/**
 * The force field (paper §3): places plants on the ground, updates visibility and level of detail
 * from the camera, and answers the wind acting on each plant. {@link QuadtreeForceField} is the
 * paper's; a game may give a simulation its own through a {@link ForceFieldFactory} (the
 * simulation calls only {@link #update}, {@link #gather}, {@link #plantCount}, {@link #counters}
 * and, for the viewer, {@link #debugView}; a field without nodes may answer node 0 or -1 to the
 * node queries). Every plant belongs to exactly one
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
     *
     * @param x ground X, metres, inside the bounds
     * @param z ground Z, metres, inside the bounds
     * @return the plant's id, {@code plantCount() - 1}
     */
    int addPlant(double x, double z);

    /**
     * Moves a movable plant/object to (x, z), re-locating its leaf. No allocation unless arrays grow.
     *
     * @param plant plant id, in [0, plantCount())
     * @param x     new ground X, metres
     * @param z     new ground Z, metres
     */
    void movePlant(int plant, double x, double z);

    /** {@return the number of plants} */
    int plantCount();

    /**
     * Recomputes visibility, LOD and the wind of every effective node for this camera, with the
     * flows at their current time (paper §3.1.1 and §3.2). No allocation.
     *
     * @param camera the viewer: its frustum culls nodes, its eye sets the distance LOD
     */
    void update(Camera camera);

    /**
     * Like {@link #update(Camera)} for several views at once (split screen, a minimap, a shadow map's
     * light): a plant is visible when any view sees it, and its node is as detailed as the view that
     * needs the most detail asks. A field that knows only one view keeps this default, which updates for
     * {@code camera} alone. No allocation.
     *
     * @param camera the main view
     * @param others further views, the first {@code count} of them read
     * @param count  how many of {@code others}, at least 0
     */
    default void update(Camera camera, Camera[] others, int count) {
        update(camera);
    }

    /**
     * {@return whether the plant was on a visible node at the last update (invisible plants are not animated)}
     *
     * @param plant plant id, in [0, plantCount())
     */
    boolean isVisible(int plant);

    /**
     * {@return the effective node representing the plant at the last update, or -1 when it is not visible}
     *
     * @param plant plant id, in [0, plantCount())
     */
    int effectiveNode(int plant);

    /**
     * {@return the leaf node holding the plant (stable until the tree splits that leaf)}
     *
     * @param plant plant id, in [0, plantCount())
     */
    int leafNode(int plant);

    /**
     * {@return the depth of the plant's leaf (root 0)}
     *
     * @param plant plant id, in [0, plantCount())
     */
    int depth(int plant);

    /**
     * Writes the wind velocity (m/s; x = X, y = Z) at the plant into dest: its effective node's wind
     * (the quadtree field refines it inside the node by the node's wind gradient); (0, 0) when the
     * plant is not visible. No allocation.
     *
     * @param plant plant id, in [0, plantCount())
     * @param dest  where to write
     * @return {@code dest}
     */
    Vector2d wind(int plant, Vector2d dest);

    /**
     * Bulk per-plant read for the animation workers: for plants {@code first .. first + n - 1}
     * writes {@code visible[i]} and, for visible plants only, {@code windX[i]}, {@code windZ[i]}
     * (m/s) at index {@code i = plant - first}; invisible plants keep their previous wind
     * ("they keep their last state"). No allocation.
     *
     * @param first   first plant id
     * @param n       number of plants; {@code first + n <= plantCount()}
     * @param windX   receives wind X, m/s, at indices [0, n)
     * @param windZ   receives wind Z, m/s, at indices [0, n)
     * @param visible receives visibility at indices [0, n)
     */
    void gather(int first, int n, float[] windX, float[] windZ, boolean[] visible);

    /**
     * Counters of the last update (a live, preallocated view). The default, for fields that do not
     * count, is {@link FieldCounters#NONE} (all zero).
     *
     * @return the counters, not null
     */
    default FieldCounters counters() {
        return FieldCounters.NONE;
    }

    /**
     * Per-node debug data of the last update, for the viewer's overlays (a live, preallocated view).
     * The default, for fields without nodes to show, is {@link FieldDebugView#EMPTY} (no nodes).
     *
     * @return the view, not null
     */
    default FieldDebugView debugView() {
        return FieldDebugView.EMPTY;
    }
}
