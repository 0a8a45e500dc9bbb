package org.jecosys.anim;

import org.jecosys.math.Require;
import org.jecosys.math.Rng;

/**
 * The per-step inputs of {@link AnimationState#animate(int, int, AnimationStep)}: the mode, the
 * per-plant wind and visibility, the eyes of its views and the random source. A
 * reusable holder: create one at build time for each range of plants that may be animated while
 * another is (for example one per chunk), then refill it before each call with its setters, which
 * return it for chaining and allocate nothing. Arrays are referenced, not copied, and read during
 * the call only.
 *
 * <p>One holder must not be refilled while a call reads it. Fill it on the thread that calls
 * {@code animate}, or publish it to that thread (as the worker pool's start does). A new holder is in
 * CONSTRAINT mode with the eye at the origin and no random source; wind and visibility must be set
 * before use.
 */
public final class AnimationStep {
    AnimationMode mode = AnimationMode.CONSTRAINT;
    float[] windX;
    float[] windZ;
    boolean[] visible;
    double eyeX;
    double eyeY;
    double eyeZ;
    /** Views whose levels of detail count (0: the eye alone, at the reference lens). */
    int views;
    double[] viewX;
    double[] viewY;
    double[] viewZ;
    double[] viewScale2;
    double[] viewFixed2;
    Rng rng;
    double time;
    float[] pushX;
    float[] pushZ;
    /** The box round the range's plant bases, six floats from {@link #boundsAt}, or null. */
    float[] bounds;
    int boundsAt;
    /** Per species, the level every plant of the range takes when they all take one ({@link PlantLevels#uniform}). */
    byte[] speciesLevel;

    /** An empty holder (see the class comment). Build time; allocates. */
    public AnimationStep() {
    }

    /**
     * A new holder with these inputs, the eye at the origin and no random source: for
     * tests and one-off calls. Allocates.
     *
     * @param mode    CONSTRAINT, RANDOM or STATIC
     * @param windX   per plant wind X at its node, m/s
     * @param windZ   per plant wind Z, m/s
     * @param visible per plant, whether it is on a visible node
     * @return the new holder
     */
    public static AnimationStep of(AnimationMode mode, float[] windX, float[] windZ, boolean[] visible) {
        return new AnimationStep().set(mode, windX, windZ, visible);
    }

    /**
     * Sets the mode and the per-plant inputs. No allocation.
     *
     * @param mode    CONSTRAINT, RANDOM or STATIC (see {@link AnimationState#animate(int, int, AnimationStep)})
     * @param windX   per plant wind X at its node, m/s (indexed by plant; read in CONSTRAINT mode only)
     * @param windZ   per plant wind Z, m/s
     * @param visible per plant, whether it is on a visible node
     * @return this holder
     */
    public AnimationStep set(AnimationMode mode, float[] windX, float[] windZ, boolean[] visible) {
        this.mode = Require.nonNull("mode", mode);
        this.windX = windX;
        this.windZ = windZ;
        this.visible = visible;
        return this;
    }

    /**
     * Sets the eye, world metres: every plant's level of detail is recomputed from its distance to
     * it. No allocation.
     *
     * @param x eye X, metres
     * @param y eye Y, metres
     * @param z eye Z, metres
     * @return this holder
     */
    public AnimationStep eye(double x, double y, double z) {
        eyeX = x;
        eyeY = y;
        eyeZ = z;
        views = 0;
        return this;
    }

    /**
     * Sets the views whose levels of detail the animation follows: a plant is updated at the finest
     * level any view asks, each view measuring distance by projected size
     * ({@link org.jecosys.math.ViewLod}). Replaces {@link #eye} (which is one view through the
     * reference lens). The arrays are read, not copied; no allocation.
     *
     * @param count  number of views, at least 1
     * @param x      per view, eye X, metres
     * @param y      per view, eye Y, metres
     * @param z      per view, eye Z, metres
     * @param scale2 per view, the scale on squared distances
     * @param fixed2 per view, the fixed squared equivalent distance of an orthographic view, else &lt; 0
     * @return this
     */
    public AnimationStep views(int count, double[] x, double[] y, double[] z, double[] scale2, double[] fixed2) {
        views = count;
        viewX = x;
        viewY = y;
        viewZ = z;
        viewScale2 = scale2;
        viewFixed2 = fixed2;
        if (count > 0) {
            eyeX = x[0];
            eyeY = y[0];
            eyeZ = z[0];
        }
        return this;
    }

    /**
     * Sets the simulation time at the end of the step, seconds: when pushes flatten plants and how far
     * their flattening has recovered ({@code AnimationState.useTrails}; unused without trails). No
     * allocation.
     *
     * @param time seconds since the simulation started, finite, not decreasing from step to step
     * @return this holder
     */
    public AnimationStep time(double time) {
        this.time = time;
        return this;
    }

    /**
     * Sets the wind of the flows that flatten at each plant (m/s, indexed by plant; see
     * {@code AnimationState.useTrails}): what may flatten a plant of a species with trails. Null for
     * none (nothing is flattened this step; flattened plants keep recovering). No allocation.
     *
     * @param x per plant X, or null
     * @param z per plant Z, or null
     * @return this holder
     */
    public AnimationStep pushes(float[] x, float[] z) {
        pushX = x;
        pushZ = z;
        return this;
    }

    /**
     * Sets the box round the bases of the range's plants (minimum X, Y, Z, then maximum, metres, six
     * floats from {@code box[offset]}), or null for none. Optional: with one view it lets
     * {@link AnimationState#animate} find the levels of detail once per species for a range that lies,
     * for each species, wholly within one level's distances, with the levels the per-plant distances
     * give. The array is read, not copied; the first step with a box allocates a byte per species,
     * later ones nothing.
     *
     * @param box    the boxes, or null
     * @param offset where the range's box starts
     * @return this holder
     * @throws IllegalArgumentException when the box does not fit in the array from the offset
     */
    public AnimationStep bounds(float[] box, int offset) {
        if (box != null && (offset < 0 || offset > box.length - 6)) {
            throw new IllegalArgumentException("bounds: a box is six floats from the offset, got offset " + offset
                    + " in an array of " + box.length);
        }
        bounds = box;
        boundsAt = offset;
        return this;
    }

    /**
     * Sets the random source of the range (RANDOM mode only; may be null otherwise). No allocation.
     *
     * @param rng the range's own generator (not shared with another range running at the same time)
     * @return this holder
     */

    public AnimationStep rng(Rng rng) {
        this.rng = rng;
        return this;
    }
}
