package org.jecosys.anim;

/**
 * A read-only view of the animated state of every plant component (paper §4.2): what a game, a tool
 * or a test may read between steps, without the updater's mutators ({@code animate},
 * {@code resetToRest}, {@code setLodScale}). Components are indexed 0 .. {@link #componentCount()} - 1
 * in the world's order, plants 0 .. {@link #plantCount()} - 1. {@link AnimationState} is the one
 * implementation; {@code Simulation.state()} hands it out as this view.
 *
 * <p>A live view, not a copy: it changes with every step. Threads: read it on the thread that owns
 * the state (a simulation's stepping thread), never while a step runs. No method allocates.
 */
public interface AnimationView {
    /**
     * The component kinds: their constants and spring coefficients, read only (the simulation
     * prepares them again at every step).
     *
     * @return a read-only view of the kinds
     */
    KindsView kinds();

    /**
     * Number of plants.
     *
     * @return plants, &gt;= 0
     */
    int plantCount();

    /**
     * Number of components of all plants.
     *
     * @return components, &gt;= 0
     */
    int componentCount();

    /**
     * First component of plant p; {@code firstComponent(plantCount())} is the component count.
     *
     * @param p plant, in [0, plantCount()]
     * @return component index
     */
    int firstComponent(int p);

    /**
     * The level-of-detail distance scale (1: the species' own distances).
     *
     * @return the scale, in [0.01, 100]
     */
    double lodScale();

    /**
     * The version of plant p's state: it changes whenever the plant's deviations may have changed,
     * so equal versions mean equal outputs.
     *
     * @param p plant
     * @return the version
     */
    long version(int p);

    /**
     * Writes the pose coordinates and azimuths of components {@code first .. end-1}, computed from
     * their current deviations, into the dest arrays (same indices). No allocation.
     *
     * @param first       first component
     * @param end         one past the last component
     * @param poseDest    pose coordinates, indexed by component
     * @param azimuthDest azimuths, radians, indexed by component
     */
    void copyOutputs(int first, int end, float[] poseDest, float[] azimuthDest);

    /**
     * Copies the levels of detail of plants {@code first .. end-1} into dest (same indices).
     *
     * @param first first plant
     * @param end   one past the last plant
     * @param dest  levels, indexed by plant
     */
    void copyLevels(int first, int end, byte[] dest);

    /**
     * Deviation X of component c: the offset of its centre of mass from rest (eq. 4's D), metres.
     *
     * @param c component
     * @return metres
     */
    float deviationX(int c);

    /**
     * Deviation Z of component c, metres.
     *
     * @param c component
     * @return metres
     */
    float deviationZ(int c);

    /**
     * Velocity X of component c's deviation, m/s.
     *
     * @param c component
     * @return m/s
     */
    float velocityX(int c);

    /**
     * Velocity Z of component c's deviation, m/s.
     *
     * @param c component
     * @return m/s
     */
    float velocityZ(int c);

    /**
     * Pose coordinate of component c, in [0, K - 1] (paper §4.1's pre-computed shapes), from its
     * deviation.
     *
     * @param c component
     * @return the continuous pose coordinate
     */
    float poseCoordinate(int c);

    /**
     * Bend azimuth of component c, radians in [-pi, pi] (local +X to (cos a, 0, sin a)).
     *
     * @param c component
     * @return radians
     */
    float azimuth(int c);

    /**
     * Kind of component c (an index into {@link #kinds()}).
     *
     * @param c component
     * @return the kind
     */
    int kind(int c);

    /**
     * Bend of component c beyond its rest shape, radians.
     *
     * @param c component
     * @return radians, &gt;= 0
     */
    float bend(int c);

    /**
     * Force on component c at its plant's last update, N, X part: {@code 0.5 rho dragArea |u| u_x}.
     *
     * @param c component
     * @return newtons
     */
    double forceX(int c);

    /**
     * Force on component c at its plant's last update, N, Z part.
     *
     * @param c component
     * @return newtons
     */
    double forceZ(int c);

    /**
     * The plant of component c (a binary search; not for per-frame use on every component).
     *
     * @param c component
     * @return plant index
     */
    int plantOf(int c);

    /**
     * Level of detail plant p was last animated at.
     *
     * @param p plant
     * @return the level, 0 the finest
     */
    int level(int p);

    /**
     * How far plant p is flattened by a strong push at its last update, as a fraction of its bend
     * limit: 0 when its species leaves no trails ({@code org.jecosys.plant.TrailDef}) or nothing pushed
     * it past its threshold lately.
     *
     * @param p plant
     * @return the fraction, in [0, 1)
     */
    float flattening(int p);

    /**
     * A 64-bit hash of the raw float bits of every component's state and outputs: equal states give
     * equal hashes (the determinism tests' fingerprint).
     *
     * @return the hash
     */
    long stateHash();
}
